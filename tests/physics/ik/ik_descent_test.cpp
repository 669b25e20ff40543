// Gradient descent and L-BFGS (CMU asst4 "Gradient IK" and its extensions). Both run on IK-3's
// Jacobian columns (and IK-6's clamping where limits are enforced), hence the IK_3_ tag.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "ik_random_targets.h"

namespace pba::ik {
namespace {

using testing::chain;

// f(θ) = ½ |g − e(θ)|² for one position effector, by forward kinematics.
Real objectiveOf(const Rig& rig, const std::vector<Effector>& effectors, const std::vector<Real>& dofs) {
  Pose pose = rig.skeleton.restPose();
  pose.dofs = dofs;
  const Vec3 d = effectors[0].targetPosition - effectorPosition(effectors[0], forwardKinematics(rig.skeleton, pose));
  return 0.5 * glm::dot(d, d);
}

// asst4's method written out in the test: θ ← θ − α ∇f with ∇f by central differences of f (an
// independent reference for the solver's analytic gradient −Jᵀr). After 40 steps the two agree to
// 1e-7 rad: the finite-difference gradient is accurate to O(h²) ≈ 1e-10 per step.
TEST(IK_3_GradientDescent, FixedStepFollowsAReferenceLoopOnFiniteDifferenceGradients) {
  const Rig rig = chain(JointType::Hinge, 3, 180.0);
  std::vector<Effector> effectors = rig.effectors;
  effectors[0].targetPosition = Vec3(0.6, 1.3, 0.0);
  constexpr Real kAlpha = 0.15;  // [rad²/m²]
  constexpr int kSteps = 40;
  constexpr Real kH = 1e-5;
  std::vector<Real> theta = rig.skeleton.restPose().dofs;
  for (int step = 0; step < kSteps; ++step) {
    std::vector<Real> grad(theta.size());
    for (size_t i = 0; i < theta.size(); ++i) {
      std::vector<Real> plus = theta, minus = theta;
      plus[i] += kH;
      minus[i] -= kH;
      grad[i] = (objectiveOf(rig, effectors, plus) - objectiveOf(rig, effectors, minus)) / (2.0 * kH);
    }
    for (size_t i = 0; i < theta.size(); ++i) theta[i] -= kAlpha * grad[i];
  }

  SolveOptions o;
  o.solver = SolverKind::GradientDescent;
  o.lineSearch = LineSearch::Fixed;
  o.gradientStep = kAlpha;
  o.maxIterations = kSteps;
  o.tolerance = 1e-12;     // never met: exactly kSteps steps
  o.stallIterations = 0;   // no stall test
  o.maxJointStep = 10.0;   // no step clamp
  o.enforceLimits = false;
  Pose pose = rig.skeleton.restPose();
  const SolveResult r = solve(rig.skeleton, pose, effectors, o);
  EXPECT_EQ(r.iterations, kSteps);
  for (size_t i = 0; i < theta.size(); ++i) EXPECT_NEAR(pose.dofs[i], theta[i], 1e-7) << "dof " << i;
  EXPECT_LT(objectiveOf(rig, effectors, pose.dofs), objectiveOf(rig, effectors, rig.skeleton.restPose().dofs));
}

// Backtracking and golden-section line searches, and L-BFGS's Armijo search, accept only steps that
// decrease f: the residual (√(2f) for one effector) never grows from one iteration to the next.
TEST(IK_3_GradientDescent, LineSearchesNeverIncreaseTheResidual) {
  const Rig rig = chain(JointType::Ball, 8, 120.0);
  std::mt19937_64 rng(7);
  int successes = 0;
  for (int t = 0; t < 40; ++t) {
    std::vector<Effector> effectors = rig.effectors;
    setGoalsFromPose(rig.skeleton, randomPose(rig.skeleton, rng), effectors);
    for (int variant = 0; variant < 3; ++variant) {
      SolveOptions o;
      o.solver = variant == 2 ? SolverKind::Lbfgs : SolverKind::GradientDescent;
      o.lineSearch = variant == 0 ? LineSearch::Backtracking : LineSearch::GoldenSection;
      o.maxIterations = 200;
      o.recordHistory = true;
      Pose pose = rig.skeleton.restPose();
      const SolveResult r = solve(rig.skeleton, pose, effectors, o);
      for (size_t i = 1; i < r.residualHistory.size(); ++i)
        ASSERT_LE(r.residualHistory[i], r.residualHistory[i - 1] * (1.0 + 1e-12))
            << solverName(o.solver) << " " << lineSearchName(o.lineSearch) << ", target " << t << ", iteration " << i;
      successes += r.status == SolveStatus::Success;
    }
  }
  // Monotone and effective: not standing still (which would also never increase the residual).
  EXPECT_GE(successes, 3 * 40 * 9 / 10);
}

// Random reachable goals (FK of random poses inside ±60° limits; seed 11): L-BFGS reaches at least
// 99 % within 500 iterations, never leaves the limits (projected gradient), and needs fewer iterations
// than gradient descent with an exact (golden-section) line search — the point of a quasi-Newton
// method on an ill-conditioned least-squares problem.
TEST(IK_3_Lbfgs, ReachesRandomTargetsInFewerIterationsThanGradientDescent) {
  const Rig rig = chain(JointType::Ball, 10, 60.0);
  SolveOptions o;
  o.maxIterations = 500;
  o.solver = SolverKind::Lbfgs;
  const testing::BatchStats quasiNewton = testing::runRandomTargets(rig, o, 300, 11);
  o.solver = SolverKind::GradientDescent;
  o.lineSearch = LineSearch::GoldenSection;
  const testing::BatchStats gradient = testing::runRandomTargets(rig, o, 300, 11);
  EXPECT_EQ(quasiNewton.nonFinite + gradient.nonFinite, 0);
  EXPECT_GE(quasiNewton.successRate(), 0.99);
  EXPECT_LE(quasiNewton.worstLimitViolation, 1e-9);
  EXPECT_LE(gradient.worstLimitViolation, 1e-9);
  EXPECT_LE(quasiNewton.worstReportMismatch, 1e-9);
  EXPECT_LT(quasiNewton.meanIterations, gradient.meanIterations)
      << "L-BFGS " << quasiNewton.meanIterations << " vs gradient " << gradient.meanIterations << " iterations";
}

// A fixed step far above the stability limit 2/λ_max makes f oscillate, but the state stays finite
// (the per-step DOF clamp bounds every change) and the solve ends with a clear status.
TEST(IK_3_GradientDescent, OversizedFixedStepStaysFinite) {
  const Rig rig = chain(JointType::Ball, 10, 180.0);
  std::vector<Effector> effectors = rig.effectors;
  effectors[0].targetPosition = Vec3(0.5, 1.2, -0.4);
  SolveOptions o;
  o.solver = SolverKind::GradientDescent;
  o.lineSearch = LineSearch::Fixed;
  o.gradientStep = 10.0;
  o.restarts = 0;  // the chain must move by its own steps, not by a random restart
  Pose pose = rig.skeleton.restPose();
  const SolveResult r = solve(rig.skeleton, pose, effectors, o);
  EXPECT_NE(r.status, SolveStatus::InvalidInput);
  EXPECT_TRUE(isFinite(r.positionResidual));
  Real largest = 0.0;
  for (Real v : pose.dofs) {
    EXPECT_TRUE(isFinite(v));
    largest = std::max(largest, std::abs(v));
  }
  EXPECT_GT(largest, 0.1) << "the oversized steps must have moved the chain";
}

}  // namespace

TEST(IkSolveOptions, RejectsANonPositiveGradientStepAndAnEmptyMemory) {
  ChainDesc d;
  d.links = 2;
  const Rig rig = buildIkChain(d).value();
  for (int bad = 0; bad < 2; ++bad) {
    SolveOptions o;
    o.solver = bad == 0 ? SolverKind::GradientDescent : SolverKind::Lbfgs;
    if (bad == 0) o.gradientStep = 0.0;
    else o.lbfgsMemory = 0;
    Pose pose = rig.skeleton.restPose();
    const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
    EXPECT_EQ(r.status, SolveStatus::InvalidInput);
    EXPECT_NE(r.message.find(bad == 0 ? "gradientStep" : "lbfgsMemory"), std::string::npos) << r.message;
  }
}

TEST(IkSolverNames, RoundTripEverySolverAndListThemInOrder) {
  const std::vector<std::string> names = solverNames();
  ASSERT_EQ(static_cast<int>(names.size()), kSolverKindCount);
  for (int k = 0; k < kSolverKindCount; ++k) {
    SolverKind kind{};
    ASSERT_TRUE(solverFromName(names[static_cast<size_t>(k)], &kind)) << names[static_cast<size_t>(k)];
    EXPECT_EQ(static_cast<int>(kind), k);
    EXPECT_EQ(names[static_cast<size_t>(k)], solverName(kind));
  }
  SolverKind kind{};
  EXPECT_FALSE(solverFromName("newton", &kind));
}

}  // namespace pba::ik
