// The Jacobian-family methods that are no exercise (JT, pinv, SDLS) and the options that depart from
// their sources, tested on reference-only code: the central-difference Jacobian and no joint limits,
// so these tests pass in the student release too. Expected steps come from Eigen (pseudo-inverse by
// its SVD), not from the library's own routines.
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/SVD>

#include "ik_random_targets.h"

namespace pba::ik {
namespace {

using testing::chain;

SolveOptions reference(SolverKind kind) { return testing::unlimited(kind, JacobianSource::CentralDifferences); }

// One iteration of `o` from `pose`; returns the pose after it.
Pose oneStep(const Rig& rig, const std::vector<Effector>& effectors, const Pose& pose, SolveOptions o) {
  o.maxIterations = 1;
  o.tolerance = 1e-15;
  o.stallIterations = 0;
  Pose after = pose;
  solve(rig.skeleton, after, effectors, o);
  return after;
}

Real largestChange(const Pose& a, const Pose& b) {
  Real largest = 0.0;
  for (size_t i = 0; i < a.dofs.size(); ++i) largest = std::max(largest, std::abs(a.dofs[i] - b.dofs[i]));
  return largest;
}

// The defaults are the methods as published: a pinv step is the whole Gauss-Newton step
// Δθ = J⁺ Δe (σ below cutoff · σ_max dropped), with no clamp and no line search. Reference: J by
// central differences of FK here, J⁺ Δe by Eigen's SVD solve; Δe within the error clamp.
TEST(IkMethods, PseudoInverseTakesTheFullGaussNewtonStepByDefault) {
  const Rig rig = chain(JointType::Hinge, 4, 180.0);  // 4 planar hinges of 0.5 m: J is 3 × 4, rank 2
  std::vector<Effector> effectors = rig.effectors;
  Pose pose = rig.skeleton.restPose();
  pose.dofs = {0.3, 0.5, -0.4, 0.8};
  const Vec3 tip = effectorPosition(effectors[0], forwardKinematics(rig.skeleton, pose));
  effectors[0].targetPosition = tip + Vec3(-0.3, 0.2, 0.0);  // 0.36 m < the 0.5 m error clamp
  const Pose after = oneStep(rig, effectors, pose, reference(SolverKind::PseudoInverse));
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(testing::centralDifferenceJacobian(rig.skeleton, pose, effectors),
                                        Eigen::ComputeThinU | Eigen::ComputeThinV);
  svd.setThreshold(1e-3);  // SolveOptions::singularCutoff, relative to σ_max as in the solver
  const Vec3 de = effectors[0].targetPosition - tip;
  const Eigen::VectorXd step = svd.solve(Eigen::Vector3d(de.x, de.y, de.z));
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(after.dofs[size_t(i)] - pose.dofs[size_t(i)], step(i), 1e-8) << "dof " << i;
}

// SDLS as Buss & Kim 2005 publish it: no step exceeds γ_max = π/4, and no 0.5 rad clamp of ours
// shortens it. One ball joint with a 2 m bone along x, goal at 90° (0, 2, 0): the error (2.83 m) is
// clamped to D_max = 2 m, so the pseudo-inverse response about z is 1/√2 rad; for that singular
// vector N = 1 and M = σ⁻¹ |v_z| ρ_z = 1, so γ = γ_max and the step is the whole 1/√2 rad.
TEST(IkMethods, SelectivelyDampedStepsAreBoundedByTheirOwnGammaMax) {
  const Rig bone = chain(JointType::Ball, 1, 180.0);
  std::vector<Effector> up = bone.effectors;
  up[0].targetPosition = Vec3(0.0, 2.0, 0.0);
  const Pose rest = bone.skeleton.restPose();
  const Pose first = oneStep(bone, up, rest, reference(SolverKind::SelectivelyDamped));
  EXPECT_NEAR(first.dofs[2], 1.0 / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(std::abs(first.dofs[0]) + std::abs(first.dofs[1]), 0.0, 1e-6);
  // On a chain toward a goal across it, no step exceeds γ_max.
  const Rig rig = chain(JointType::Ball, 6, 180.0);
  std::vector<Effector> effectors = rig.effectors;
  effectors[0].targetPosition = Vec3(-0.4, 1.2, 0.6);
  Pose pose = rig.skeleton.restPose();
  pose.dofs[1] = 0.2;  // off the straight, singular pose
  for (int step = 0; step < 20; ++step) {
    const Pose next = oneStep(rig, effectors, pose, reference(SolverKind::SelectivelyDamped));
    EXPECT_LE(largestChange(pose, next), kPi / 4.0 + 1e-12) << "step " << step;
    pose = next;
  }
}

// The departures are options: maxJointStep bounds every step of JT, pinv and SDLS.
TEST(IkMethods, MaxJointStepBoundsEveryStepWhenSet) {
  const Rig rig = chain(JointType::Ball, 6, 180.0);
  std::vector<Effector> effectors = rig.effectors;
  effectors[0].targetPosition = Vec3(-0.4, 1.2, 0.6);
  for (SolverKind kind : {SolverKind::JacobianTranspose, SolverKind::PseudoInverse, SolverKind::SelectivelyDamped}) {
    SolveOptions o = reference(kind);
    o.maxJointStep = 0.1;
    Pose pose = rig.skeleton.restPose();
    pose.dofs[1] = 0.2;
    Real largest = 0.0;
    for (int step = 0; step < 15; ++step) {
      const Pose next = oneStep(rig, effectors, pose, o);
      largest = std::max(largest, largestChange(pose, next));
      pose = next;
    }
    EXPECT_LE(largest, 0.1 + 1e-12) << solverName(kind);
    EXPECT_GT(largest, 0.05) << solverName(kind) << ": the steps must move the chain";
  }
}

// The line-search option: every accepted step of JT (Armijo, from Buss's α), pinv and SDLS
// decreases the residual, and the solve makes real progress (at least halves the rest pose's
// residual), which a method that stands still would not.
TEST(IkMethods, JacobianLineSearchNeverIncreasesTheResidual) {
  Rig rig = chain(JointType::Ball, 8, 180.0);
  std::mt19937_64 rng(7);
  for (SolverKind kind : {SolverKind::JacobianTranspose, SolverKind::PseudoInverse, SolverKind::SelectivelyDamped})
    for (int i = 0; i < 10; ++i) {
      setGoalsFromPose(rig.skeleton, randomPose(rig.skeleton, rng), rig.effectors);
      Pose pose = rig.skeleton.restPose();
      SolveOptions o = reference(kind);
      o.jacobianLineSearch = true;
      o.recordHistory = true;
      o.maxIterations = 200;
      const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
      ASSERT_GE(r.residualHistory.size(), 2u);
      for (size_t k = 1; k < r.residualHistory.size(); ++k)
        EXPECT_LE(r.residualHistory[k], r.residualHistory[k - 1] * (1.0 + 1e-12))
            << solverName(kind) << " target " << i;
      EXPECT_LT(r.residualHistory.back(), 0.5 * r.residualHistory.front()) << solverName(kind) << " target " << i;
    }
}

// The methods as published (no clamp, no line search, no restarts) on the reference Jacobian reach
// random reachable goals of a 10-link chain.
TEST(IkMethods, PublishedMethodsReachRandomTargetsOnTheReferenceJacobian) {
  for (SolverKind kind : {SolverKind::JacobianTranspose, SolverKind::PseudoInverse, SolverKind::SelectivelyDamped}) {
    const testing::BatchStats s = testing::runRandomTargets(chain(JointType::Ball), reference(kind), 200, 17);
    EXPECT_EQ(s.nonFinite, 0) << solverName(kind);
    EXPECT_GE(s.successRate(), 0.97) << solverName(kind);
    EXPECT_LE(s.worstReportMismatch, 1e-9) << solverName(kind);
  }
}

// Analytic IK on 1 and 2 hinges uses the exact hinge angle (reference code, no exercise): every goal
// a pose reaches is reached in one step.
TEST(IkMethods, AnalyticHingeChainsReachEveryGoalInOneStep) {
  for (int links : {1, 2}) {
    ChainDesc d;
    d.links = links;
    const testing::BatchStats s =
        testing::runRandomTargets(buildIkChain(d).value(), testing::unlimited(SolverKind::Analytic), 500, 1);
    EXPECT_EQ(s.successes, s.solves) << links << " hinges";
    EXPECT_LE(s.maxIterations, 1);
  }
}

}  // namespace
}  // namespace pba::ik
