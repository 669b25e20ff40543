// The explicit (symplectic Euler) mass-spring cloth, and what every solver shares: pins, energy, tearing,
// self-collision, determinism. No exercise code: Mesh layout, no colliders, no wind.
#include <cmath>

#include <gtest/gtest.h>

#include "cloth_test_support.h"
#include "physics/cloth/self_collision.h"
#include "physics/cloth/tearing.h"
#include "support/expect_helpers.h"

namespace pba::cloth {
namespace {

using testing::chainExtension;
using testing::hangingChain;
using testing::meshGrid;
using testing::run;
using testing::StackedSheets;
using testing::stackedSheets;

ClothSolverSettings explicitSettings(int substeps) {
  ClothSolverSettings s;
  s.kind = ClothSolverKind::Explicit;
  s.substeps = substeps;
  return s;
}

TEST(ExplicitCloth, HangingSpringChainSettlesToTheClosedFormStaticSag) {
  // At rest, link s (counted from the bottom, s = 1…N−1) carries the weight of the s particles below it:
  // its extension is s m g / k.
  ClothMaterial m;
  m.stretchStiffness = 500.0;
  m.springDamping = 0.5;
  const int n = 8;
  const Real mass = 0.02, L = 0.1;
  Cloth c = hangingChain(n, mass, L, 2.0, m);
  ClothEnvironment env;
  env.massDamping = 2.0;  // settles within the run
  ClothSolver solver;
  run(c, solver, env, {}, explicitSettings(20), 1.0 / 60.0, 600);
  const Real g = -env.gravity.y;
  for (int s = 1; s < n; ++s) {
    // Tolerance: the residual motion after 10 s of damping is far below 1e-7 m.
    EXPECT_NEAR(chainExtension(c, n - 1 - s), s * mass * g / m.stretchStiffness, 1e-7)
        << "link " << s << " from the bottom";
  }
}

TEST(ExplicitCloth, PinnedParticlesStayExactlyWhereTheyAre) {
  Cloth c = meshGrid(10, 1.0, 1.5, GridPins::TopCorners);
  const Vec3 a = c.position[c.pins[0].particle], b = c.position[c.pins[1].particle];
  ClothSolver solver;
  run(c, solver, ClothEnvironment{}, {}, explicitSettings(40), 1.0 / 60.0, 120);
  EXPECT_EQ(c.position[c.pins[0].particle], a);
  EXPECT_EQ(c.position[c.pins[1].particle], b);
  EXPECT_EQ(c.velocity[c.pins[0].particle], Vec3(0.0));
}

TEST(ExplicitCloth, MovingPinsFollowTheirTargetsExactly) {
  Cloth c = meshGrid(6, 1.0, 1.5, GridPins::TopCorners);
  ClothSolver solver;
  Real t = 0.0;
  for (int frame = 1; frame <= 60; ++frame) {
    const Vec3 target = c.restPosition[0] + Vec3(0.005 * frame, 0.0, 0.0);  // a rail opening at 0.3 m/s
    pin(c, 0, target);
    solver.step(c, ClothEnvironment{}, {}, explicitSettings(40), 1.0 / 60.0, t);
    t += 1.0 / 60.0;
    EXPECT_EQ(c.position[0], target);
  }
}

TEST(ExplicitCloth, EnergyNeverGrowsInAPassiveHangingCloth) {
  ClothMaterial m;
  m.springDamping = 0.05;
  Cloth c = meshGrid(12, 1.0, 1.5, GridPins::TopCorners, m);
  ClothEnvironment env;
  ClothSolver solver;
  const ClothSolverSettings s = explicitSettings(60);
  const Real e0 = clothEnergy(c, env, s.kind);
  Real t = 0.0;
  for (int f = 0; f < 180; ++f) {
    solver.step(c, env, {}, s, 1.0 / 60.0, t);
    t += 1.0 / 60.0;
    ASSERT_LE(clothEnergy(c, env, s.kind), e0 + 0.01 * std::abs(e0)) << "frame " << f;
  }
  EXPECT_LT(clothEnergy(c, env, s.kind), e0);  // it fell and lost energy to damping
}

TEST(ExplicitCloth, BlowsUpAtTheFrameStepWithStiffSprings) {
  // The contrast of the workbook: k = 10⁵ N/m at h = 1/60 s is far beyond 2/ω_max.
  ClothMaterial m;
  m.stretchStiffness = m.shearStiffness = m.bendStiffness = 1e5;
  Cloth c = meshGrid(8, 1.0, 1.5, GridPins::TopCorners, m);
  ASSERT_LT(explicitStabilityLimit(c), 1e-3);
  ClothSolver solver;
  ClothEnvironment env;
  pba::testing::FloatingPointTrapsOff traps;  // it overflows on purpose
  const Real e0 = clothEnergy(c, env, ClothSolverKind::Explicit);
  run(c, solver, env, {}, explicitSettings(1), 1.0 / 60.0, 30);
  const Real e = clothEnergy(c, env, ClothSolverKind::Explicit);
  EXPECT_TRUE(!std::isfinite(e) || e > 100.0 * std::abs(e0));
}

/// The fastest particle's speed [m/s] (NaN when a velocity is not finite).
Real fastestSpeed(const Cloth& c) {
  Real fastest = 0.0;
  for (const Vec3& v : c.velocity) {
    const Real speed = glm::length(v);
    if (!(speed <= fastest)) fastest = speed;
  }
  return fastest;
}

TEST(ExplicitCloth, ADivergingStepStopsAtTheFirstSubstepPastTheSpeedLimit) {
  // The stiff cloth above, 4 substeps per step of 3× its stability bound: it diverges over a few steps.
  // Reference: the same substeps one by one, with the check off; the first substep after which a
  // particle is faster than 1000 m/s is where the checked step must stop, with the same state.
  ClothMaterial m;
  m.stretchStiffness = m.shearStiffness = m.bendStiffness = 1e5;
  Cloth checked = meshGrid(8, 1.0, 1.5, GridPins::TopCorners, m);
  Cloth reference = checked;
  const int substeps = 4;
  const Real h = 3.0 * explicitStabilityLimit(checked), dt = substeps * h;
  pba::testing::FloatingPointTrapsOff traps;  // the reference overflows on purpose
  ClothSolverSettings off = explicitSettings(1);
  off.divergedSpeed = 0.0;
  ClothSolver referenceSolver, solver;
  int firstPast = -1;  // counted in substeps from the start
  for (int k = 0; k < 20 * substeps && firstPast < 0; ++k) {
    referenceSolver.step(reference, ClothEnvironment{}, {}, off, h, k * h);
    if (!(fastestSpeed(reference) <= 1000.0)) firstPast = k + 1;
  }
  ASSERT_GT(firstPast, substeps) << "diverges within the first frame: the test would not see a whole step";
  ClothStepStats stats;
  int frames = 0;
  for (; frames < 20 && !stats.diverged; ++frames) {
    stats = solver.step(checked, ClothEnvironment{}, {}, explicitSettings(substeps), dt, frames * dt);
  }
  ASSERT_TRUE(stats.diverged);
  EXPECT_EQ((frames - 1) * substeps + stats.substepsTaken, firstPast);
  ASSERT_EQ(checked.size(), reference.size());
  for (std::size_t i = 0; i < checked.size(); ++i) {
    // Substeps of h, whether as 40 per step or one per step, are the same arithmetic.
    EXPECT_EQ(checked.position[i], reference.position[i]) << "particle " << i;
  }
  // A step from the diverged state does nothing, and says so.
  const std::vector<Vec3> before = checked.position;
  stats = solver.step(checked, ClothEnvironment{}, {}, explicitSettings(substeps), dt, frames * dt);
  EXPECT_TRUE(stats.diverged);
  EXPECT_EQ(stats.substepsTaken, 0);
  EXPECT_EQ(checked.position, before);
}

TEST(ExplicitCloth, AStableStepTakesEverySubstep) {
  Cloth c = meshGrid(10, 1.0, 1.5, GridPins::TopCorners);
  ClothSolver solver;
  const ClothStepStats stats = solver.step(c, ClothEnvironment{}, {}, explicitSettings(40), 1.0 / 60.0, 0.0);
  EXPECT_FALSE(stats.diverged);
  EXPECT_EQ(stats.substepsTaken, 40);
}

TEST(ClothTearing, KeepsTheMeshValidAndFiniteWhilePulledApart) {
  ClothMaterial m;
  m.springDamping = 0.1;
  Cloth c = meshGrid(12, 1.0, 1.5, GridPins::TopRow, m);
  ClothSolverSettings s = explicitSettings(40);
  s.tearing.enabled = true;
  s.tearing.threshold = 0.3;
  ClothSolver solver;
  ClothEnvironment env;
  Real t = 0.0;
  const std::size_t bottom = c.size() - 6;  // a particle in the middle of the bottom row
  for (int f = 0; f < 120; ++f) {
    // Drag the far edge's middle particle away from the pinned row at 2 m/s: the cloth must tear.
    pin(c, static_cast<std::uint32_t>(bottom), c.restPosition[bottom] + Vec3(0.0, 0.0, 2.0 * (f + 1) / 60.0));
    solver.step(c, env, {}, s, 1.0 / 60.0, t);
    t += 1.0 / 60.0;
    ASSERT_EQ(checkMeshConsistency(c), "") << "frame " << f;
    ASSERT_FALSE(describeNonFinite(c).has_value()) << "frame " << f;
  }
  EXPECT_GT(c.torn, 0u);
  EXPECT_GT(c.size(), 144u);               // particles were split
  EXPECT_NEAR(c.totalMass(), 0.2, 1e-12);  // mass is conserved by the splits
}

TEST(SelfCollision, AFallingSheetNeverPassesThroughAPinnedOne) {
  // Two sheets in one cloth: the lower one is pinned flat, the upper one falls on it. Without
  // self-collision it would fall straight through.
  const Real spacing = 0.02;
  StackedSheets sheets = stackedSheets(11, spacing, 0.08);
  Cloth& c = sheets.cloth;
  const ClothMaterial& m = sheets.material;
  const std::uint32_t offset = sheets.upperFirst;
  ClothSolverSettings s = explicitSettings(80);
  s.selfCollision = true;
  ClothSolver solver;
  particles::SpatialHash hash;
  Real t = 0.0;
  for (int f = 0; f < 90; ++f) {
    solver.step(c, ClothEnvironment{}, {}, s, 1.0 / 60.0, t);
    t += 1.0 / 60.0;
    ASSERT_EQ(countSelfIntersections(c.position, c.restPosition, m.thickness, hash), 0u) << "frame " << f;
  }
  // The upper sheet rests on the lower one, a thickness above it (within the sag between particles).
  for (std::size_t i = offset; i < c.size(); ++i) EXPECT_GT(c.position[i].y, 1.5 + 0.5 * spacing);
}

TEST(ClothSolver, IsDeterministic) {
  auto simulate = [] {
    Cloth c = meshGrid(10, 1.0, 1.5, GridPins::TopCorners);
    ClothSolverSettings s = explicitSettings(30);
    s.selfCollision = true;
    ClothSolver solver;
    run(c, solver, ClothEnvironment{}, {}, s, 1.0 / 60.0, 60);
    return testing::stateHash(c);
  };
  EXPECT_EQ(simulate(), simulate());
}

TEST(ClothSolverSettings, BadValuesGiveAnErrorNamingTheField) {
  ClothSolverSettings s;
  s.substeps = 0;
  EXPECT_NE(validate(s).error().find("substeps"), std::string::npos);
  s = {};
  s.iterations = -1;
  EXPECT_NE(validate(s).error().find("iterations"), std::string::npos);
  EXPECT_TRUE(validate(ClothSolverSettings{}).ok());
  EXPECT_EQ(parseSolver("xpbd"), ClothSolverKind::Xpbd);
  EXPECT_FALSE(parseSolver("verlet").has_value());
  for (ClothSolverKind k : kAllClothSolvers) EXPECT_EQ(parseSolver(solverName(k)), k);
}

}  // namespace
}  // namespace pba::cloth
