// ANIM-1: the Hermite basis and its derivatives. References: a cubic polynomial written out in the
// test (a Hermite segment with the polynomial's end values and slopes must be that polynomial) and
// central differences of the basis itself.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "physics/animation/hermite.h"
#include "support/expect_helpers.h"

namespace {

using pba::Real;
using pba::Vec3;
namespace an = pba::animation;

/// f(t) = a + b t + c t² + d t³ per component, and its derivatives.
struct Cubic {
  Vec3 a, b, c, d;
  Vec3 at(Real t, int derivative) const {
    switch (derivative) {
      case 0:
        return a + t * b + t * t * c + t * t * t * d;
      case 1:
        return b + 2.0 * t * c + 3.0 * t * t * d;
      default:
        return 2.0 * c + 6.0 * t * d;
    }
  }
};

TEST(ANIM_1_HermiteBasis, SegmentWithACubicsEndValuesAndSlopesIsThatCubic) {
  std::mt19937_64 rng(11);  // seed printed by SCOPED_TRACE below
  std::uniform_real_distribution<Real> coef(-2.0, 2.0);
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE(std::string("seed 11, trial ") + std::to_string(trial));
    const Cubic f{{coef(rng), coef(rng), coef(rng)},
                  {coef(rng), coef(rng), coef(rng)},
                  {coef(rng), coef(rng), coef(rng)},
                  {coef(rng), coef(rng), coef(rng)}};
    const Real t1 = coef(rng), h = 0.1 + std::abs(coef(rng));
    const Vec3 p0 = f.at(t1, 0), p1 = f.at(t1 + h, 0);
    const Vec3 m0 = h * f.at(t1, 1), m1 = h * f.at(t1 + h, 1);  // tangents in d/du
    for (Real u = 0.0; u <= 1.0; u += 0.125) {
      // Tolerance: a few ulps of values of size ~10 (coefficients ≤ 2, |t| ≤ 4).
      EXPECT_VEC3_NEAR(an::hermite(p0, m0, p1, m1, u, 0), f.at(t1 + u * h, 0), 1e-11);
      EXPECT_VEC3_NEAR(an::hermite(p0, m0, p1, m1, u, 1) / h, f.at(t1 + u * h, 1), 1e-10);
      EXPECT_VEC3_NEAR(an::hermite(p0, m0, p1, m1, u, 2) / (h * h), f.at(t1 + u * h, 2), 1e-9);
    }
  }
}

TEST(ANIM_1_HermiteBasis, EndpointsInterpolateValuesAndTangents) {
  const an::HermiteBasis b0 = an::hermiteBasis(0.0, 0), b1 = an::hermiteBasis(1.0, 0);
  EXPECT_DOUBLE_EQ(b0.h00, 1.0);
  EXPECT_DOUBLE_EQ(b0.h10 + b0.h01 + b0.h11, 0.0);
  EXPECT_DOUBLE_EQ(b1.h01, 1.0);
  EXPECT_DOUBLE_EQ(b1.h00 + b1.h10 + b1.h11, 0.0);
  const an::HermiteBasis d0 = an::hermiteBasis(0.0, 1), d1 = an::hermiteBasis(1.0, 1);
  EXPECT_DOUBLE_EQ(d0.h10, 1.0);
  EXPECT_DOUBLE_EQ(d1.h11, 1.0);
  EXPECT_DOUBLE_EQ(d0.h00 + d0.h01 + d0.h11, 0.0);
}

TEST(ANIM_1_HermiteBasis, DerivativesMatchCentralDifferences) {
  const Real e = 1e-5;  // central differences err by O(e²) ≈ 1e-10 · |f'''|; rounding ~1e-16/e
  for (Real u = 0.05; u < 1.0; u += 0.1) {
    for (int d = 1; d <= 2; ++d) {
      const an::HermiteBasis lo = an::hermiteBasis(u - e, d - 1), hi = an::hermiteBasis(u + e, d - 1);
      const an::HermiteBasis x = an::hermiteBasis(u, d);
      // Inside (0, 1) the derivative weights never vanish together (h00' ≠ 0 there; h00'' and h10''
      // have different roots), so matching the differences is not satisfied by all zeros.
      EXPECT_GT(std::abs(x.h00) + std::abs(x.h10) + std::abs(x.h01) + std::abs(x.h11), 0.1) << "u " << u;
      EXPECT_NEAR(x.h00, (hi.h00 - lo.h00) / (2 * e), 1e-8) << "u " << u << " derivative " << d;
      EXPECT_NEAR(x.h10, (hi.h10 - lo.h10) / (2 * e), 1e-8) << "u " << u << " derivative " << d;
      EXPECT_NEAR(x.h01, (hi.h01 - lo.h01) / (2 * e), 1e-8) << "u " << u << " derivative " << d;
      EXPECT_NEAR(x.h11, (hi.h11 - lo.h11) / (2 * e), 1e-8) << "u " << u << " derivative " << d;
    }
  }
}

TEST(ANIM_1_HermiteBasis, ValueWeightsSumToOneSoConstantsStayConstant) {
  for (Real u = 0.0; u <= 1.0; u += 0.05) {
    const an::HermiteBasis b = an::hermiteBasis(u, 0);
    EXPECT_NEAR(b.h00 + b.h01, 1.0, 1e-15) << "u " << u;
    const an::HermiteBasis d = an::hermiteBasis(u, 1);
    EXPECT_NEAR(d.h00 + d.h01, 0.0, 1e-14) << "u " << u;
  }
}

}  // namespace
