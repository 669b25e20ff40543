// Gradient descent and L-BFGS (CMU asst4 "Gradient IK" and its extensions). Both run on IK-3's
// Jacobian columns, hence the IK_3_ tag; joint limits stay off (IK-6's clamp is its own exercise:
// projected-gradient limits are tested in ik_limits_test.cpp).
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include <Eigen/SVD>

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
  o.tolerance = 1e-12;         // never met: exactly kSteps steps
  o.stallIterations = 0;       // no stall test
  o.lineSearchMaxStep = 10.0;  // no step clamp
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
  const Rig rig = chain(JointType::Ball, 8, 120.0);  // goals from poses inside ±120°; limits off
  std::mt19937_64 rng(7);
  int successes = 0;
  for (int t = 0; t < 40; ++t) {
    std::vector<Effector> effectors = rig.effectors;
    setGoalsFromPose(rig.skeleton, randomPose(rig.skeleton, rng), effectors);
    for (int variant = 0; variant < 3; ++variant) {
      SolveOptions o = testing::unlimited(variant == 2 ? SolverKind::Lbfgs : SolverKind::GradientDescent);
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

// Random reachable goals (FK of random poses inside ±60°; seed 11): L-BFGS reaches at least 99 %
// within 500 iterations and needs fewer iterations than gradient descent with an exact
// (golden-section) line search — the point of a quasi-Newton method on an ill-conditioned
// least-squares problem.
TEST(IK_3_Lbfgs, ReachesRandomTargetsInFewerIterationsThanGradientDescent) {
  const Rig rig = chain(JointType::Ball, 10, 60.0);
  SolveOptions o = testing::unlimited(SolverKind::Lbfgs);
  o.maxIterations = 500;
  const testing::BatchStats quasiNewton = testing::runRandomTargets(rig, o, 300, 11);
  o.solver = SolverKind::GradientDescent;
  o.lineSearch = LineSearch::GoldenSection;
  const testing::BatchStats gradient = testing::runRandomTargets(rig, o, 300, 11);
  EXPECT_EQ(quasiNewton.nonFinite + gradient.nonFinite, 0);
  EXPECT_GE(quasiNewton.successRate(), 0.99);
  EXPECT_LE(quasiNewton.worstReportMismatch, 1e-9);
  EXPECT_LT(quasiNewton.meanIterations, gradient.meanIterations)
      << "L-BFGS " << quasiNewton.meanIterations << " vs gradient " << gradient.meanIterations << " iterations";
}

// asst4's fixed step and its stability limit. Near the optimum θ* of a reachable goal the fixed-step
// iteration is linear, δ ← (I − α JᵀJ) δ, so it converges (monotonically in f, every mode's factor
// |1 − α λᵢ| < 1) for α below 2/λ_max(JᵀJ) and moves away from θ* above it. λ_max comes from Eigen's
// SVD of a central-difference Jacobian at θ* (independent of IK-3). Below the limit (α = 1/λ_max) the
// residual must fall at every step down to the tolerance; above it (α = 3/λ_max, step clamp off) the
// top mode's factor is |1 − 3| = 2, so three steps must multiply the residual by more than 2 (the
// start error lies mostly along that mode). Far from θ* the iteration may still settle elsewhere on
// the redundant chain's solution set, where λ_max is smaller; the claim is local, and so is the test.
TEST(IK_3_GradientDescent, FixedStepConvergesBelowTheStabilityLimitAndNotAboveIt) {
  const Rig rig = chain(JointType::Hinge, 3, 180.0);
  Pose optimum = rig.skeleton.restPose();
  optimum.dofs = {0.3, 1.5, 1.5};  // well conditioned: λ₂/λ₁ ≈ 0.31, so α = 1/λ₁ converges in ~50 steps
  std::vector<Effector> effectors = rig.effectors;
  setGoalsFromPose(rig.skeleton, optimum, effectors);
  const Real sigmaMax =
      Eigen::JacobiSVD<Eigen::MatrixXd>(testing::centralDifferenceJacobian(rig.skeleton, optimum, effectors))
          .singularValues()(0);
  const Real limit = 2.0 / (sigmaMax * sigmaMax);  // [rad²/m²] 2 / λ_max(JᵀJ)
  auto run = [&](Real alpha) {
    SolveOptions o = testing::unlimited(SolverKind::GradientDescent);
    o.lineSearch = LineSearch::Fixed;
    o.gradientStep = alpha;
    o.lineSearchMaxStep = 10.0;  // no step clamp: the plain method
    o.maxIterations = 400;
    o.tolerance = 1e-7;
    o.stallIterations = 0;
    o.recordHistory = true;
    Pose pose = optimum;
    for (Real& v : pose.dofs) v += 0.05;  // start near θ*, where the linear analysis holds
    return solve(rig.skeleton, pose, effectors, o);
  };
  const SolveResult stable = run(0.5 * limit);
  EXPECT_EQ(stable.status, SolveStatus::Success) << "alpha " << 0.5 * limit << ": residual " << stable.positionResidual;
  for (size_t k = 1; k < stable.residualHistory.size(); ++k)
    EXPECT_LT(stable.residualHistory[k], stable.residualHistory[k - 1]) << "iteration " << k;
  const SolveResult unstable = run(1.5 * limit);
  ASSERT_GE(unstable.residualHistory.size(), 4u);
  EXPECT_GT(unstable.residualHistory[3], 2.0 * unstable.residualHistory[0])
      << "alpha " << 1.5 * limit << " exceeds the stability limit";
  EXPECT_TRUE(isFinite(unstable.positionResidual));
}

}  // namespace
}  // namespace pba::ik
