#include "physics/ik/jacobian.h"

#include "physics/exercises/not_implemented.h"
#include "physics/ik/exercises.h"

namespace pba::ik {

// ***** IK-3: one joint's columns of the Jacobian (Workbook §2.5; IK slides, "Columns" and "3-DOF
// joints") *****
// Inputs: the joint (its type, and for a hinge or prismatic joint its unit axis in the frame R_pre), the
// pose (a ball joint's three XYZ Euler angles start at pose.dofs[joint.firstDof]), the joint's frame from
// forward kinematics (pivot [m] and R_pre, both world) and the effector's position e [m], world.
// Output, for each of the joint's scalar DOFs k (hinge, prismatic: 1; ball: 3; others: none): its axis
// in world axes (unit) and its column ∂e/∂θ_k, the velocity of e [m/s] when that DOF alone changes at
// one unit per second (1 rad/s, or 1 m/s for a prismatic joint), every other DOF held. jacobian() walks
// each effector's chain to the root and writes these columns (and, for a 6-DOF effector, the axes).
// (1) World axes. A hinge's or a prismatic joint's axis is given in the frame R_pre: bring it to world
//     axes. A ball joint turns by R_pre Rx(θ₀) Ry(θ₁) Rz(θ₂): each angle turns about its own axis AFTER
//     the rotations to its left have been applied; work out which partial product carries x̂, ŷ and ẑ.
// (2) Rotational columns: the effector turns on a circle about the axis through the pivot. Describe it
//     from the pivot where it is NOW (not where it should go; the Workbook's formula has a typo there),
//     then work out its velocity's direction (right-hand rule) and size (radius times angular speed).
// (3) A prismatic DOF slides the whole subtree: how fast does e move, and in which direction?
// Check: a rotational column is perpendicular to its axis and zero when e lies on the axis; a ball
// joint's first axis does not depend on its angles; the columns match central finite differences of
// forward kinematics (numericalJacobian below) for every DOF type.
// *****
JointColumns jointJacobianColumns(const Joint& joint, const Pose& pose, const Frame& frame, const Vec3& effector) {
  // BEGIN SOLUTION
  JointColumns out;
  const Vec3 lever = effector - frame.position;
  if (joint.type == JointType::Hinge || joint.type == JointType::Prismatic) {
    out.axis[0] = frame.pre * joint.axis;
    out.column[0] = joint.type == JointType::Hinge ? glm::cross(out.axis[0], lever) : out.axis[0];
    return out;
  }
  if (joint.type != JointType::Ball) return out;
  const Real* d = pose.dofs.data() + joint.firstDof;
  const Quat qx = frame.pre * glm::angleAxis(d[0], Vec3(1, 0, 0));
  const Quat qxy = qx * glm::angleAxis(d[1], Vec3(0, 1, 0));
  out.axis[0] = frame.pre * Vec3(1, 0, 0);
  out.axis[1] = qx * Vec3(0, 1, 0);
  out.axis[2] = qxy * Vec3(0, 0, 1);
  for (int k = 0; k < 3; ++k) out.column[k] = glm::cross(out.axis[k], lever);
  return out;
  // END SOLUTION
  // STUB: return exercises::notImplemented("IK-3", JointColumns{}, joint, pose, frame, effector);
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
// Writes effector k's rows of column `col` from a DOF's world axis and its position column; a
// rotational DOF also fills the orientation rows of a 6-DOF effector.
void writeColumn(Matrix& J, int col, int row, bool oriented, bool rotational, const Vec3& axis, const Vec3& column,
                 Real scale) {
  for (int i = 0; i < 3; ++i) J(row + i, col) = column[i];
  if (oriented && rotational)
    for (int i = 0; i < 3; ++i) J(row + 3 + i, col) = scale * axis[i];
}
}  // namespace

void jacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
              const std::vector<Frame>& frames, const JacobianLayout& L, Real scale, Matrix& J) {
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
      const JointColumns c = jointJacobianColumns(joint, pose, frames[static_cast<size_t>(j)], p);  // IK-3
      for (int d = 0; d < dofCount(joint.type); ++d)
        writeColumn(J, joint.firstDof + d, row, oriented, joint.type != JointType::Prismatic, c.axis[d], c.column[d],
                    scale);
    }
    // A free joint's column turns about its chosen world axis through its pivot: the column of a hinge
    // with that axis and no pre-rotation.
    for (size_t q = 0; q < L.freeJoints.size(); ++q) {
      const int j = L.freeJoints[q];
      if (!isAncestorOrSelf(s, j, e.joint)) continue;
      Joint hinge;
      hinge.type = JointType::Hinge;
      hinge.axis = L.freeAxes[q];
      const Frame pivot{frames[static_cast<size_t>(j)].position, Quat(1, 0, 0, 0), Quat(1, 0, 0, 0)};
      const JointColumns c = jointJacobianColumns(hinge, pose, pivot, p);  // IK-3
      writeColumn(J, s.dofCount() + static_cast<int>(q), row, oriented, true, c.axis[0], c.column[0], scale);
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
PBA_EXERCISE_PROBE(jointJacobianColumns(Joint{}, Pose{}, Frame{}, Vec3(1.0, 0.0, 0.0)));

}  // namespace pba::ik
