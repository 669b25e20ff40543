// Whole-solver tests. Every solver runs exercise code (IK-2 in CCD, IK-3 in every Jacobian method,
// IK-5 in FABRIK, IK-6 wherever limits are enforced), so the suites carry the tag of the solver's
// main exercise and fail, as they must, in the student release.
//
// Random reachable targets: goals are forward kinematics of random poses inside the limits. The
// default suite runs kTargets of them per solver and chain (10,000 in release builds; 2,000 in debug
// builds, where 10,000 per solver would take longer than the 10 s budget of a unit test). The
// thresholds are issue 3's: ≥ 99 % for CCD and FABRIK, ≥ 99.5 % for DLS and SDLS (and 99 % for JT
// and pinv), within the iteration cap, on chains whose every DOF is limited to ±120°, with the
// default stall recovery (SolveOptions::restarts); limits never violated by more than 1e-9.
#include <initializer_list>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "ik_random_targets.h"
#include "physics/ik/analytic.h"
#include "support/expect_helpers.h"

namespace pba::ik {
namespace {

#ifdef NDEBUG
constexpr int kTargets = 10000;
#else
constexpr int kTargets = 2000;
#endif

using testing::chain;

// A method far below its threshold on the first goals (an exercise still a stub: every solve stalls
// and restarts up to the cap) fails at once instead of spending minutes on all of them.
bool farBelowOnAFewGoals(const Rig& rig, const SolveOptions& o, Real minimumRate, std::uint64_t seed, const char* label, int few = 100) {
  const testing::BatchStats probe = testing::runRandomTargets(rig, o, few, seed);
  if (probe.successRate() >= minimumRate - 0.1) return false;
  ADD_FAILURE() << solverName(o.solver) << " on " << label << ": " << 100.0 * probe.successRate()
                << " % of the first " << few << " goals, far below the required " << 100.0 * minimumRate << " %";
  return true;
}

void expectRandomTargets(SolverKind kind, const Rig& rig, Real minimumRate, const char* label, int count = kTargets) {
  SolveOptions o;
  o.solver = kind;
  o.maxIterations = 1000;
  if (farBelowOnAFewGoals(rig, o, minimumRate, 2024, label)) return;
  const testing::BatchStats s = testing::runRandomTargets(rig, o, count, 2024);
  SCOPED_TRACE(::testing::Message() << solverName(kind) << " on " << label << ", seed 2024");
  std::printf("[ stats    ] %s on %s: %.2f %% of %d, %.1f iterations, %.3f restarts per solve\n", solverName(kind), label,
              100.0 * s.successRate(), s.solves, s.meanIterations, s.meanRestarts);
  EXPECT_EQ(s.nonFinite, 0);
  EXPECT_GE(s.successRate(), minimumRate) << "mean iterations " << s.meanIterations;
  EXPECT_LE(s.maxIterations, o.maxIterations) << "restarts share the iteration cap";
  EXPECT_LE(s.worstLimitViolation, 1e-9);
  EXPECT_LE(s.worstReportMismatch, 1e-9) << "the reported residual must be the returned pose's";
}

TEST(IK_2_CcdSolver, ReachesRandomReachableTargets) {
  expectRandomTargets(SolverKind::Ccd, chain(JointType::Ball), 0.99, "10 ball joints, limits ±120°");
  expectRandomTargets(SolverKind::Ccd, chain(JointType::Hinge), 0.99, "10 hinges, limits ±120°");
}

// Stall recovery (IK slides, "Stopping": when stuck, randomise the pose). With limits CCD crawls or
// stalls short of many goals; restarting from random poses inside the limits, within the same
// iteration cap, recovers them. The restarts are counted, bounded, and deterministic.
TEST(IK_2_CcdSolver, StallRecoveryRestartsFromRandomPosesWithinTheCap) {
  const Rig rig = chain(JointType::Hinge);
  SolveOptions o;
  o.solver = SolverKind::Ccd;
  o.maxIterations = 1000;
  SolveOptions none = o;
  none.restarts = 0;
  const testing::BatchStats with = testing::runRandomTargets(rig, o, 500, 99);
  const testing::BatchStats without = testing::runRandomTargets(rig, none, 500, 99);
  std::printf("[ stats    ] ccd on 10 hinges ±120°: %.1f %% with stall recovery (%.3f restarts per solve), %.1f %% without\n",
              100.0 * with.successRate(), with.meanRestarts, 100.0 * without.successRate());
  EXPECT_EQ(without.meanRestarts, 0.0);
  EXPECT_GT(with.meanRestarts, 0.0);
  EXPECT_GT(with.successRate(), without.successRate() + 0.05);
  EXPECT_LE(with.maxIterations, o.maxIterations);
  EXPECT_LE(with.worstLimitViolation, 1e-9);
  // Each restart is counted, never more than allowed.
  Rig r = rig;
  std::mt19937_64 rng(4);
  for (int i = 0; i < 50; ++i) {
    setGoalsFromPose(r.skeleton, randomPose(r.skeleton, rng), r.effectors);
    Pose pose = r.skeleton.restPose();
    SolveOptions few = o;
    few.restarts = 2;
    const SolveResult result = solve(r.skeleton, pose, r.effectors, few);
    EXPECT_LE(result.restarts, 2);
    EXPECT_LE(result.iterations, few.maxIterations);
  }
}

TEST(IK_5_FabrikSolver, ReachesRandomReachableTargets) {
  expectRandomTargets(SolverKind::Fabrik, chain(JointType::Ball), 0.99, "10 ball joints, limits ±120°");
  expectRandomTargets(SolverKind::Fabrik, chain(JointType::Hinge), 0.99, "10 hinges, limits ±120°");
  // Unconstrained ball joints: FABRIK iterates on points alone and writes the angles once at the end.
  expectRandomTargets(SolverKind::Fabrik, chain(JointType::Ball, 10, 180.0), 0.99, "10 unconstrained ball joints");
}

TEST(IK_2_CcdSolver, ReachesRandomReachableTargetsOnUnconstrainedChains) {
  // No limit can act, so CCD defers the Euler angles to the end of the solve (Context::flushPose).
  expectRandomTargets(SolverKind::Ccd, chain(JointType::Ball, 10, 180.0), 0.99, "10 unconstrained ball joints");
}

// Plain FABRIK (Aristidou & Lasenby 2011, Algorithm 1) written out here on points, independently of
// the library: on an unconstrained chain the solver must place every joint where the points are,
// iteration for iteration.
TEST(IK_5_FabrikSolver, UnconstrainedChainMatchesPlainFabrikOnPoints) {
  const Rig rig = chain(JointType::Ball, 12, 180.0);
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Effector> goals = rig.effectors;
    setGoalsFromPose(rig.skeleton, randomPose(rig.skeleton, rng), goals);
    const std::vector<Frame> rest = forwardKinematics(rig.skeleton, rig.skeleton.restPose());
    std::vector<Vec3> p;
    for (const Frame& f : rest) p.push_back(f.position);
    p.push_back(effectorPosition(goals[0], rest));
    std::vector<Real> length;
    for (size_t i = 0; i + 1 < p.size(); ++i) length.push_back(glm::length(p[i + 1] - p[i]));
    const Vec3 base = p.front(), goal = goals[0].targetPosition;
    const int iterations = 1 + trial % 4;
    for (int it = 0; it < iterations; ++it) {
      p.back() = goal;
      for (size_t i = p.size() - 1; i-- > 0;) p[i] = p[i + 1] + glm::normalize(p[i] - p[i + 1]) * length[i];
      p.front() = base;
      for (size_t i = 1; i < p.size(); ++i) p[i] = p[i - 1] + glm::normalize(p[i] - p[i - 1]) * length[i - 1];
    }
    SolveOptions o;
    o.solver = SolverKind::Fabrik;
    o.maxIterations = iterations;
    o.tolerance = 1e-15;  // run exactly `iterations` passes
    o.stallIterations = 0;
    Pose pose = rig.skeleton.restPose();
    const SolveResult r = solve(rig.skeleton, pose, goals, o);
    ASSERT_EQ(r.iterations, iterations);
    const std::vector<Frame> frames = forwardKinematics(rig.skeleton, pose);
    for (size_t j = 0; j < frames.size(); ++j) EXPECT_NEAR(glm::length(frames[j].position - p[j]), 0.0, 1e-9) << "joint " << j;
    EXPECT_NEAR(glm::length(effectorPosition(goals[0], frames) - p.back()), 0.0, 1e-9);
    EXPECT_NEAR(r.positionResidual, glm::length(goal - p.back()), 1e-9);
  }
}

TEST(IK_4_DampedLeastSquaresSolver, ReachesRandomReachableTargets) {
  expectRandomTargets(SolverKind::DampedLeastSquares, chain(JointType::Ball), 0.995, "10 ball joints, limits ±120°");
  expectRandomTargets(SolverKind::DampedLeastSquares, chain(JointType::Hinge), 0.995, "10 hinges, limits ±120°");
}

TEST(IK_4_SelectivelyDampedSolver, ReachesRandomReachableTargets) {
  expectRandomTargets(SolverKind::SelectivelyDamped, chain(JointType::Ball), 0.995, "10 ball joints, limits ±120°");
  expectRandomTargets(SolverKind::SelectivelyDamped, chain(JointType::Hinge), 0.995, "10 hinges, limits ±120°");
}

TEST(IK_3_JacobianTransposeAndPseudoInverse, ReachRandomReachableTargetsWithoutNaN) {
  expectRandomTargets(SolverKind::JacobianTranspose, chain(JointType::Ball), 0.99, "10 ball joints, limits ±120°");
  expectRandomTargets(SolverKind::JacobianTranspose, chain(JointType::Hinge), 0.99, "10 hinges, limits ±120°");
  expectRandomTargets(SolverKind::PseudoInverse, chain(JointType::Ball), 0.99, "10 ball joints, limits ±120°");
  expectRandomTargets(SolverKind::PseudoInverse, chain(JointType::Hinge), 0.99, "10 hinges, limits ±120°");
}

// L-BFGS (projected, with the driver's stall recovery) on the same chains and goals as DLS.
// Gradient descent with its golden-section search costs ~30 FK per step, so its random-goal test
// (ik_descent_test.cpp) uses fewer goals.
TEST(IK_3_Lbfgs, ReachesRandomReachableTargetsOnLimitedChains) {
  expectRandomTargets(SolverKind::Lbfgs, chain(JointType::Ball), 0.995, "10 ball joints, limits ±120°");
  expectRandomTargets(SolverKind::Lbfgs, chain(JointType::Hinge), 0.995, "10 hinges, limits ±120°");
}

// Analytic IK on every chain it applies to (1 or 2 links, hinge or ball, ±120°): every goal made by
// forward kinematics of a pose inside the limits is reached. A ball joint limited to more than ±90°
// on its middle Euler angle admits some rotations only in the second Euler representation, and a
// limited one reaches some directions only with a twist other than the shortest arc's.
TEST(IK_1_AnalyticSolver, ReachesEveryGoalInsideTheLimitsOfOneAndTwoLinkChains) {
  for (int links : {1, 2})
    for (JointType joint : {JointType::Hinge, JointType::Ball}) {
      ChainDesc d;
      d.links = links;
      d.joint = joint;
      SolveOptions o;
      o.solver = SolverKind::Analytic;
      const testing::BatchStats s = testing::runRandomTargets(buildIkChain(d).value(), o, kTargets, 1);
      SCOPED_TRACE(::testing::Message() << links << " " << jointTypeName(joint) << " links");
      EXPECT_EQ(s.successes, s.solves);
      EXPECT_EQ(s.nonFinite, 0);
      EXPECT_LE(s.worstLimitViolation, 1e-9);
      EXPECT_LE(s.maxIterations, 1);
    }
}

TEST(IK_3_JacobianTransposeAndPseudoInverse, JacobianTransposeNeverIncreasesTheResidual) {
  Rig rig = chain(JointType::Ball);
  std::mt19937_64 rng(7);
  for (int i = 0; i < 50; ++i) {
    setGoalsFromPose(rig.skeleton, randomPose(rig.skeleton, rng), rig.effectors);
    Pose pose = rig.skeleton.restPose();
    SolveOptions o;
    o.solver = SolverKind::JacobianTranspose;
    o.recordHistory = true;
    const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
    ASSERT_GE(r.residualHistory.size(), 2u);
    for (size_t k = 1; k < r.residualHistory.size(); ++k) EXPECT_LE(r.residualHistory[k], r.residualHistory[k - 1] + 1e-12);
    // Never increasing is not enough (a step of zero never increases it): the line search must
    // make real progress, at least halving the residual of the rest pose within the 200 steps.
    EXPECT_LT(r.residualHistory.back(), 0.5 * r.residualHistory.front()) << "target " << i;
  }
}

// Unreachable goals: every solver stretches the chain toward the goal; the residual is then the
// distance minus the reach, within 1e-6 m.
TEST(IK_4_AllSolvers, StretchTowardUnreachableTargets) {
  for (int k = 1; k < kSolverKindCount; ++k) {
    for (JointType joint : {JointType::Ball, JointType::Hinge}) {
      Rig rig = chain(joint, 10, 180.0);
      Pose pose = rig.skeleton.restPose();
      pose.dofs[2] = 0.4;  // start bent
      const Vec3 goal = joint == JointType::Ball ? Vec3(1.0, 2.5, -1.5) : Vec3(-2.0, 2.5, 0.0);
      rig.effectors[0].targetPosition = goal;
      SolveOptions o;
      o.solver = static_cast<SolverKind>(k);
      const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
      SCOPED_TRACE(::testing::Message() << solverName(o.solver) << " " << jointTypeName(joint));
      EXPECT_EQ(r.status, SolveStatus::Unreachable);
      EXPECT_NEAR(r.positionResidual, glm::length(goal) - 2.0, 1e-6);
      for (Real v : pose.dofs) EXPECT_TRUE(isFinite(v));
      // The driver's stretch leaves the chain straight: a singular pose. When the goal comes back
      // within reach (off the chain's line), the method itself must leave that pose and reach it.
      rig.effectors[0].targetPosition = joint == JointType::Ball ? Vec3(0.6, 0.9, -0.7) : Vec3(-0.7, 1.1, 0.0);
      o.maxIterations = 2000;
      const SolveResult back = solve(rig.skeleton, pose, rig.effectors, o);
      EXPECT_EQ(back.status, SolveStatus::Success) << statusName(back.status) << " residual " << back.positionResidual;
    }
  }
}

// Singular poses: a straight chain with the goal on its own axis (beyond, short of, behind the base),
// and a chain with a zero-length bone. No NaN (the traps of the test main would stop the test) and a
// clear status.
TEST(IK_4_AllSolvers, SingularPosesGiveFiniteResultsAndAClearStatus) {
  for (int k = 1; k < kSolverKindCount; ++k) {
    for (const Vec3& goal : {Vec3(1.5, 0, 0), Vec3(-1.0, 0, 0), Vec3(0.0), Vec3(2.0, 0, 0)}) {
      Rig rig = chain(JointType::Ball, 10, 180.0);
      Pose pose = rig.skeleton.restPose();
      rig.effectors[0].targetPosition = goal;
      SolveOptions o;
      o.solver = static_cast<SolverKind>(k);
      const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
      SCOPED_TRACE(::testing::Message() << solverName(o.solver) << " goal x " << goal.x);
      EXPECT_NE(r.status, SolveStatus::InvalidInput);
      EXPECT_TRUE(isFinite(r.positionResidual));
      for (Real v : pose.dofs) EXPECT_TRUE(isFinite(v));
    }
    Rig rig = chain(JointType::Ball, 4, 180.0);
    rig.skeleton.joint(2).offset = Vec3(0.0);  // zero-length bone
    Pose pose = rig.skeleton.restPose();
    rig.effectors[0].targetPosition = Vec3(0.3, 0.6, 0.2);
    SolveOptions o;
    o.solver = static_cast<SolverKind>(k);
    const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
    EXPECT_TRUE(isFinite(r.positionResidual)) << solverName(o.solver);
    EXPECT_EQ(r.status, SolveStatus::Success) << solverName(o.solver) << " " << statusName(r.status);
  }
}

TEST(IK_1_AnalyticSolver, SingleJointReachesAnyDirectionInOneStep) {
  Rig rig = buildSingleJoint(1.0).value();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const Vec3 dir = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    rig.effectors[0].targetPosition = dir;
    Pose pose = rig.skeleton.restPose();
    SolveOptions o;
    o.solver = SolverKind::Analytic;
    o.tolerance = 1e-12;
    const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
    EXPECT_EQ(r.status, SolveStatus::Success);
    EXPECT_LE(r.iterations, 1);
  }
}

