// The particle ragdoll's own parts: the particulating (tetrahedron mass, centre and inertia equal the
// box's, against the closed form of a solid box), barycentric embedding and frame fitting, hinge limits
// beyond 180° on the correct side (through RAG-2), the statistics against sums over the
// particles, determinism, and bad descriptions.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "physics/ragdoll/builders.h"
#include "physics/ragdoll/constraint_ragdoll.h"
#include "physics/ragdoll/particle_ragdoll.h"
#include "physics/ragdoll/ragdoll_test_scenes.h"
#include "support/expect_helpers.h"

namespace pba::ragdoll {
namespace {

TEST(RagdollTetrahedron, HasTheMassCentreAndInertiaOfItsBoxForSeveralBoxesAndRotations) {
  std::mt19937_64 rng(5);
  std::normal_distribution<Real> n(0.0, 1.0);
  for (const Vec3& h : {Vec3(0.5), Vec3(0.1, 0.7, 0.3), Vec3(0.044, 0.183, 0.044), Vec3(2.0, 0.05, 1.0)}) {
    const Real mass = 3.7;  // [kg]
    const std::array<Vec3, 4> rest = tetrahedronOffsets(h);
    const Quat q = glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng)));
    std::array<Vec3, 4> x{};
    for (int i = 0; i < 4; ++i) x[i] = Vec3(1.0, 2.0, 3.0) + q * rest[i];
    const Weights m{mass / 4, mass / 4, mass / 4, mass / 4};
    // Closed form of the solid box (full sides a, b, c): I = m/12 diag(b² + c², a² + c², a² + b²), in world axes R I Rᵀ.
    const Vec3 s = 2.0 * h;
    const Mat3 box(mass / 12.0 * (s.y * s.y + s.z * s.z), 0, 0, 0, mass / 12.0 * (s.x * s.x + s.z * s.z), 0, 0, 0,
                   mass / 12.0 * (s.x * s.x + s.y * s.y));
    const Mat3 r = glm::mat3_cast(q);
    const Mat3 expected = r * box * glm::transpose(r);
    const Mat3 actual = pointMassInertia(x, m);
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(actual[c][k], expected[c][k], 1e-12 * mass) << "entry " << k << "," << c;
    EXPECT_VEC3_NEAR(0.25 * (x[0] + x[1] + x[2] + x[3]), Vec3(1.0, 2.0, 3.0), 1e-12);
  }
}

TEST(RagdollTetrahedron, EmbedsPointsWithBarycentricWeights) {
  std::mt19937_64 rng(6);
  std::normal_distribution<Real> n(0.0, 1.0);
  const Vec3 h(0.2, 0.4, 0.1);
  const std::array<Vec3, 4> rest = tetrahedronOffsets(h);
  for (int trial = 0; trial < 50; ++trial) {
    SCOPED_TRACE(trial);
    const Quat q = glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng)));
    const Vec3 t(n(rng), n(rng), n(rng));
    std::array<Vec3, 4> x{};
    for (int i = 0; i < 4; ++i) x[i] = t + q * rest[i];
    const Vec3 p = t + q * Vec3(h.x, -h.y, h.z);  // a corner, outside the tetrahedron
    const Weights c = barycentric(x, p);
    EXPECT_NEAR(c[0] + c[1] + c[2] + c[3], 1.0, 1e-12);
    EXPECT_VEC3_NEAR(embedded(x, c), p, 1e-12);
  }
}

using test_scenes::hingeArm;

