// Exercise tests of RAG-1 to RAG-4. Each checks its kernel on fixed inputs against defining properties
// computed here (closed forms: lengths, atan2 angles, barycentric sums), so that a test fails for its own
// exercise only. The particle ragdoll runs all four (RagdollParticleExercises below): those tests are not
// any one exercise's, and in the hand-out they report themselves skipped until the four are solved.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "physics/ragdoll/builders.h"
#include "physics/ragdoll/exercises.h"
#include "physics/ragdoll/particle_ragdoll.h"
#include "physics/ragdoll/ragdoll_test_scenes.h"
#include "support/expect_helpers.h"

namespace pba::ragdoll {
namespace {

Vec3 randomVec(std::mt19937_64& rng, Real scale = 1.0) {
  std::uniform_real_distribution<Real> u(-scale, scale);
  return Vec3(u(rng), u(rng), u(rng));
}

using test_scenes::hingeArm;

// ---------------------------------------------------------------------------------------------- RAG-1

TEST(RAG_1_Stick, RestoresTheRestLengthSharedByInverseMassesAlongTheStick) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<Real> w(0.0, 2.0), len(0.1, 2.0);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE(trial);  // seed 11
    const Vec3 a0 = randomVec(rng), b0 = randomVec(rng);
    const Real wa = trial % 10 == 0 ? 0.0 : w(rng), wb = w(rng) + 0.01, rest = len(rng);
    Vec3 a = a0, b = b0;
    projectStick(a, b, wa, wb, rest);
    EXPECT_NEAR(glm::length(b - a), rest, 1e-12);
    // Momentum: the masses 1/w move in opposite directions by amounts in the ratio of the inverse masses.
    EXPECT_VEC3_NEAR(wb * (a - a0), -wa * (b - b0), 1e-12);
    // Along the stick: no turn.
    EXPECT_NEAR(glm::length(glm::cross(b - b0, b0 - a0)), 0.0, 1e-12);
  }
  // Two pinned ends and coincident ends are left alone (and stay finite).
  Vec3 a(0.0), b(1.0, 0.0, 0.0);
  projectStick(a, b, 0.0, 0.0, 2.0);
  EXPECT_VEC3_NEAR(b, Vec3(1.0, 0.0, 0.0), 0.0);
  Vec3 c(0.5), d(0.5);
  projectStick(c, d, 1.0, 1.0, 1.0);
  EXPECT_TRUE(isFinite(c) && isFinite(d));
}

TEST(RagdollParticleExercises, SticksHoldASwingingHingeChainWithinOnePercent) {
  ParticleSettings s;
  ChainDesc chain;
  chain.joint = JointKind::Hinge;
  ParticleRagdoll r = ParticleRagdoll::build(buildChain(chain), s).value();
  for (int i = 0; i < 300; ++i) r.step(1.0 / 60.0);
  // After the relaxation pass; the joints' pull after it leaves up to 2.5 % (the paper's "soft bones").
  EXPECT_LT(r.stats().maxStickStrainAfterRelaxation, 0.01);
  EXPECT_LT(r.stats().maxStickStrain, 0.05);
  EXPECT_LT(r.stats().maxJointError, 0.01) << "[m]";
}

// ---------------------------------------------------------------------------------------------- RAG-2