TEST(IK_1_AnalyticSolver, TwoBoneArmIsExactAndBendsTowardThePole) {
  Rig rig = buildTwoBoneArm(TwoBoneDesc{}).value();
  // No limits on the shoulder, elbow in [0, 150°]: every target at a distance in [0.5, 1.6] m is
  // exactly reachable (a = 0.9, b = 0.8).
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  const Vec3 s = rig.skeleton.joint(0).offset;
  for (int i = 0; i < 500; ++i) {
    const Vec3 dir = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    const Real d = 0.5 + 1.1 * (0.5 + 0.5 * u(rng));  // the elbow's 150° limit keeps the wrist ≥ 0.45 m away
    rig.effectors[0].targetPosition = s + d * dir;
    Pose pose = rig.skeleton.restPose();
    SolveOptions o;
    o.solver = SolverKind::Analytic;
    o.tolerance = 1e-9;
    o.usePole = true;
    o.polePoint = s + Vec3(0.0, 0.0, 2.0);
    const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
    ASSERT_EQ(r.status, SolveStatus::Success) << "target " << i << " residual " << r.positionResidual;
    const std::vector<Frame> f = forwardKinematics(rig.skeleton, pose);
    const TwoBonePose expected = twoBoneGeometry(s, 0.9, 0.8, rig.effectors[0].targetPosition, o.polePoint);
    EXPECT_VEC3_NEAR(f[1].position, expected.elbow, 1e-9);
  }
}