// An arm released horizontally on a hinge about z: gravity turns it to −90°. Allowed [0°, 270°]: it
// may only go up and over, so it rests on its lower limit at 0°. Allowed [−270°, 0°]: it hangs at −90°.
TEST(RagdollTetrahedron, AFlippedTetrahedronIsTurnedBackToItsLeastVolumeKeepingItsCentroid) {
  // A thin bone's tetrahedron (kernels.h, keepMinimumVolume) mirrored through its x = 0 plane: the same
  // edges, the opposite signed volume. Repeated projections (the solver's passes) bring the signed volume
  // back to at least half the rest value; equal weights keep the centroid (Σ gradients = 0). Tolerances:
  // the projection is first order, so each pass removes most of the remaining violation; 1e-9 relative
  // is far below what 20 passes leave, and the centroid moves only by rounding.
  const std::array<Vec3, 4> rest = tetrahedronOffsets(Vec3(0.25, 0.025, 0.025));
  const Real rest6 = sixVolume(rest);
  ASSERT_LT(rest6, 0.0);
  std::array<Vec3, 4> x = rest;
  for (Vec3& p : x) p.x = -p.x;  // mirrored
  EXPECT_NEAR(sixVolume(x), -rest6, 1e-15);
  const Vec3 centroidBefore = centroid(x);
  const std::array<Real, 4> w{1.0, 1.0, 1.0, 1.0};
  for (int pass = 0; pass < 20; ++pass) keepMinimumVolume(x, w, rest6, 0.5);
  EXPECT_GE(-sixVolume(x), 0.5 * std::abs(rest6) * (1.0 - 1e-9));
  EXPECT_VEC3_NEAR(centroid(x), centroidBefore, 1e-12);
  // Within its least volume nothing moves, bit for bit; fixed particles never move.
  std::array<Vec3, 4> same = rest;
  EXPECT_FALSE(keepMinimumVolume(same, w, rest6, 0.5));
  for (int k = 0; k < 4; ++k) EXPECT_EQ(same[k], rest[k]);
  std::array<Vec3, 4> pinned = x;
  for (Vec3& p : pinned) p.x = -p.x;
  const std::array<Vec3, 4> before = pinned;
  EXPECT_FALSE(keepMinimumVolume(pinned, {0.0, 0.0, 0.0, 0.0}, rest6, 0.5));
  for (int k = 0; k < 4; ++k) EXPECT_EQ(pinned[k], before[k]);
}

TEST(RagdollParticleHinge, LimitsBeyondHalfATurnHoldOnTheCorrectSide) {
  ParticleRagdoll up = ParticleRagdoll::build(hingeArm(0.0, degToRad(270.0))).value();
  ParticleRagdoll down = ParticleRagdoll::build(hingeArm(degToRad(-270.0), 0.0)).value();
  ParticleSettings damped;
  damped.damping = 2.0;  // [1/s] so that the hanging arm settles
  down.settings() = damped;
  for (int i = 0; i < 600; ++i) up.step(1.0 / 60.0), down.step(1.0 / 60.0);
  EXPECT_NEAR(radToDeg(up.jointAngle(0)), 0.0, 2.0);
  EXPECT_NEAR(radToDeg(down.jointAngle(0)), -90.0, 2.0);
}

// stats() measures when asked: the state after the last step, with that step's length (here 0.01 s, not
// the 1/60 s before the first step). Expected values summed here from the particles: kinetic energy
// Σ ½ m |(x − x_old)/h|², potential energy −Σ m g·x over free particles, and the deepest box corner below
// the ground, the corners embedded by their barycentric weights in the tetrahedron.
TEST(RagdollParticleStats, DescribeTheStateAfterTheLastStepWithItsStepLength) {
  const RagdollDesc d = buildBoxesTest();
  ParticleRagdoll r = ParticleRagdoll::build(d).value();
  EXPECT_EQ(r.stats().kineticEnergy, 0.0);  // not started: the initial velocities need the step
  const Real h = 0.01;
  for (int step = 1; step <= 120; ++step) {
    r.step(h);
    if (step % 40 != 0) continue;
    SCOPED_TRACE(step);
    Real kinetic = 0.0, potential = 0.0, penetration = 0.0;
    for (int b = 0; b < r.boneCount(); ++b) {
      const Real m = 0.25 * r.boneMass(b);
      std::array<Vec3, 4> x{};
      for (int k = 0; k < 4; ++k) {
        const int i = 4 * b + k;
        x[k] = r.positions()[i];
        const Vec3 v = (r.positions()[i] - r.previousPositions()[i]) / h;
        kinetic += 0.5 * m * glm::dot(v, v);
        potential += m * kStandardGravity * x[k].y;
      }
      const Vec3 e = r.halfExtents(b);
      const std::array<Vec3, 4> rest = tetrahedronOffsets(e);
      for (int c = 0; c < 8; ++c) {
        const Vec3 corner(c & 1 ? e.x : -e.x, c & 2 ? e.y : -e.y, c & 4 ? e.z : -e.z);
        penetration = std::max(penetration, -embedded(x, barycentric(rest, corner)).y);
      }
    }
    const ParticleStats s = r.stats();
    EXPECT_NEAR(s.kineticEnergy, kinetic, 1e-12 * kinetic);
    EXPECT_NEAR(s.potentialEnergy, potential, 1e-12 * std::abs(potential));
    EXPECT_NEAR(s.maxPenetration, penetration, 1e-12);
    EXPECT_EQ(r.stats().kineticEnergy, s.kineticEnergy);  // asking again measures the same state
  }
}