// The reference: the angle by atan2, unwrapped around the middle of the range, clamped to the nearer limit.
TEST(RAG_2_HingeLimit, AgreesWithTheClampedAtan2AngleForRangesBelowAndBeyondHalfATurn) {
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<Real> u(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    SCOPED_TRACE(trial);  // seed 22
    HingeFrame f;
    f.origin = randomVec(rng);
    f.axis = glm::normalize(randomVec(rng) + Vec3(0.0, 0.0, 0.1));
    f.zero = glm::normalize(glm::cross(f.axis, randomVec(rng) + Vec3(0.3, 0.0, 0.0)));
    const Real lower = -u(rng) * 3.0, upper = u(rng) * 3.0;  // ranges up to 6 rad (beyond π)
    const Vec3 p = f.origin + randomVec(rng);
    const Vec3 side = glm::cross(f.axis, f.zero);
    const Vec3 q = p - f.origin;
    const Real angle = std::atan2(glm::dot(q, side), glm::dot(q, f.zero));
    const Real mid = 0.5 * (lower + upper);
    const Real a = mid + std::remainder(angle - mid, 2.0 * kPi);
    const LimitCorrection c = hingeLimit(f, p, lower, upper);
    if (a >= lower && a <= upper) {
      EXPECT_EQ(c.side, LimitSide::Inside);
      EXPECT_VEC3_NEAR(c.target, p, 1e-12);
      continue;
    }
    const bool lowerNearer = a < lower;
    EXPECT_EQ(c.side, lowerNearer ? LimitSide::Lower : LimitSide::Upper)
        << "angle " << a << " in [" << lower << ", " << upper << "]";
    const Real limit = lowerNearer ? lower : upper;
    const Vec3 t = c.target - f.origin;
    const Real height = glm::dot(q, f.axis);
    EXPECT_NEAR(glm::dot(t, f.axis), height, 1e-9);
    EXPECT_NEAR(glm::length(t - glm::dot(t, f.axis) * f.axis), glm::length(q - height * f.axis), 1e-9);
    EXPECT_NEAR(std::remainder(std::atan2(glm::dot(t, side), glm::dot(t, f.zero)) - limit, 2.0 * kPi), 0.0, 1e-9);
  }
}

// Limits beyond 180°: the arm may turn up and over to 270° but not below 0°, so under gravity it stays
// horizontal instead of hanging (a wrong side would let it fall to −90°, which lies in the wide range's
// complement seen the other way round).
TEST(RagdollParticleExercises, HingeLimitKeepsAnArmOnTheCorrectSideOfALimitBeyondHalfATurn) {
  ParticleSettings s;
  ParticleRagdoll r = ParticleRagdoll::build(hingeArm(0.0, degToRad(270.0)), s).value();
  for (int i = 0; i < 180; ++i) r.step(1.0 / 60.0);
  EXPECT_NEAR(radToDeg(r.jointAngle(0)), 0.0, 2.0);
}

// ---------------------------------------------------------------------------------------------- RAG-3

TEST(RAG_3_ConeLimit, TurnsPointsOutsideTheConeOntoItsRimInTheirOwnPlane) {
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<Real> u(0.0, kPi - 0.01);
  for (int trial = 0; trial < 2000; ++trial) {
    SCOPED_TRACE(trial);  // seed 33
    const Vec3 apex = randomVec(rng), axis = glm::normalize(randomVec(rng) + Vec3(0.0, 0.1, 0.0));
    const Real half = u(rng);
    const Vec3 p = apex + randomVec(rng);
    const Vec3 d = p - apex;
    const Real angle = std::acos(std::clamp(glm::dot(glm::normalize(d), axis), -1.0, 1.0));
    const LimitCorrection c = coneLimit(apex, axis, p, half);
    if (angle <= half - 1e-12) {
      EXPECT_EQ(c.side, LimitSide::Inside);
      EXPECT_VEC3_NEAR(c.target, p, 1e-12);
      continue;
    }
    if (angle < half + 1e-12) continue;  // on the rim to rounding: either answer is right
    EXPECT_NE(c.side, LimitSide::Inside);
    const Vec3 t = c.target - apex;
    EXPECT_NEAR(glm::length(t), glm::length(d), 1e-9);
    EXPECT_NEAR(std::acos(std::clamp(glm::dot(glm::normalize(t), axis), -1.0, 1.0)), half, 1e-6);
    EXPECT_NEAR(glm::dot(t, glm::normalize(glm::cross(axis, d))), 0.0, 1e-9) << "left the plane of axis and point";
    if (half > 1e-3) {  // the same side of the axis
      EXPECT_GT(glm::dot(t - glm::dot(t, axis) * axis, d - glm::dot(d, axis) * axis), 0.0);
    }
  }
}