TEST(IK_2_CcdSolver, IsDeterministicAndRepeatableFromRest) {
  Rig rig = chain(JointType::Ball);
  rig.effectors[0].targetPosition = Vec3(0.5, 1.0, 0.3);
  SolveOptions o;
  o.solver = SolverKind::Ccd;
  o.fromRest = true;
  Pose a = rig.skeleton.restPose();
  a.dofs[4] = 0.7;  // ignored: fromRest
  Pose b = rig.skeleton.restPose();
  const SolveResult ra = solve(rig.skeleton, a, rig.effectors, o);
  const SolveResult rb = solve(rig.skeleton, b, rig.effectors, o);
  EXPECT_EQ(ra.iterations, rb.iterations);
  EXPECT_EQ(a.dofs, b.dofs);
  // Repeatable and right: both solves reach the goal (a pose that never moves is repeatable too).
  EXPECT_EQ(ra.status, SolveStatus::Success) << statusName(ra.status) << " residual " << ra.positionResidual;
  EXPECT_LE(ra.positionResidual, o.tolerance);
  EXPECT_GT(ra.iterations, 0);
}

TEST(IK_2_CcdSolver, Solves1000LinkChains) {
  // FABRIK converges in a few iterations; CCD's O(n) passes move the tip joints most and need many
  // passes on 1,000 links (Workbook §2.4: "joints near the start of the sweep move much more"), so it
  // gets a looser tolerance here. docs/performance-ik.md has the timings.
  for (SolverKind kind : {SolverKind::Ccd, SolverKind::Fabrik}) {
    Rig rig = chain(JointType::Ball, 1000, 30.0);
    rig.effectors[0].targetPosition = Vec3(0.8, 0.9, -0.4);
    Pose pose = rig.skeleton.restPose();
    SolveOptions o;
    o.solver = kind;
    o.maxIterations = 500;
    o.tolerance = kind == SolverKind::Ccd ? 0.05 : 1e-4;
    const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
    EXPECT_EQ(r.status, SolveStatus::Success) << solverName(kind) << " " << statusName(r.status) << " " << r.positionResidual;
    EXPECT_LE(limitViolation(rig.skeleton, pose), 1e-9);
  }
  // Unconstrained (the FABRIK paper's setting): both converge to 1e-4 m, and the returned pose
  // reaches the goal (checked by forward kinematics here, not by the solver's own residual).
  for (SolverKind kind : {SolverKind::Ccd, SolverKind::Fabrik}) {
    Rig rig = chain(JointType::Ball, 1000, 180.0);
    std::mt19937_64 rng(3);
    setGoalsFromPose(rig.skeleton, randomPose(rig.skeleton, rng), rig.effectors);
    Pose pose = rig.skeleton.restPose();
    SolveOptions o;
    o.solver = kind;
    o.maxIterations = 200;
    const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
    EXPECT_EQ(r.status, SolveStatus::Success) << solverName(kind) << " " << statusName(r.status);
    EXPECT_LE(residual(rig.effectors, forwardKinematics(rig.skeleton, pose)).position, 1e-4 * (1.0 + 1e-9)) << solverName(kind);
  }
}

