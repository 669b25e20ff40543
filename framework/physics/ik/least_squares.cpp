// The weighted least-squares problem shared by the Jacobian and descent methods (least_squares.h).
#include "physics/ik/least_squares.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "physics/ik/exercises.h"

namespace pba::ik::detail {

namespace {
Vec3 clampLength(const Vec3& v, Real maxLength) {
  const Real l = glm::length(v);
  return l > maxLength ? v * (maxLength / l) : v;
}
}  // namespace

void leastSquaresSystem(const Context& c, LeastSquaresSystem& sys) {
  const Skeleton& s = c.skeleton;
  sys.layout = planJacobian(s, c.pose, c.effectors, c.frames, c.orientationScale);
  if (c.options.jacobian == JacobianSource::Analytic)
    jacobian(s, c.pose, c.effectors, c.frames, sys.layout, c.orientationScale, sys.J);
  else
    sys.J = numericalJacobian(s, c.pose, c.effectors, sys.layout, c.orientationScale, kJacobianStep);
  Matrix& J = sys.J;
  const int m = J.rows, n = J.cols;
  sys.residual.assign(static_cast<size_t>(m), 0.0);
  sys.clamped.assign(static_cast<size_t>(m), 0.0);
  for (size_t k = 0; k < c.effectors.size(); ++k) {
    const Effector& e = c.effectors[k];
    const int row = sys.layout.rowOfEffector[k];
    const Vec3 dp = e.targetPosition - effectorPosition(e, c.frames);
    const Vec3 cp = clampLength(dp, c.maxErrorStep);
    for (int i = 0; i < 3; ++i) {
      sys.residual[static_cast<size_t>(row + i)] = e.weight * dp[i];
      sys.clamped[static_cast<size_t>(row + i)] = e.weight * cp[i];
    }
    const bool oriented = e.kind == EffectorKind::PositionOrientation;
    if (oriented) {
      const Vec3 w = c.orientationScale * orientationError(e, c.frames);
      const Vec3 cw = clampLength(w, c.maxErrorStep);
      for (int i = 0; i < 3; ++i) {
        sys.residual[static_cast<size_t>(row + 3 + i)] = e.weight * w[i];
        sys.clamped[static_cast<size_t>(row + 3 + i)] = e.weight * cw[i];
      }
    }
    if (e.weight != 1.0)  // (a product by 1 is exact: skipping it changes nothing)
      for (int r = row; r < row + (oriented ? 6 : 3); ++r)
        for (int col = 0; col < n; ++col) J(r, col) *= e.weight;
  }
  if (sys.dofWeights.size() != static_cast<size_t>(n)) {  // the weights are the skeleton's: set once
    sys.dofWeights.assign(static_cast<size_t>(n), 1.0);
    for (int i = 0; i < s.dofCount(); ++i) sys.dofWeights[static_cast<size_t>(i)] = s.dofWeight(i);
    sys.unitDofWeights = true;
    for (Real w : sys.dofWeights) sys.unitDofWeights = sys.unitDofWeights && w == 1.0;
  }
  if (!sys.unitDofWeights)
    for (int r = 0; r < m; ++r)
      for (int col = 0; col < n; ++col) J(r, col) *= sys.dofWeights[static_cast<size_t>(col)];
}

LeastSquaresSystem leastSquaresSystem(const Context& c) {
  LeastSquaresSystem sys;
  leastSquaresSystem(c, sys);
  return sys;
}

Real objective(const Context& c, const std::vector<Frame>& frames) {
  Real f = 0.0;
  for (const Effector& e : c.effectors) {
    const Vec3 d = e.targetPosition - effectorPosition(e, frames);
    f += e.weight * e.weight * glm::dot(d, d);
    if (e.kind == EffectorKind::PositionOrientation) {
      const Vec3 w = c.orientationScale * orientationError(e, frames);
      f += e.weight * e.weight * glm::dot(w, w);
    }
  }
  return 0.5 * f;
}

void projectOntoLimits(Context& c) {
  if (!c.options.enforceLimits) return;
  for (int j = 0; j < c.skeleton.jointCount(); ++j) clampJointToLimits(c.skeleton, c.pose, j);
}

Real trialObjective(Context& c, const Pose& start, const std::vector<Frame>& frames, const JacobianLayout& layout,
                    const std::vector<Real>& delta, TrialFrames& scratch) {
  assignPose(c.pose, start, !layout.freeJoints.empty());
  applyStep(c.skeleton, c.pose, frames, layout, delta);
  projectOntoLimits(c);
  c.evaluate(c.pose, scratch.local, scratch.half, scratch.frames);
  return objective(c, scratch.frames);
}

void acceptTrial(Context& c, TrialFrames& scratch) {
  std::swap(c.local, scratch.local);
  std::swap(c.half, scratch.half);
  std::swap(c.frames, scratch.frames);
}

void assignPose(Pose& to, const Pose& from, bool freeJoints) {
  to.dofs = from.dofs;
  if (freeJoints || to.rotations.size() != from.rotations.size()) to.rotations = from.rotations;
}

Real maxAbs(const std::vector<Real>& v) {
  Real largest = 0.0;
  for (Real x : v) largest = std::max(largest, std::abs(x));
  return largest;
}

void clampMaxAbs(std::vector<Real>& v, Real limit) {
  const Real largest = maxAbs(v);
  if (largest > limit)
    for (Real& x : v) x *= limit / largest;
}

}  // namespace pba::ik::detail