TEST(RagdollParticleExercises, ConeLimitHoldsAnArmFallingOntoAFortyFiveDegreeCone) {
  RagdollDesc d = hingeArm(0.0, 0.0);
  d.joints[0].kind = JointKind::Ball;
  d.joints[0].axis = Vec3(1.0, 0.0, 0.0);
  d.joints[0].coneAngle = degToRad(45.0);
  ParticleSettings s;
  ParticleRagdoll r = ParticleRagdoll::build(d, s).value();
  Real worst = 0.0;
  for (int i = 0; i < 300; ++i) {
    r.step(1.0 / 60.0);
    worst = std::max(worst, r.jointAngle(0));
  }
  EXPECT_LT(radToDeg(worst), 47.0);
  EXPECT_GT(radToDeg(worst), 40.0) << "the arm should reach the cone";
}

// ---------------------------------------------------------------------------------------------- RAG-4

TEST(RAG_4_DeepestContact, MovesTheContactPointExactlyByThePushWithMovesProportionalToTheWeights) {
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<Real> u(0.1, 2.0);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE(trial);  // seed 44
    std::array<Vec3, 4> x{randomVec(rng), randomVec(rng), randomVec(rng), randomVec(rng)};
    const std::array<Vec3, 4> x0 = x;
    Weights c{u(rng), -u(rng) * 0.3, u(rng), 0.0};
    c[3] = 1.0 - c[0] - c[1] - c[2];
    const Vec3 n = glm::normalize(randomVec(rng) + Vec3(0.0, 0.1, 0.0));
    const Real depth = u(rng) * 0.1;
    ContactSide a{&x, c, u(rng)}, ground{};
    resolveDeepestContact(a, ground, n, depth);
    Vec3 moved(0.0);
    for (int i = 0; i < 4; ++i) moved += c[i] * (x[i] - x0[i]);
    EXPECT_VEC3_NEAR(moved, depth * n, 1e-12);
    // Each particle moves along n by an amount proportional to its weight (λ c_i d).
    for (int i = 0; i < 4; ++i) EXPECT_VEC3_NEAR(x[i] - x0[i], (glm::dot(x[i] - x0[i], n)) * n, 1e-12);
    EXPECT_NEAR(glm::dot(x[0] - x0[0], n) * c[2], glm::dot(x[2] - x0[2], n) * c[0], 1e-12);
  }
}

TEST(RAG_4_DeepestContact, SplitsThePushBetweenTwoBonesByTheirMasses) {
  std::array<Vec3, 4> xa{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  std::array<Vec3, 4> xb{Vec3(0, -1, 0), Vec3(1, -1, 0), Vec3(0, -2, 0), Vec3(0, -1, 1)};
  const auto a0 = xa, b0 = xb;
  const Weights ca{0.4, 0.3, 0.2, 0.1}, cb{0.1, 0.2, 0.3, 0.4};
  ContactSide a{&xa, ca, 8.0}, b{&xb, cb, 1.0};  // A is 8× heavier: it moves 1/9 of the push
  resolveDeepestContact(a, b, kUp, 0.09);
  Vec3 movedA(0.0), movedB(0.0);
  for (int i = 0; i < 4; ++i) movedA += ca[i] * (xa[i] - a0[i]), movedB += cb[i] * (xb[i] - b0[i]);
  EXPECT_VEC3_NEAR(movedA, Vec3(0.0, 0.01, 0.0), 1e-12);
  EXPECT_VEC3_NEAR(movedB, Vec3(0.0, -0.08, 0.0), 1e-12);
}

TEST(RagdollParticleExercises, DeepestContactKeepsTheEightTimesHeavierBoxOutOfTheGround) {
  ParticleSettings s;
  ParticleRagdoll r = ParticleRagdoll::build(buildMassesTest(), s).value();
  Real worst = 0.0;
  for (int i = 0; i < 300; ++i) {
    r.step(1.0 / 60.0);
    worst = std::max(worst, r.stats().maxPenetration);
  }
  EXPECT_LT(worst, 0.01) << "[m]";
}

}  // namespace
}  // namespace pba::ragdoll
