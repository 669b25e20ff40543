// Suites Cloth… (not CLOTH-5's own: the implicit step runs CLOTH-5 and the spring force, PART-4; in the
// hand-out they are skipped until both are solved). CLOTH-5's implicit Euler with contacts and step
// control (implicit.h, solver.h): a particle inside a collider is moved onto its surface inside the solve
// without being set moving (the position alteration of Baraff & Witkin §6), one that would pass the
// surface within the step lands on it (speculative contact), and a pin dragged far in one frame does not
// overstretch stiff cloth when the step control halves the step. Frictionless colliders only, so that
// CLOTH-4 (the friction) does not run. Reference values: closed forms (surface heights, free fall, the
// closing speed, one spring's backward Euler pull).
#include <gtest/gtest.h>

#include "cloth_test_support.h"
#include "physics/cloth/implicit.h"
#include "support/expect_helpers.h"

namespace pba::cloth {
namespace {

using testing::meshGrid;

constexpr Real kH = 1.0 / 60.0;

/// Two particles of mass m on one spring along x, stretched from its rest length L to l, at height y,
/// both moving at vy, over a frictionless floor (y = 0). No spring damping, so that backward Euler has a
/// closed form along the spring: v = ± h k (l − L) / (m + 2 h² k) towards each other.
struct PairOverFloor {
  Cloth cloth;
  std::vector<Collider> colliders;
  Real margin = 0.0, inwardSpeed = 0.0;
};
PairOverFloor pairOverFloor(Real y, Real vy) {
  constexpr Real m = 0.01, k = 500.0, L = 0.1, l = 0.12;
  PairOverFloor s;
  s.cloth.material.stretchStiffness = k;
  s.cloth.material.springDamping = 0.0;
  s.cloth.material.thickness = 0.01;
  for (const Real x : {-0.5 * l, 0.5 * l}) {
    s.cloth.position.emplace_back(x, y, 0.0);
    s.cloth.restPosition.emplace_back(x * L / l, y, 0.0);
    s.cloth.velocity.emplace_back(0.0, vy, 0.0);
    s.cloth.mass.push_back(m);
    s.cloth.inverseMass.push_back(1.0 / m);
  }
  s.cloth.springs.push_back(Link{0, 1, L, LinkKind::Stretch});
  Collider floor;
  floor.friction = 0.0;
  s.colliders = {floor};
  s.margin = 0.5 * s.cloth.material.thickness;
  s.inwardSpeed = kH * k * (l - L) / (m + 2.0 * kH * kH * k);
  return s;
}

ImplicitSettings exactSolve() {
  ImplicitSettings settings;
  settings.cg.tolerance = 1e-12;
  return settings;
}

/// The spring's pull, solved with the contact: particle 0 moves +x, particle 1 −x, at the closed form.
void expectThePullAlongTheSpring(const PairOverFloor& s) {
  EXPECT_NEAR(s.cloth.velocity[0].x, s.inwardSpeed, 1e-9);
  EXPECT_NEAR(s.cloth.velocity[1].x, -s.inwardSpeed, 1e-9);
}

TEST(ClothImplicitContacts, AParticleInsideAColliderEndsTheStepOnItsSurfaceWithoutBeingSetMoving) {
  const Real depth = 0.004;
  PairOverFloor s = pairOverFloor(0.005 - depth, 0.0);  // margin 5 mm: 4 mm inside, at rest
  ImplicitWorkspace w;
  const ImplicitStats stats = implicitStep(s.cloth, ClothEnvironment{}, s.colliders, exactSolve(), kH, 0.0, w);
  EXPECT_EQ(stats.contactConstraints, 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(s.cloth.position[i].y, s.margin, 1e-12) << "particle " << i;
    // Moved out by the depth, not launched at depth / h = 0.24 m/s: resting contact stays resting.
    EXPECT_NEAR(s.cloth.velocity[i].y, 0.0, 1e-12) << "particle " << i;
  }
  expectThePullAlongTheSpring(s);
}

TEST(ClothImplicitContacts, AParticleThatWouldPassTheSurfaceWithinTheStepLandsOnIt) {
  const Real gap = 0.002, speed = 1.0;  // h · speed = 16.7 mm > gap
  PairOverFloor s = pairOverFloor(0.005 + gap, -speed);
  ImplicitWorkspace w;
  const ImplicitStats stats = implicitStep(s.cloth, ClothEnvironment{}, s.colliders, exactSolve(), kH, 0.0, w);
  EXPECT_EQ(stats.contactConstraints, 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(s.cloth.position[i].y, s.margin, 1e-12) << "particle " << i;
    EXPECT_NEAR(s.cloth.velocity[i].y, -gap / kH, 1e-9) << "particle " << i;  // it closed the gap, no more
  }
  expectThePullAlongTheSpring(s);
}

TEST(ClothImplicitContacts, AColliderFartherThanOneStepLeavesTheFreeFallAlone) {
  PairOverFloor s = pairOverFloor(0.5, -1.0);  // 0.5 m up at 1 m/s: out of reach of one step
  ImplicitWorkspace w;
  const ImplicitStats stats = implicitStep(s.cloth, ClothEnvironment{}, s.colliders, exactSolve(), kH, 0.0, w);
  EXPECT_EQ(stats.contactConstraints, 0u);
  for (std::size_t i = 0; i < 2; ++i) {  // backward Euler of gravity: v₁ = v₀ − g h
    EXPECT_NEAR(s.cloth.velocity[i].y, -1.0 - kStandardGravity * kH, 1e-9) << "particle " << i;
  }
  expectThePullAlongTheSpring(s);
}

/// A stiff cloth hanging from two corners; one second in, one corner's pin is moved 10 cm sideways and
/// 10 cm up within one frame (a fast mouse drag). Largest edge strain over the next three seconds.
struct DragResult {
  Real worstStrain = 0.0, finalStrain = 0.0;
  int retries = 0;
};
DragResult dragAPin(Real maxStrainGrowth) {
  ClothMaterial m;
  m.stretchStiffness = m.shearStiffness = 1e5;
  m.bendStiffness = 1e4;
  m.springDamping = 0.1;
  Cloth c = meshGrid(16, 1.0, 1.5, GridPins::TopCorners, m);
  ClothSolverSettings s;
  s.kind = ClothSolverKind::Implicit;
  s.substeps = 1;
  s.implicit.maxStrainGrowth = maxStrainGrowth;
  ClothSolver solver;
  DragResult r;
  for (int f = 0; f < 240; ++f) {
    if (f == 60) c.pins[0].target += Vec3(0.1, 0.1, 0.0);
    r.retries += solver.step(c, ClothEnvironment{}, {}, s, kH, f * kH).implicitRetries;
    EXPECT_FALSE(describeNonFinite(c).has_value()) << "frame " << f;
    if (f >= 60) r.worstStrain = std::max(r.worstStrain, edgeStrain(c).max);
  }
  r.finalStrain = edgeStrain(c).max;
  return r;
}

TEST(ClothImplicitStepControl, APinDraggedFarInOneFrameDoesNotOverstretchStiffCloth) {
  const DragResult controlled = dragAPin(0.1);
  EXPECT_GT(controlled.retries, 0);  // the drag's frame was split
  // No step grows a strain by more than the threshold, from a taut cloth (the bare method: 4.9).
  EXPECT_LT(controlled.worstStrain, 0.1);
  EXPECT_LT(controlled.finalStrain, 0.002);  // and the cloth hangs taut again (k = 10⁵ N/m)
}

TEST(ClothImplicitStepControl, OffTakesEveryStepAsAskedAndCalmStepsAreNeverSplit) {
  const DragResult bare = dragAPin(0.0);
  EXPECT_EQ(bare.retries, 0);
  // A cloth hanging at rest never trips the control.
  ClothMaterial m;
  m.stretchStiffness = m.shearStiffness = 1e5;
  Cloth c = meshGrid(16, 1.0, 1.5, GridPins::TopCorners, m);
  ClothSolverSettings s;
  s.kind = ClothSolverKind::Implicit;
  s.substeps = 1;
  ClothSolver solver;
  int retries = 0;
  const Real startY = c.position.back().y;
  for (int f = 0; f < 120; ++f) retries += solver.step(c, ClothEnvironment{}, {}, s, kH, f * kH).implicitRetries;
  EXPECT_EQ(retries, 0);
  EXPECT_LT(c.position.back().y, startY - 0.1);  // the free corner swung down
  EXPECT_LT(edgeStrain(c).max, 0.002);
}

}  // namespace
}  // namespace pba::cloth
