// Slerp and squad (rotation.h). References: the rotation angle between quaternions (acos of the dot
// product), the keys themselves, and finite differences of the curves.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "physics/animation/rotation.h"
#include "support/expect_helpers.h"
#include "support/random_rotation.h"

namespace {

using pba::Quat;
using pba::Real;
using pba::Vec3;
namespace an = pba::animation;

using pba::test::randomRotation;

void expectSameRotation(const Quat& a, const Quat& b, Real tol) { EXPECT_LT(an::rotationAngle(a, b), tol); }

TEST(Slerp, IsUnitExactAtTheEndsAndTurnsAtConstantAngularSpeed) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    SCOPED_TRACE(std::string("seed 7, trial ") + std::to_string(trial));
    const Quat a = randomRotation(rng), b = randomRotation(rng);
    expectSameRotation(an::slerp(a, b, 0.0), a, 1e-7);
    expectSameRotation(an::slerp(a, b, 1.0), b, 1e-7);
    const Real total = an::rotationAngle(a, b);
    for (Real u = 0.0; u <= 1.0; u += 0.1) {
      const Quat q = an::slerp(a, b, u);
      EXPECT_NEAR(glm::length(q), 1.0, 1e-14);
      // Constant speed: the angle travelled is proportional to u (shorter arc, total ≤ π).
      EXPECT_NEAR(an::rotationAngle(a, q), u * total, 1e-7);
    }
  }
}

TEST(Slerp, TakesTheShorterWayRound) {
  const Quat a(1, 0, 0, 0);
  const Quat b = -glm::angleAxis(0.4, Vec3(0, 1, 0));  // same rotation as +, opposite hemisphere
  EXPECT_NEAR(an::rotationAngle(a, an::slerp(a, b, 0.5)), 0.2, 1e-12);
}

TEST(QuatLogExp, AreInverses) {
  std::mt19937_64 rng(8);
  for (int k = 0; k < 50; ++k) {
    const Quat q = randomRotation(rng);
    expectSameRotation(an::quatExp(an::quatLog(q)), q, 1e-7);
  }
  EXPECT_VEC3_NEAR(an::quatLog(glm::angleAxis(0.6, Vec3(0, 0, 1))), Vec3(0, 0, 0.3), 1e-15);
}

TEST(Squad, PassesThroughTheKeysStaysUnitAndIsC1AtInteriorKeys) {
  std::mt19937_64 rng(9);
  const std::vector<Real> times{0.0, 0.5, 1.3, 2.0, 2.4};
  std::vector<Quat> keys{Quat(1, 0, 0, 0)};
  for (size_t k = 1; k < times.size(); ++k)
    keys.push_back(glm::normalize(keys.back() * glm::angleAxis(0.7, glm::normalize(Vec3(1, 2, 0.5 * k)))));
  static_cast<void>(rng);
  for (size_t k = 0; k < times.size(); ++k)
    expectSameRotation(an::interpolateRotation(times, keys, times[k], an::RotationInterpolation::Squad), keys[k], 1e-7);
  for (Real t = 0.0; t <= 2.4; t += 0.05)
    EXPECT_NEAR(glm::length(an::interpolateRotation(times, keys, t, an::RotationInterpolation::Squad)), 1.0, 1e-12);
  // Angular speed just before and just after an interior key (finite differences over 1e-4 s).
  // Squad is C¹ for uniform knots; on non-uniform knots its speed is only continuous in u, so compare
  // the rates per unit of each interval's own parameter: ω_before·h_before = ω_after·h_after.
  for (size_t k = 1; k + 1 < times.size(); ++k) {
    const Real e = 1e-5;
    auto at = [&](Real t) { return an::interpolateRotation(times, keys, t, an::RotationInterpolation::Squad); };
    const Real before = an::rotationAngle(at(times[k] - 2 * e), at(times[k] - e)) / e * (times[k] - times[k - 1]);
    const Real after = an::rotationAngle(at(times[k] + e), at(times[k] + 2 * e)) / e * (times[k + 1] - times[k]);
    EXPECT_NEAR(before, after, 1e-3 * std::max(before, 1.0)) << "key " << k;
  }
}

TEST(Slerp, ChannelTurnsAtTheChordSpeedAndStepHoldsTheKey) {
  const std::vector<Real> times{0.0, 1.0, 2.0};
  const std::vector<Quat> keys{Quat(1, 0, 0, 0), glm::angleAxis(0.5, Vec3(0, 1, 0)),
                               glm::angleAxis(0.5, Vec3(1, 0, 0))};
  auto speed = [&](an::RotationInterpolation mode, Real t) {
    const Real e = 1e-5;
    return an::rotationAngle(an::interpolateRotation(times, keys, t, mode),
                             an::interpolateRotation(times, keys, t + e, mode)) /
           e;
  };
  // Slerp between keys 0 and 1 (0.5 rad in 1 s) turns at 0.5 rad/s.
  EXPECT_NEAR(speed(an::RotationInterpolation::Slerp, 0.5), 0.5, 1e-6);
  const Quat mid = an::interpolateRotation(times, keys, 1.0, an::RotationInterpolation::Step);
  expectSameRotation(mid, keys[1], 1e-12);
}

}  // namespace
