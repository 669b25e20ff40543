// Exercise tests of ANIM-5 (squadSegment, rotation.cpp): Shoemake's squad on one segment. Expected values
// come from routes that do not run squad: keys about one fixed axis commute, so every quaternion product
// becomes a sum of angles and squad's result is a rotation about that axis whose angle is a scalar formula
// (worked out below from the definitions of log, exp and slerp); the keys themselves at u = 0 and 1; and
// the defining C¹ property across an interior key, measured by finite differences.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "physics/animation/rotation.h"
#include "support/random_rotation.h"

namespace pba::animation {
namespace {

const Vec3 kAxis = glm::normalize(Vec3(1.0, 2.0, -0.5));
Quat about(Real angle) { return glm::angleAxis(angle, kAxis); }

// |q · expected| = 1 up to the sign, and q unit.
void expectSameRotation(const Quat& q, const Quat& expected, Real tolerance) {
  EXPECT_NEAR(glm::length(q), 1.0, 1e-12);
  EXPECT_LT(rotationAngle(q, expected), tolerance);
}

TEST(ANIM_5_Squad, KeysAboutOneAxisFollowTheScalarSquadOfTheirAngles) {
  // About one axis n, q(θ) = (cos θ/2, sin θ/2 n); log q(θ) = (θ/2) n and exp((φ/2) n) = q(φ); slerp moves
  // the angle linearly. So the control angle is σ_i = θ_i − ((θ_{i+1} − θ_i) + (θ_{i−1} − θ_i))/4 (σ = θ at
  // an end), and squad's angle is A + 2u(1 − u)(B − A) with A = θ1 + u(θ2 − θ1), B = σ1 + u(σ2 − σ1).
  const Real angles[4] = {0.1, 0.5, 1.4, 1.6};
  auto sigma = [&](int i) { return angles[i] - ((angles[i + 1] - angles[i]) + (angles[i - 1] - angles[i])) / 4.0; };
  for (int ends = 0; ends < 4; ++ends) {
    const bool hasPrevious = (ends & 1) != 0, hasNext = (ends & 2) != 0;
    const Real s1 = hasPrevious ? sigma(1) : angles[1];
    const Real s2 = hasNext ? sigma(2) : angles[2];
    for (Real u = 0.0; u <= 1.0 + 1e-12; u += 0.125) {
      SCOPED_TRACE(testing::Message() << "previous " << hasPrevious << " next " << hasNext << " u " << u);
      const Real a = angles[1] + u * (angles[2] - angles[1]);
      const Real b = s1 + u * (s2 - s1);
      const Quat q =
          squadSegment(about(angles[0]), about(angles[1]), about(angles[2]), about(angles[3]), hasPrevious, hasNext, u);
      expectSameRotation(q, about(a + 2.0 * u * (1.0 - u) * (b - a)), 1e-12);
    }
  }
}

TEST(ANIM_5_Squad, UnequalStepsAboutOneAxisBendTheAngleAwayFromTheSlerpLine) {
  // With interior neighbours whose steps differ from the segment's, the controls leave the keys (σ ≠ θ):
  // here they move symmetrically, so the midpoint stays slerp's while the quarter point does not.
  const Quat q = squadSegment(about(0.0), about(0.2), about(1.0), about(1.2), true, true, 0.5);
  const Real s1 = 0.2 - (0.8 - 0.2) / 4.0, s2 = 1.0 - (0.2 - 0.8) / 4.0;  // 0.05 and 1.15
  const Real expected = 0.6 + 0.5 * (0.5 * (s1 + s2) - 0.6);              // 0.6: the slerp midpoint
  EXPECT_NEAR(expected, 0.6, 1e-15);                                      // this symmetric case keeps the midpoint …
  expectSameRotation(q, about(expected), 1e-12);
  const Quat quarter = squadSegment(about(0.0), about(0.2), about(1.0), about(1.2), true, true, 0.25);
  const Real a = 0.2 + 0.25 * 0.8, b = s1 + 0.25 * (s2 - s1);
  expectSameRotation(quarter, about(a + 2.0 * 0.25 * 0.75 * (b - a)), 1e-12);  // … but not the quarter point
  EXPECT_GT(rotationAngle(quarter, about(a)), 1e-3);
}

TEST(ANIM_5_Squad, PassesThroughTheKeysStaysUnitAndTurnsSmoothlyAcrossAKey) {
  std::mt19937_64 rng(55);
  std::vector<Quat> keys{test::randomRotation(rng)};
  std::uniform_real_distribution<Real> angle(0.3, 1.0);
  for (int k = 1; k < 5; ++k) {
    Quat next = glm::normalize(keys.back() * glm::angleAxis(angle(rng), glm::axis(test::randomRotation(rng))));
    if (glm::dot(keys.back(), next) < 0.0) next = -next;
    keys.push_back(next);
  }
  // Segment k runs from key k to key k + 1 (k = 0..3); keys 0 and 4 are the channel's ends.
  auto segment = [&](int k, Real u) {
    const bool hasPrevious = k > 0, hasNext = k + 2 < 5;
    const Quat& q0 = keys[static_cast<size_t>(hasPrevious ? k - 1 : k)];
    const Quat& q3 = keys[static_cast<size_t>(hasNext ? k + 2 : k + 1)];
    return squadSegment(q0, keys[static_cast<size_t>(k)], keys[static_cast<size_t>(k + 1)], q3, hasPrevious, hasNext,
                        u);
  };
  for (int k = 0; k < 4; ++k) {
    SCOPED_TRACE(k);
    expectSameRotation(segment(k, 0.0), keys[static_cast<size_t>(k)], 1e-12);
    expectSameRotation(segment(k, 1.0), keys[static_cast<size_t>(k + 1)], 1e-12);
    for (Real u = 0.0; u <= 1.0; u += 0.1) EXPECT_NEAR(glm::length(segment(k, u)), 1.0, 1e-12);
  }
  // C¹ at the interior keys 1..3 on uniform knots: the rotation from key − e to the key equals the one
  // from the key to key + e up to O(e²) (a kink would leave an O(e) difference).
  const Real e = 1e-4;
  for (int k = 1; k < 4; ++k) {
    SCOPED_TRACE(k);
    const Quat key = keys[static_cast<size_t>(k)];
    const Quat before = glm::conjugate(segment(k - 1, 1.0 - e)) * key;
    const Quat after = glm::conjugate(key) * segment(k, e);
    EXPECT_GT(rotationAngle(Quat(1, 0, 0, 0), after), 1e-6);  // it turns at all
    EXPECT_LT(rotationAngle(before, after), 1e-6);
  }
}

}  // namespace
}  // namespace pba::animation
