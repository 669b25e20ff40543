#pragma once
// Shared helper of the IK solver tests: K solves from the rest pose toward goals made by forward
// kinematics of random poses inside the limits (reachable by construction), with statistics.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "physics/exercises/not_implemented.h"
#include "physics/ik/builders.h"
#include "physics/ik/jacobian.h"
#include "physics/ik/solver.h"

namespace pba::ik::testing {

/// The test chain: `links` links of `joint` along +x, every rotational DOF within ±limitDegrees.
inline Rig chain(JointType joint, int links = 10, Real limitDegrees = 120.0) {
  ChainDesc d;
  d.joint = joint;
  d.links = links;
  d.limit = degToRad(limitDegrees);
  return buildIkChain(d).value();
}

/// Options of a solver test: the method as published (SolveOptions' defaults: no restarts, no step
/// clamp, no line search of the Jacobian methods), iteration cap 1,000, joint limits off. An exercise
/// test of IK-n must not depend on IK-6's clamp (one exercise, one grade): limits are IK-6's tests'
/// business (ik_limits_test.cpp). `jacobian`: CentralDifferences keeps IK-3 out of a method's test.
inline SolveOptions unlimited(SolverKind kind, JacobianSource jacobian = JacobianSource::Analytic) {
  SolveOptions o;
  o.solver = kind;
  o.maxIterations = 1000;
  o.enforceLimits = false;
  o.jacobian = jacobian;
  return o;
}

/// J at `pose` by central differences of forward kinematics (orientation scale 1 m/rad), as an Eigen
/// matrix for reference computations (Eigen's SVD) independent of IK-3 and of linalg.cpp.
inline Eigen::MatrixXd centralDifferenceJacobian(const Skeleton& s, const Pose& pose,
                                                 const std::vector<Effector>& effectors) {
  const JacobianLayout layout = planJacobian(s, pose, effectors, forwardKinematics(s, pose), 1.0);
  const Matrix J = numericalJacobian(s, pose, effectors, layout, 1.0, kJacobianStep);
  Eigen::MatrixXd out(J.rows, J.cols);
  for (int r = 0; r < J.rows; ++r)
    for (int c = 0; c < J.cols; ++c) out(r, c) = J(r, c);
  return out;
}

/// True (and says so, with `consequence`) when an exercise stub ran since the last exercises::clearNotImplemented():
/// a test of a method that runs two exercises (CCD or FABRIK with limits) then checks nothing that needs the
/// solutions (docs/decisions/2026-12-01-ik-one-exercise-one-grade.md).
inline bool stubRan(const char* consequence) {
  const std::vector<std::string> stubs = exercises::notImplementedTags();
  if (stubs.empty()) return false;
  std::printf("[ stats    ] the stub of %s ran: %s\n", stubs.front().c_str(), consequence);
  return true;
}

struct BatchStats {
  int solves = 0;
  int successes = 0;
  int nonFinite = 0;
  Real worstLimitViolation = 0.0;  ///< [rad]
  Real worstResidual = 0.0;        ///< [m] recomputed from forward kinematics of the returned pose
  Real worstReportMismatch = 0.0;  ///< [m] largest |reported residual − recomputed residual|
  double meanIterations = 0.0;
  double meanRestarts = 0.0;  ///< stall recoveries per solve (SolveOptions::restarts)
  int maxIterations = 0;      ///< largest iteration count of a solve
  Real successRate() const { return solves > 0 ? Real(successes) / solves : 0.0; }
};

inline BatchStats runRandomTargets(const Rig& rig, const SolveOptions& options, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  BatchStats stats;
  long iterations = 0, restarts = 0;
  for (int i = 0; i < count; ++i) {
    std::vector<Effector> effectors = rig.effectors;
    setGoalsFromPose(rig.skeleton, randomPose(rig.skeleton, rng), effectors);
    Pose pose = rig.skeleton.restPose();
    const SolveResult r = solve(rig.skeleton, pose, effectors, options);
    ++stats.solves;
    iterations += r.iterations;
    restarts += r.restarts;
    stats.maxIterations = std::max(stats.maxIterations, r.iterations);
    bool finite = isFinite(r.positionResidual);
    for (Real v : pose.dofs) finite = finite && isFinite(v);
    if (!finite) ++stats.nonFinite;
    // The solver's own residual is not trusted: the pose it returns must reach the goal.
    const Real actual = residual(effectors, forwardKinematics(rig.skeleton, pose)).position;
    stats.worstReportMismatch = std::max(stats.worstReportMismatch, std::abs(actual - r.positionResidual));
    if (r.status == SolveStatus::Success && actual <= options.tolerance * (1.0 + 1e-9)) ++stats.successes;
    stats.worstResidual = std::max(stats.worstResidual, actual);
    stats.worstLimitViolation = std::max(stats.worstLimitViolation, limitViolation(rig.skeleton, pose));
  }
  stats.meanIterations = count > 0 ? double(iterations) / count : 0.0;
  stats.meanRestarts = count > 0 ? double(restarts) / count : 0.0;
  return stats;
}

}  // namespace pba::ik::testing
