// Joint limits in the solvers (exercise IK-6, clampJointToLimits; Workbook §2.7, IK slides "Joint
// limits"). One exercise, one grade: these tests run only solver paths whose sole exercise is IK-6 —
// the Jacobian-family methods that are no exercise (JT, pinv, SDLS, gradient descent, L-BFGS) on the
// central-difference Jacobian (so IK-3's columns play no part), and the analytic solver on hinges
// (the reference hinge formula, no IK-1). CCD and FABRIK with limits run IK-2 or IK-5 as well, so no
// test grades them together.
//
// Each test includes a goal that only the clamp keeps out of reach: a chain whose joints may turn
// ±35° must curl more than that to reach it. With the clamp the solve ends short, at a limit, inside
// the limits; with IK-6 still a stub it would reach the goal by leaving them — so every test here
// fails against the stub.
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <random>

#include <gtest/gtest.h>

#include "ik_random_targets.h"

namespace pba::ik {
namespace {

#ifdef NDEBUG
constexpr int kTargets = 300;
#else
constexpr int kTargets = 60;
#endif

using testing::chain;

SolveOptions limited(SolverKind kind) {
  SolveOptions o = testing::unlimited(kind, JacobianSource::CentralDifferences);
  o.enforceLimits = true;
  return o;
}

// The limits scene's setup: 6 planar hinges of 1/3 m limited to ±35°, the goal 0.54 m from the base,
// up and back over the chain (it needs more bend than ±35° per joint allows).
void expectStopsAtTheLimits(const SolveOptions& o) {
  ChainDesc d;
  d.links = 6;
  d.limit = degToRad(35.0);
  Rig rig = buildIkChain(d).value();
  rig.effectors[0].targetPosition = Vec3(0.2, 0.5, 0.0);
  Pose pose = rig.skeleton.restPose();
  const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
  SCOPED_TRACE(::testing::Message() << solverName(o.solver) << " toward a goal outside the limits' workspace");
  EXPECT_LE(limitViolation(rig.skeleton, pose), 1e-9);
  const Real actual = residual(rig.effectors, forwardKinematics(rig.skeleton, pose)).position;
  EXPECT_GT(actual, 0.05) << "the goal lies outside what ±35° per joint can reach";
  int atLimit = 0;
  for (int i = 0; i < rig.skeleton.dofCount(); ++i) {
    const Real v = pose.dofs[static_cast<size_t>(i)];
    atLimit += std::abs(v - rig.skeleton.dofLo(i)) < 1e-9 || std::abs(v - rig.skeleton.dofHi(i)) < 1e-9;
  }
  EXPECT_GE(atLimit, 1) << "some joint must sit at its limit";
}

void expectWithinLimitsOnRandomTargets(const Rig& rig, const SolveOptions& o, Real minimumRate, const char* label) {
  const testing::BatchStats s = testing::runRandomTargets(rig, o, kTargets, 31);
  std::printf("[ stats    ] %s (central differences) on %s: %.1f %% of %d, %.1f iterations\n", solverName(o.solver),
              label, 100.0 * s.successRate(), s.solves, s.meanIterations);
  SCOPED_TRACE(::testing::Message() << solverName(o.solver) << " on " << label);
  EXPECT_EQ(s.nonFinite, 0);
  EXPECT_LE(s.worstLimitViolation, 1e-9);
  EXPECT_GE(s.successRate(), minimumRate);
}

// (The Jacobian transpose and SDLS are the exercises IK-7 and IK-8: one exercise's test runs no other
// exercise.)
TEST(IK_6_LimitsInSolvers, JacobianMethodsStayWithinTheLimits) {
  for (SolverKind kind : {SolverKind::PseudoInverse}) {
    expectStopsAtTheLimits(limited(kind));
    expectWithinLimitsOnRandomTargets(chain(JointType::Ball), limited(kind), 0.95, "10 ball joints ±120°");
    expectWithinLimitsOnRandomTargets(chain(JointType::Hinge), limited(kind), 0.6, "10 hinges ±120°");
  }
}

// Both limit modes of the Jacobian methods (IK slides: clamp after each step, or also zero the
// columns of DOFs pushed against their limit) keep the pose inside.
TEST(IK_6_LimitsInSolvers, ClampAndZeroColumnModesBothRespectTheLimits) {
  for (JacobianLimitMode mode : {JacobianLimitMode::Clamp, JacobianLimitMode::ZeroColumns}) {
    SolveOptions o = limited(SolverKind::PseudoInverse);
    o.limitMode = mode;
    expectStopsAtTheLimits(o);
    expectWithinLimitsOnRandomTargets(chain(JointType::Ball, 10, 60.0), o, 0.9, "10 ball joints ±60°");
  }
}

// Gradient descent and L-BFGS handle limits by projection (asst4 extension): trial poses clamped
// into the box, DOFs pushed outward frozen.
TEST(IK_6_LimitsInSolvers, ProjectedGradientMethodsStayWithinTheLimits) {
  for (SolverKind kind : {SolverKind::GradientDescent, SolverKind::Lbfgs}) {
    SolveOptions o = limited(kind);
    o.lineSearch = LineSearch::Backtracking;
    expectStopsAtTheLimits(o);
    expectWithinLimitsOnRandomTargets(chain(JointType::Ball, 10, 60.0), o, 0.9, "10 ball joints ±60°");
  }
}

// Analytic IK on hinges (the exact hinge angle, then IK-6's clamp): every goal inside the limits is
// reached in one step; a goal whose direction needs more than the limit leaves the joint at it.
TEST(IK_6_LimitsInSolvers, AnalyticHingesStayWithinTheirLimits) {
  for (int links : {1, 2}) {
    ChainDesc d;
    d.links = links;
    d.limit = degToRad(60.0);
    const Rig rig = buildIkChain(d).value();
    SolveOptions o = limited(SolverKind::Analytic);
    const testing::BatchStats s = testing::runRandomTargets(rig, o, kTargets, 5);
    EXPECT_EQ(s.successes, s.solves) << links << " hinges";
    EXPECT_LE(s.worstLimitViolation, 1e-9);
    std::vector<Effector> behind = rig.effectors;
    behind[0].targetPosition = Vec3(-1.0, 0.5, 0.0);  // 153° from the rest direction
    Pose pose = rig.skeleton.restPose();
    const SolveResult r = solve(rig.skeleton, pose, behind, o);
    EXPECT_EQ(r.status, SolveStatus::Unreachable) << statusName(r.status);
    EXPECT_LE(limitViolation(rig.skeleton, pose), 1e-9);
    EXPECT_NEAR(std::abs(pose.dofs[0]), degToRad(60.0), 1e-9) << "the first hinge turns as far as it may";
  }
  expectStopsAtTheLimits(limited(SolverKind::PseudoInverse));
}

// Stall recovery (SolveOptions::restarts; IK slides, "Stopping": when stuck, randomise the pose).
// Limits make local minima: the pseudo-inverse as published stalls short of many goals on ±120°
// hinges. Restarting from random poses inside the limits, within the same iteration cap, recovers
// them; the restarts are counted and bounded, and no attempt leaves the limits.
TEST(IK_6_StallRecovery, RestartsFromRandomPosesInsideTheLimitsWithinTheCap) {
  const Rig rig = chain(JointType::Hinge);
  SolveOptions none = limited(SolverKind::PseudoInverse);
  SolveOptions with = none;
  with.restarts = 10;
  const testing::BatchStats a = testing::runRandomTargets(rig, with, kTargets, 99);
  const testing::BatchStats b = testing::runRandomTargets(rig, none, kTargets, 99);
  std::printf(
      "[ stats    ] pinv on 10 hinges ±120°: %.1f %% with stall recovery (%.3f restarts per solve), %.1f %% without\n",
      100.0 * a.successRate(), a.meanRestarts, 100.0 * b.successRate());
  EXPECT_EQ(b.meanRestarts, 0.0);
  EXPECT_GT(a.meanRestarts, 0.0);
  EXPECT_GT(a.successRate(), b.successRate() + 0.05);
  EXPECT_LE(a.maxIterations, with.maxIterations);
  EXPECT_LE(a.worstLimitViolation, 1e-9);
  EXPECT_LE(b.worstLimitViolation, 1e-9);
  Rig r = rig;
  std::mt19937_64 rng(4);
  for (int i = 0; i < 30; ++i) {
    setGoalsFromPose(r.skeleton, randomPose(r.skeleton, rng), r.effectors);
    Pose pose = r.skeleton.restPose();
    SolveOptions few = with;
    few.restarts = 2;
    const SolveResult result = solve(r.skeleton, pose, r.effectors, few);
    EXPECT_LE(result.restarts, 2);
    EXPECT_LE(result.iterations, few.maxIterations);
  }
  expectStopsAtTheLimits(with);
}

}  // namespace
}  // namespace pba::ik
