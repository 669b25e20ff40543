#include "physics/ik/jacobian.h"

#include "physics/exercises/not_implemented.h"
#include "physics/ik/exercises.h"

namespace pba::ik {

// ***** IK-3: a Jacobian column of a rotational joint (Workbook §2.5; IK slides, "Columns") *****
// (1) The effector e moves on a circle about the joint's axis a (unit, world space) through the
//     pivot r: its velocity for a unit angular speed is the cross product of the axis with the lever.
// (2) The lever is e − r: the vector from the pivot to the CURRENT effector position (not the target:
//     the Workbook's formula has a typo there; the IK slides have it right).
// (3) Return a × (e − r). Its units are metres per radian.
// *****
Vec3 rotationalColumn([[maybe_unused]] const Vec3& worldAxis, [[maybe_unused]] const Vec3& pivot,
                      [[maybe_unused]] const Vec3& effector) {
  // BEGIN SOLUTION
  return glm::cross(worldAxis, effector - pivot);
  // END SOLUTION
  // STUB: return exercises::notImplemented("IK-3", Vec3(0.0));
}

Vec3 dofWorldAxis(const Joint& joint, const Pose& pose, const Frame& f, int k) {
  if (joint.type == JointType::Hinge || joint.type == JointType::Prismatic) return f.pre * joint.axis;
  if (joint.type != JointType::Ball) return Vec3(0.0);
  const Real* d = pose.dofs.data() + joint.firstDof;
  Quat q = f.pre;
  if (k >= 1) q = q * glm::angleAxis(d[0], Vec3(1, 0, 0));
  if (k >= 2) q = q * glm::angleAxis(d[1], Vec3(0, 1, 0));
  Vec3 unit(0.0);
  unit[k] = 1.0;
  return q * unit;
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
// Writes the column of a rotation about world axis a at pivot r (rotational = true) or a translation
// along a, for every effector below `joint`.
void fillColumn(Matrix& J, int col, const std::vector<int>& below, const Vec3& a, const Vec3& r, bool rotational,
                const std::vector<Effector>& effectors, const std::vector<Frame>& frames, const JacobianLayout& L,
                Real scale) {
  for (int k : below) {
    const Effector& e = effectors[static_cast<size_t>(k)];
    const int row = L.rowOfEffector[static_cast<size_t>(k)];
    const Vec3 v = rotational ? rotationalColumn(a, r, effectorPosition(e, frames)) : a;
    for (int i = 0; i < 3; ++i) J(row + i, col) = v[i];
    if (e.kind == EffectorKind::PositionOrientation && rotational)
      for (int i = 0; i < 3; ++i) J(row + 3 + i, col) = scale * a[i];
  }
}
}  // namespace

Matrix jacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
                const std::vector<Frame>& frames, const JacobianLayout& L, Real scale) {
  Matrix J(L.rows, L.cols);
  const std::vector<std::vector<int>> below = effectorsBelowJoints(s, effectors);
  for (int i = 0; i < s.dofCount(); ++i) {
    const int j = s.dofJoint(i);
    const Joint& joint = s.joint(j);
    const Frame& f = frames[static_cast<size_t>(j)];
    fillColumn(J, i, below[static_cast<size_t>(j)], dofWorldAxis(joint, pose, f, i - joint.firstDof), f.position,
               joint.type != JointType::Prismatic, effectors, frames, L, scale);
  }
  for (size_t k = 0; k < L.freeJoints.size(); ++k) {
    const int j = L.freeJoints[k];
    fillColumn(J, s.dofCount() + static_cast<int>(k), below[static_cast<size_t>(j)], L.freeAxes[k],
               frames[static_cast<size_t>(j)].position, true, effectors, frames, L, scale);
  }
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