// Trees (Workbook §2.1 task 5, §2.7): Buss & Kim's double Y (ball joints, ±90°) and a hand (ball
// wrist ±80°, ball knuckles ±60°, phalanges hinged one way only, [−100°, 0]). Goals are forward
// kinematics of random poses: reachable by construction, every effector at once. FABRIK and CCD get
// the same goals. The hand is the hard case for FABRIK: a straight finger whose hinges bend one way
// must first find the plane and side it bends to, and its knuckle's twist is limited; one attempt
// succeeds on about a quarter of the goals, the stall recovery lifts that to about 85 % (CCD: 80 %
// and 99 %). Measured rates are printed; the thresholds leave a few points of margin.
#ifdef NDEBUG
constexpr int kTreeTargets = 300;
#else
constexpr int kTreeTargets = 60;
#endif

struct TreeCase {
  SolverKind kind;
  Real minimumRate;
};

void expectTreeTargets(const Rig& rig, const char* tree, std::initializer_list<TreeCase> cases) {
  for (const TreeCase& t : cases) {
    SolveOptions o;
    o.solver = t.kind;
    o.maxIterations = 1000;
    if (farBelowOnAFewGoals(rig, o, t.minimumRate, 12, tree, 20)) continue;
    const testing::BatchStats s = testing::runRandomTargets(rig, o, kTreeTargets, 12);
    std::printf("[ stats    ] %s on %s: %.1f %% of %d, %.1f iterations, %.2f restarts per solve\n", solverName(t.kind), tree,
                100.0 * s.successRate(), s.solves, s.meanIterations, s.meanRestarts);
    SCOPED_TRACE(::testing::Message() << solverName(t.kind) << " on " << tree);
    EXPECT_GE(s.successRate(), t.minimumRate);
    EXPECT_EQ(s.nonFinite, 0);
    EXPECT_LE(s.worstLimitViolation, 1e-9);
    EXPECT_LE(s.worstReportMismatch, 1e-9);
  }
}

