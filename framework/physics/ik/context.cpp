// The solve context of the IK driver (solver_internal.h): the pose's local rotations and world frames
// kept in step with it (forward kinematics, flushing one joint or the whole pose back to Euler angles),
// the evaluation of trial poses, and the stretch toward a goal that starts a solve from the straight
// pose.
#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/ik/exercises.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik {

namespace detail {

namespace {
// jointRotation(), also keeping a ball joint's half angles (the Jacobian reuses them).
Quat localRotation(const Joint& joint, const Pose& p, int j, EulerHalfAngles* half) {
  if (joint.type != JointType::Ball) return jointRotation(joint, p, j);
  const Real* d = p.dofs.data() + joint.firstDof;
  return quatFromEulerXYZ(Vec3(d[0], d[1], d[2]), half);
}
}  // namespace

void ContextStorage::clear() {
  // frames, local and half keep their entries: refresh() rewrites every one of them first, and
  // resizing from empty would initialise them only to be overwritten.
  belowStart.clear();
  belowList.clear();
  active.clear();
  insideCosHalf.clear();
  eulerRanges.clear();
  staleEuler.clear();
  links.clear();
}

void Context::flushPose() {
  for (size_t j = 0; j < staleEuler.size(); ++j)
    if (staleEuler[j]) flushJoint(static_cast<int>(j));
}

void Context::flushJoint(int j) {
  const Joint& joint = skeleton.joint(j);
  const Quat& q = local[static_cast<size_t>(j)];
  Real* dofs = pose.dofs.data() + joint.firstDof;
  if (joint.type == JointType::Hinge) {
    // q = (cos ½θ, sin ½θ a) with q.w > 0 (FABRIK's hinge update keeps θ inside (−π, π)).
    dofs[0] = 2.0 * std::atan2(glm::dot(Vec3(q.x, q.y, q.z), joint.axis), q.w);
  } else {
    const Vec3 e = eulerXYZFromQuat(q);
    for (int k = 0; k < 3; ++k) dofs[k] = e[k];
  }
  staleEuler[static_cast<size_t>(j)] = 0;
}

bool Context::principalEulerInside(int j, const Quat& q) const {
  const std::array<EulerRange, 3>& ranges = eulerRanges[static_cast<size_t>(j)];
  if (ranges[0].cosHalf > 1.0 || ranges[1].cosHalf > 1.0 || ranges[2].cosHalf > 1.0) return false;
  // The entries eulerXYZFromQuat reads: a = atan2(−R12, R22), b = atan2(R02, hypot(R00, R01)),
  // c = atan2(−R01, R00).
  const Mat3 m = glm::mat3_cast(q);
  const Real r02 = std::clamp(m[2][0], -1.0, 1.0), r12 = m[2][1], r22 = m[2][2], r00 = m[0][0], r01 = m[1][0];
  const Real cosB = std::sqrt(r00 * r00 + r01 * r01);
  const Real s[3] = {-r12, r02, -r01}, cs[3] = {r22, cosB, r00};
  for (size_t k = 0; k < 3; ++k) {
    const EulerRange& r = ranges[k];
    if (r.cosHalf < -1.0) continue;
    if (!(cs[k] * r.cosMid + s[k] * r.sinMid >= r.cosHalf * std::sqrt(s[k] * s[k] + cs[k] * cs[k]) + 1e-9))
      return false;
  }
  return true;
}

void Context::refresh() {
  if (links.size() != static_cast<size_t>(skeleton.jointCount())) {
    // Field by field into place: a Link built aside and copied would be read back in 16-byte pieces
    // just after being stored in smaller ones (a store-forwarding stall per joint).
    links.resize(skeleton.joints().size());
    for (size_t j = 0; j < links.size(); ++j) {
      const Joint& joint = skeleton.joints()[j];
      const Quat& r = joint.restRotation;
      Link& link = links[j];
      link.parent = joint.parent;
      link.identityRest = r.w == 1.0 && r.x == 0.0 && r.y == 0.0 && r.z == 0.0;
      link.prismatic = joint.type == JointType::Prismatic;
      link.offset = joint.offset;
      link.rest = r;
    }
  }
  flushPose();
  staleEuler.assign(static_cast<size_t>(skeleton.jointCount()), 0);
  local.resize(static_cast<size_t>(skeleton.jointCount()));
  half.resize(static_cast<size_t>(skeleton.jointCount()));
  for (int j = 0; j < skeleton.jointCount(); ++j)
    local[static_cast<size_t>(j)] = localRotation(skeleton.joint(j), pose, j, &half[static_cast<size_t>(j)]);
  refreshFrames();
}

void Context::evaluate(const Pose& p, std::vector<Quat>& localOut, std::vector<EulerHalfAngles>& halfOut,
                       std::vector<Frame>& framesOut) const {
  const int n = skeleton.jointCount();
  localOut.resize(static_cast<size_t>(n));
  halfOut.resize(static_cast<size_t>(n));
  framesOut.resize(static_cast<size_t>(n));
  for (int j = 0; j < n; ++j) {
    const auto k = static_cast<size_t>(j);
    localOut[k] = localRotation(skeleton.joint(j), p, j, &halfOut[k]);
    const int parent = links[k].parent;
    framesOut[k] = linkFrame(j, parent < 0 ? nullptr : &framesOut[static_cast<size_t>(parent)], p, localOut[k]);
  }
}

void Context::refreshFrames() {
  const int n = skeleton.jointCount();
  frames.resize(static_cast<size_t>(n));
  for (int j = 0; j < n; ++j) {
    const int parent = links[static_cast<size_t>(j)].parent;
    frames[static_cast<size_t>(j)] = frameFrom(j, parent < 0 ? nullptr : &frames[static_cast<size_t>(parent)]);
  }
}

Frame Context::frameFromParent(int j) const {
  const int parent = links[static_cast<size_t>(j)].parent;
  return frameFrom(j, parent >= 0 ? &frames[static_cast<size_t>(parent)] : nullptr);
}

void stretchToward(Context& c, const Effector& e) {
  // Root → tip along the path to the effector: each joint turns so that the next point of the path
  // (child joint or the effector) lies on the ray from the path's first joint toward the goal.
  std::vector<int> path;
  for (int j = e.joint; j >= 0; j = c.skeleton.joint(j).parent) path.insert(path.begin(), j);
  const Vec3 base = c.frames[static_cast<size_t>(path.front())].position;
  const Vec3 toGoal = e.targetPosition - base;
  const Real distance = glm::length(toGoal);
  if (distance < 1e-12) return;
  const Vec3 dir = toGoal / distance;
  for (size_t i = 0; i < path.size(); ++i) {
    const int j = path[i];
    if (c.skeleton.joint(j).type == JointType::Fixed) continue;
    const Frame& f = c.frames[static_cast<size_t>(j)];
    const Vec3 next =
        i + 1 < path.size() ? c.frames[static_cast<size_t>(path[i + 1])].position : effectorPosition(e, c.frames);
    const Real along = glm::dot(f.position - base, dir);
    const Real lever = glm::length(next - f.position);
    if (lever < 1e-12) continue;
    // The child should sit `lever` further along the ray than this joint's projection onto it.
    const Vec3 goal = base + dir * (along + lever);
    alignJoint(c, j, f, {next}, {goal}, {1.0}, c.options.enforceLimits, false, nullptr);
    c.refreshFrames();
  }
}

}  // namespace detail

}  // namespace pba::ik