TEST(RagdollConstraint, AnEightTimesHeavierBoxRestsOnTheFloorWithoutSinking) {
  RagdollDesc d;
  BoneDesc big;
  big.center = Vec3(0.0, 0.4, 0.0), big.halfExtents = Vec3(0.4), big.mass = 80.0;
  BoneDesc small;
  small.center = Vec3(0.0, 1.0, 0.0), small.halfExtents = Vec3(0.2), small.mass = 10.0;
  d.bones = {big, small};
  ConstraintRagdoll r = ConstraintRagdoll::build(d).value();
  for (int i = 0; i < 600; ++i) r.step(1.0 / 60.0);
  EXPECT_LT(r.stats().maxPenetration, 0.005) << "[m]";
  EXPECT_NEAR(r.world().body(r.bodyOf(0)).position.y, 0.4, 0.01);
}

TEST(RagdollDeterminism, TheSameDescriptionGivesBitIdenticalStates) {
  const RagdollDesc d = buildSpider();
  ParticleRagdoll a = ParticleRagdoll::build(d).value(), b = ParticleRagdoll::build(d).value();
  ConstraintRagdoll c = ConstraintRagdoll::build(d).value(), e = ConstraintRagdoll::build(d).value();
  for (int i = 0; i < 300; ++i) a.step(1.0 / 60.0), b.step(1.0 / 60.0), c.step(1.0 / 60.0), e.step(1.0 / 60.0);
  for (int i = 0; i < a.particleCount(); ++i) EXPECT_EQ(a.positions()[i], b.positions()[i]);
  for (int i = 0; i < c.boneCount(); ++i)
    EXPECT_EQ(c.world().body(c.bodyOf(i)).position, e.world().body(e.bodyOf(i)).position);
}

TEST(RagdollDescription, BadInputsGiveErrorsNamingTheField) {
  RagdollDesc d = buildChainTest(JointKind::Hinge);
  d.bones[1].mass = -1.0;
  EXPECT_NE(validate(d).error().find("mass"), std::string::npos) << validate(d).error();
  d = buildChainTest(JointKind::Hinge);
  d.joints[0].boneB = 99;
  EXPECT_NE(validate(d).error().find("boneB"), std::string::npos);
  d = buildLimitsTest(JointKind::Hinge);
  d.joints[1].lower = 0.5;
  EXPECT_NE(ParticleRagdoll::build(d).error().find("lower"), std::string::npos);
  EXPECT_NE(ConstraintRagdoll::build(d).error().find("lower"), std::string::npos);
  d = buildSpider();
  d.bones[0].halfExtents.x = 0.0;
  EXPECT_FALSE(validate(d).ok());
  EXPECT_FALSE(validate(RagdollDesc{}).ok());
}

TEST(RagdollHumanBuilder, HasSixteenBonesFifteenJointsAndMassInProportionToVolume) {
  const RagdollDesc h = buildHumanRagdoll();
  ASSERT_EQ(h.bones.size(), 16u);
  EXPECT_EQ(h.joints.size(), 15u);
  EXPECT_NEAR(totalMass(h), 75.0, 1e-9);
  const auto volume = [](const BoneDesc& b) { return 8.0 * b.halfExtents.x * b.halfExtents.y * b.halfExtents.z; };
  for (const BoneDesc& b : h.bones)
    EXPECT_NEAR(b.mass / volume(b), h.bones[2].mass / volume(h.bones[2]), 1e-9) << b.name;
  // The table's chest, 40.9 × 39.2 × 25.0 cm (H × W × D).
  EXPECT_VEC3_NEAR(2.0 * h.bones[2].halfExtents, Vec3(0.392, 0.409, 0.25), 1e-12);
  Real lowest = 1e30, highest = -1e30;
  for (const BoneDesc& b : h.bones)
    lowest = std::min(lowest, b.center.y - b.halfExtents.y), highest = std::max(highest, b.center.y + b.halfExtents.y);
  EXPECT_NEAR(lowest, 0.0, 1e-12);
  EXPECT_NEAR(highest, 1.833, 1e-9);  // the table's heights stacked: 13.9 + 30.5 + 51.2 + 14.5 + 40.9 + 12.3 + 20.0 cm
}

}  // namespace
}  // namespace pba::ragdoll