TEST(IK_5_FabrikSolver, DoubleYReachesItsFourGoals) {
  expectTreeTargets(buildDoubleY().value(), "double Y",
                    {{SolverKind::Fabrik, 0.95}, {SolverKind::Ccd, 0.97}, {SolverKind::DampedLeastSquares, 0.99},
                     {SolverKind::SelectivelyDamped, 0.99}});
}

TEST(IK_5_FabrikSolver, HandReachesItsFiveGoals) {
  expectTreeTargets(buildHand().value(), "hand",
                    {{SolverKind::Fabrik, 0.75}, {SolverKind::Ccd, 0.95}, {SolverKind::DampedLeastSquares, 0.95},
                     {SolverKind::SelectivelyDamped, 0.95}});
}

// The sub-base rule of FABRIK on trees (Aristidou & Lasenby 2011 §4.3): without limits, on Buss's
// double Y, one attempt (no stall recovery) reaches every goal. Before the rigid-body passes this
// failed: the two branch joints that share a point moved apart in the point passes, so the points
// described no pose and the projection back to angles undid each pass.
TEST(IK_5_FabrikSolver, UnlimitedDoubleYConvergesWithoutRestarts) {
  Rig rig = buildDoubleY().value();
  SolveOptions o;
  o.solver = SolverKind::Fabrik;
  o.maxIterations = 1000;
  o.restarts = 0;
  o.enforceLimits = false;
  const testing::BatchStats s = testing::runRandomTargets(rig, o, kTreeTargets / 2, 12);
  std::printf("[ stats    ] fabrik on the unlimited double Y, no restarts: %.1f %%, %.1f iterations\n", 100.0 * s.successRate(),
              s.meanIterations);
  EXPECT_GE(s.successRate(), 0.99);
}

TEST(IK_3_SixDofEffector, JacobianMethodsCcdAndFabrikMatchPositionAndOrientation) {
  for (SolverKind kind : {SolverKind::DampedLeastSquares, SolverKind::SelectivelyDamped, SolverKind::PseudoInverse, SolverKind::Ccd,
                          SolverKind::Fabrik}) {
    Rig rig = chain(JointType::Ball, 6, 150.0);
    rig.effectors[0].kind = EffectorKind::PositionOrientation;
    std::mt19937_64 rng(21);
    int successes = 0;
    for (int i = 0; i < 100; ++i) {
      setGoalsFromPose(rig.skeleton, randomPose(rig.skeleton, rng), rig.effectors);
      Pose pose = rig.skeleton.restPose();
      SolveOptions o;
      o.solver = kind;
      o.maxIterations = 1000;
      const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
      successes += r.status == SolveStatus::Success && r.orientationResidual <= o.angleTolerance;
    }
    std::printf("[ stats    ] 6-DOF %s: %d / 100 solved\n", solverName(kind), successes);
    EXPECT_GE(successes, 90) << solverName(kind);
  }
}

}  // namespace
}  // namespace pba::ik
