// Splines that are not exercises (cubic_spline.h) and keyframe channels (channel.h). References:
// polynomials the splines must reproduce, Eigen's dense solve of the spline's moment equations, and
// central differences.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <random>

#include "physics/animation/channel.h"
#include "physics/animation/cubic_spline.h"
#include "support/expect_helpers.h"

namespace {

using pba::Real;
using pba::Vec3;
namespace an = pba::animation;

const std::vector<Real> kSplineTimes{0.0, 0.3, 1.0, 1.2, 2.5, 3.0};

TEST(CubicSpline, ClampedWithExactEndSlopesReproducesACubic) {
  auto f = [](Real t) { return 1.0 - 2.0 * t + 0.5 * t * t + 0.3 * t * t * t; };
  auto df = [](Real t) { return -2.0 + t + 0.9 * t * t; };
  std::vector<Real> v;
  for (Real t : kSplineTimes) v.push_back(f(t));
  const auto m = an::cubicSplineMoments<Real>(kSplineTimes, v, an::CubicEnds::Clamped, df(0.0), df(3.0));
  for (Real t = 0.01; t < 3.0; t += 0.07) {  // inside the knots (outside, the ends hold)
    EXPECT_NEAR(an::cubicSplineEvaluate<Real>(kSplineTimes, v, m, t, 0), f(t), 1e-12) << "t " << t;
    EXPECT_NEAR(an::cubicSplineEvaluate<Real>(kSplineTimes, v, m, t, 1), df(t), 1e-11) << "t " << t;
  }
}

TEST(CubicSpline, NaturalMomentsSolveTheTridiagonalSystemAsEigenDoes) {
  std::vector<Real> v{0.0, 1.0, -1.0, 2.0, 0.5, 0.0};
  const auto m = an::cubicSplineMoments<Real>(kSplineTimes, v, an::CubicEnds::Natural, 0.0, 0.0);
  const int n = static_cast<int>(kSplineTimes.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  a(0, 0) = a(n - 1, n - 1) = 1.0;
  for (int i = 1; i + 1 < n; ++i) {
    const Real h0 = kSplineTimes[i] - kSplineTimes[i - 1], h1 = kSplineTimes[i + 1] - kSplineTimes[i];
    a(i, i - 1) = h0;
    a(i, i) = 2 * (h0 + h1);
    a(i, i + 1) = h1;
    b(i) = 6 * ((v[i + 1] - v[i]) / h1 - (v[i] - v[i - 1]) / h0);
  }
  const Eigen::VectorXd x = a.partialPivLu().solve(b);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(m[static_cast<size_t>(i)], x(i), 1e-12) << "knot " << i;
}

TEST(CubicSpline, NaturalSplineIsC2WithZeroEndCurvature) {
  std::vector<Vec3> v;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (size_t k = 0; k < kSplineTimes.size(); ++k) v.emplace_back(u(rng), u(rng), u(rng));
  const auto m = an::cubicSplineMoments<Vec3>(kSplineTimes, v, an::CubicEnds::Natural, Vec3(0.0), Vec3(0.0));
  EXPECT_VEC3_NEAR(an::cubicSplineEvaluate<Vec3>(kSplineTimes, v, m, 1e-12, 2), Vec3(0.0), 1e-9);
  for (size_t k = 1; k + 1 < kSplineTimes.size(); ++k) {
    const Real e = 1e-9;
    for (int d = 0; d <= 2; ++d)
      EXPECT_VEC3_NEAR(an::cubicSplineEvaluate<Vec3>(kSplineTimes, v, m, kSplineTimes[k] - e, d),
                       an::cubicSplineEvaluate<Vec3>(kSplineTimes, v, m, kSplineTimes[k] + e, d), 1e-6);
    EXPECT_VEC3_NEAR(an::cubicSplineEvaluate<Vec3>(kSplineTimes, v, m, kSplineTimes[k], 0), v[k], 1e-12);
  }
}

TEST(CubicSpline, DerivativesMatchCentralDifferences) {
  std::vector<Real> v{0.0, 1.0, -1.0, 2.0, 0.5, 0.0};
  const auto m = an::cubicSplineMoments<Real>(kSplineTimes, v, an::CubicEnds::Natural, 0.0, 0.0);
  const Real e = 1e-6;
  for (Real t = 0.05; t < 2.95; t += 0.1) {
    const Real c = (an::cubicSplineEvaluate<Real>(kSplineTimes, v, m, t + e, 0) -
                    an::cubicSplineEvaluate<Real>(kSplineTimes, v, m, t - e, 0)) /
                   (2 * e);
    EXPECT_NEAR(an::cubicSplineEvaluate<Real>(kSplineTimes, v, m, t, 1), c, 1e-7) << "t " << t;
    const Real c2 = (an::cubicSplineEvaluate<Real>(kSplineTimes, v, m, t + e, 1) -
                     an::cubicSplineEvaluate<Real>(kSplineTimes, v, m, t - e, 1)) /
                    (2 * e);
    EXPECT_NEAR(an::cubicSplineEvaluate<Real>(kSplineTimes, v, m, t, 2), c2, 1e-6) << "t " << t;
  }
}

TEST(LinearAndStep, InterpolateKnotsAndHoldTheEnds) {
  const std::vector<Real> t{1.0, 2.0, 4.0};
  const std::vector<Real> v{0.0, 2.0, 3.0};
  EXPECT_DOUBLE_EQ(an::linearInterpolate<Real>(t, v, 1.5), 1.0);
  EXPECT_DOUBLE_EQ(an::linearInterpolate<Real>(t, v, 3.0, 1), 0.5);
  EXPECT_DOUBLE_EQ(an::linearInterpolate<Real>(t, v, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(an::linearInterpolate<Real>(t, v, 9.0), 3.0);
  EXPECT_DOUBLE_EQ(an::stepInterpolate<Real>(t, v, 3.9), 2.0);
  EXPECT_DOUBLE_EQ(an::stepInterpolate<Real>({}, v, 3.9, 7.0), 7.0);
}

TEST(Channel, InsertDeleteAndMoveKeepKeysSortedAndRefuseEqualTimes) {
  an::Channel<Real> c(an::Interpolation::Linear);
  ASSERT_TRUE(c.insert(2.0, 20.0).ok());
  ASSERT_TRUE(c.insert(0.0, 0.0).ok());
  ASSERT_EQ(c.insert(1.0, 10.0).value(), 1);
  const pba::Result<int> dup = c.insert(1.0, 5.0);
  ASSERT_FALSE(dup.ok());
  EXPECT_NE(dup.error().find("key time"), std::string::npos) << dup.error();
  EXPECT_NE(dup.error().find("already"), std::string::npos) << dup.error();
  EXPECT_DOUBLE_EQ(c.valueAt(1.5), 15.0);
  ASSERT_EQ(c.move(1, 3.0).value(), 2);  // 10 at t = 3 now
  EXPECT_DOUBLE_EQ(c.time(2), 3.0);
  EXPECT_FALSE(c.move(2, 0.0).ok());  // taken: the channel is unchanged
  EXPECT_EQ(c.size(), 3);
  EXPECT_DOUBLE_EQ(c.time(2), 3.0);
  c.remove(0);
  EXPECT_EQ(c.size(), 2);
  EXPECT_DOUBLE_EQ(c.valueAt(-5.0), 20.0);
}

TEST(Channel, NaturalCubicModeGivesVelocityAndAccelerationAtAnyTime) {
  an::Channel<Vec3> c(an::Interpolation::NaturalCubic, Vec3(0.0));
  for (size_t k = 0; k < kSplineTimes.size(); ++k)
    ASSERT_TRUE(c.insert(kSplineTimes[k], Vec3(std::sin(kSplineTimes[k]), kSplineTimes[k], 1.0)).ok());
  const Real e = 1e-6;
  for (Real t = 0.1; t < 2.9; t += 0.3) {
    EXPECT_VEC3_NEAR(c.velocityAt(t), (c.valueAt(t + e) - c.valueAt(t - e)) / (2 * e), 1e-6);
    EXPECT_VEC3_NEAR(c.accelerationAt(t), (c.velocityAt(t + e) - c.velocityAt(t - e)) / (2 * e), 1e-5);
  }
  EXPECT_VEC3_NEAR(c.velocityAt(2.0).y * Vec3(1.0), Vec3(1.0), 1e-12);  // y is linear in t
}

}  // namespace
