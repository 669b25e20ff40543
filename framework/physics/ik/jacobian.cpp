#include "physics/ik/jacobian.h"

#include "physics/exercises/not_implemented.h"
#include "physics/ik/exercises.h"

namespace pba::ik {

// ***** IK-3: a Jacobian column of a rotational joint (Workbook §2.5; IK slides, "Columns") *****
// Inputs in world axes: the joint's unit axis, its pivot (a point of the axis) [m], the effector's
// position [m]. The column is the velocity of the effector [m/s] when this joint alone turns at
// 1 rad/s, all others held: metres per radian.
// (1) Which point is moving: the effector where it is NOW, not where it should go (the Workbook's
//     formula has a typo there; the IK slides have it right). Describe it from the pivot.
// (2) A point turning about an axis moves on a circle about that axis: work out its velocity's direction
//     (tangent to the circle, by the right-hand rule about the axis) and its size (the radius of the
//     circle times the angular speed).
// Check: the column is perpendicular to the axis and to the lever; it is zero when the effector lies on
// the axis; doubling the distance from the axis doubles it; it matches a finite difference of the
// effector's position over a small turn (numericalJacobian in jacobian.h).
// *****
Vec3 rotationalColumn([[maybe_unused]] const Vec3& worldAxis, [[maybe_unused]] const Vec3& pivot,
                      [[maybe_unused]] const Vec3& effector) {
  // BEGIN SOLUTION
  return glm::cross(worldAxis, effector - pivot);
  // END SOLUTION
  // STUB: return exercises::notImplemented("IK-3", Vec3(0.0));
}

namespace {
// The world axes of joint j's scalar DOFs from its frame; returns how many (0–3).
//   hinge, prismatic: R_pre a.
//   ball, R = R_pre Rx(θ₀) Ry(θ₁) Rz(θ₂): x: R_pre x̂; y: (R_pre Rx) ŷ; z: (R_pre Rx Ry) ẑ. The partial
//   products are shared between the three axes (two half-angle sincos and two quaternion products
//   per joint, not three of each).
int dofWorldAxes(const Joint& joint, const Pose& pose, const Frame& f, Vec3 axes[3],
                 const EulerHalfAngles* half = nullptr) {
  if (joint.type == JointType::Hinge || joint.type == JointType::Prismatic) {
    axes[0] = f.pre * joint.axis;
    return 1;
  }
  if (joint.type != JointType::Ball) return 0;
  const Real* d = pose.dofs.data() + joint.firstDof;
  // Rx(θ₀) = (cos ½θ₀, sin ½θ₀ x̂), Ry(θ₁) = (cos ½θ₁, sin ½θ₁ ŷ): from forward kinematics when it has them.
  const bool cached = half && half->angle0 == d[0] && half->angle1 == d[1];
  const Quat rx = cached ? Quat(half->c0, half->s0, 0.0, 0.0) : glm::angleAxis(d[0], Vec3(1, 0, 0));
  const Quat ry = cached ? Quat(half->c1, 0.0, half->s1, 0.0) : glm::angleAxis(d[1], Vec3(0, 1, 0));
  const Quat qx = f.pre * rx;
  const Quat qxy = qx * ry;
  axes[0] = f.pre * Vec3(1, 0, 0);
  axes[1] = qx * Vec3(0, 1, 0);
  axes[2] = qxy * Vec3(0, 0, 1);
  return 3;
}
}  // namespace

Vec3 dofWorldAxis(const Joint& joint, const Pose& pose, const Frame& f, int k) {
  Vec3 axes[3];
  return k < dofWorldAxes(joint, pose, f, axes) ? axes[k] : Vec3(0.0);
}

JacobianLayout planJacobian(const Skeleton& s, const Pose&, const std::vector<Effector>& effectors,
                            const std::vector<Frame>& frames, Real orientationScale) {
  JacobianLayout L;
  for (const Effector& e : effectors) {
    L.rowOfEffector.push_back(L.rows);
    L.rows += e.kind == EffectorKind::PositionOrientation ? 6 : 3;
  }
  for (int j = 0; j < s.jointCount(); ++j) {
    if (s.joint(j).type != JointType::Free) continue;
    Vec3 axis(0.0);
    const Vec3 r = frames[static_cast<size_t>(j)].position;
    for (const Effector& e : effectors) {
      if (!isAncestorOrSelf(s, j, e.joint)) continue;
      const Vec3 p = effectorPosition(e, frames);
      axis += e.weight * glm::cross(p - r, e.targetPosition - p);
      if (e.kind == EffectorKind::PositionOrientation)
        axis += e.weight * orientationScale * orientationScale * orientationError(e, frames);
    }
    const Real length = glm::length(axis);
    L.freeJoints.push_back(j);
    L.freeAxes.push_back(length > 1e-15 ? axis / length : Vec3(0.0));
  }
  L.cols = s.dofCount() + static_cast<int>(L.freeJoints.size());
  return L;
}

namespace {
// Writes effector k's rows of column `col`: a rotation about world axis a at pivot r (rotational) or a
// translation along a, for the effector point p.
void writeColumn(Matrix& J, int col, int row, bool oriented, const Vec3& a, const Vec3& r, bool rotational,
                 const Vec3& p, Real scale) {
  const Vec3 v = rotational ? rotationalColumn(a, r, p) : a;
  for (int i = 0; i < 3; ++i) J(row + i, col) = v[i];
  if (oriented && rotational)
    for (int i = 0; i < 3; ++i) J(row + 3 + i, col) = scale * a[i];
}
}  // namespace

void jacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
              const std::vector<Frame>& frames, const JacobianLayout& L, Real scale, Matrix& J,
              const EulerHalfAngles* half) {
  J.rows = L.rows;
  J.cols = L.cols;
  // Entries on no effector's path stay 0. One position effector whose path holds every DOF (a chain)
  // writes every entry below: then J need not be cleared first.
  int pathDofs = -1;
  if (effectors.size() == 1 && effectors[0].kind == EffectorKind::Position && L.freeJoints.empty()) {
    pathDofs = 0;
    for (int j = effectors[0].joint; j >= 0; j = s.joint(j).parent) pathDofs += dofCount(s.joint(j).type);
  }
  if (pathDofs == L.cols)
    J.data.resize(static_cast<size_t>(L.rows) * static_cast<size_t>(L.cols));
  else
    J.data.assign(static_cast<size_t>(L.rows) * static_cast<size_t>(L.cols), 0.0);
  // Effector by effector, up its path to the root: the joints that move it (O(m · depth), no lists).
  for (size_t k = 0; k < effectors.size(); ++k) {
    const Effector& e = effectors[k];
    const int row = L.rowOfEffector[k];
    const bool oriented = e.kind == EffectorKind::PositionOrientation;
    const Vec3 p = effectorPosition(e, frames);
    for (int j = e.joint; j >= 0; j = s.joint(j).parent) {
      const Joint& joint = s.joint(j);
      const Frame& f = frames[static_cast<size_t>(j)];
      Vec3 axes[3];
      const int count = dofWorldAxes(joint, pose, f, axes, half ? half + j : nullptr);
      for (int d = 0; d < count; ++d)
        writeColumn(J, joint.firstDof + d, row, oriented, axes[d], f.position, joint.type != JointType::Prismatic, p,
                    scale);
    }
    for (size_t q = 0; q < L.freeJoints.size(); ++q) {
      const int j = L.freeJoints[q];
      if (isAncestorOrSelf(s, j, e.joint))
        writeColumn(J, s.dofCount() + static_cast<int>(q), row, oriented, L.freeAxes[q],
                    frames[static_cast<size_t>(j)].position, true, p, scale);
    }
  }
}

Matrix jacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
                const std::vector<Frame>& frames, const JacobianLayout& L, Real scale) {
  Matrix J;
  jacobian(s, pose, effectors, frames, L, scale, J);
  return J;
}

void applyStep(const Skeleton& s, Pose& pose, const std::vector<Frame>& frames, const JacobianLayout& L,
               const std::vector<Real>& delta) {
  for (int i = 0; i < s.dofCount(); ++i) pose.dofs[static_cast<size_t>(i)] += delta[static_cast<size_t>(i)];
  for (size_t k = 0; k < L.freeJoints.size(); ++k) {
    const int j = L.freeJoints[k];
    const Real angle = delta[static_cast<size_t>(s.dofCount()) + k];
    if (angle == 0.0 || glm::length(L.freeAxes[k]) == 0.0) continue;
    // World rotation about a: q_local ← (R_pre⁻¹ R(a, Δ) R_pre) q_local.
    const Quat& pre = frames[static_cast<size_t>(j)].pre;
    Quat& q = pose.rotations[static_cast<size_t>(j)];
    q = glm::normalize(glm::angleAxis(angle, glm::inverse(pre) * L.freeAxes[k]) * q);
  }
}

Matrix numericalJacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
                         const JacobianLayout& L, Real scale, Real h) {
  Matrix J(L.rows, L.cols);
  const std::vector<Frame> frames0 = forwardKinematics(s, pose);
  for (int col = 0; col < L.cols; ++col) {
    std::vector<Real> step(static_cast<size_t>(L.cols), 0.0);
    step[static_cast<size_t>(col)] = h;
    Pose plus = pose, minus = pose;
    applyStep(s, plus, frames0, L, step);
    step[static_cast<size_t>(col)] = -h;
    applyStep(s, minus, frames0, L, step);
    const std::vector<Frame> fp = forwardKinematics(s, plus), fm = forwardKinematics(s, minus);
    for (size_t k = 0; k < effectors.size(); ++k) {
      const Effector& e = effectors[k];
      const int row = L.rowOfEffector[k];
      const Vec3 dp = (effectorPosition(e, fp) - effectorPosition(e, fm)) / (2.0 * h);
      for (int i = 0; i < 3; ++i) J(row + i, col) = dp[i];
      if (e.kind == EffectorKind::PositionOrientation) {
        const Vec3 w =
            rotationVector(effectorOrientation(e, fp) * glm::inverse(effectorOrientation(e, fm))) / (2.0 * h);
        for (int i = 0; i < 3; ++i) J(row + 3 + i, col) = scale * w[i];
      }
    }
  }
  return J;
}

// Start-up probe: tells the lab whether IK-3 is still a stub.
PBA_EXERCISE_PROBE(rotationalColumn(Vec3(0.0, 0.0, 1.0), Vec3(0.0), Vec3(1.0, 0.0, 0.0)));

}  // namespace pba::ik
