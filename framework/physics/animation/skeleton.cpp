#include "physics/animation/skeleton.h"

#include <cmath>

#include "physics/exercises/not_implemented.h"

namespace pba::animation {

int Skeleton::find(const std::string& name) const {
  for (int i = 0; i < size(); ++i)
    if (names[static_cast<size_t>(i)] == name) return i;
  return -1;
}

int Skeleton::add(const std::string& name, int parent, const Vec3& translation, const Quat& rotation) {
  names.push_back(name);
  parents.push_back(parent);
  restTranslations.push_back(translation);
  restRotations.push_back(rotation);
  return size() - 1;
}

Status validate(const Skeleton& s) {
  const size_t n = s.names.size();
  if (n == 0) return Error{"skeleton: has no joints"};
  if (s.parents.size() != n || s.restTranslations.size() != n || s.restRotations.size() != n)
    return Error{"skeleton: names, parents, rest translations and rest rotations differ in size"};
  for (size_t i = 0; i < n; ++i) {
    const std::string field = std::string("skeleton.joints[") + std::to_string(i) + "] (" + s.names[i] + ")";
    const int p = s.parents[i];
    if ((i == 0) != (p < 0) || p >= static_cast<int>(i))
      return Error{field + ": parent must precede the joint (only joint 0 is the root)"};
    if (!isFinite(s.restTranslations[i])) return Error{field + ": rest translation is not finite"};
    const Quat& q = s.restRotations[i];
    if (!std::isfinite(q.w) || !isFinite(Vec3(q.x, q.y, q.z)) || std::abs(glm::length(q) - 1.0) > 1e-6)
      return Error{field + ": rest rotation is not a unit quaternion"};
  }
  return Status::success();
}

Pose restPose(const Skeleton& s) { return Pose{s.restTranslations, s.restRotations}; }

// ***** ANIM-3: forward kinematics of the joint tree (CMU asst4, "Character") *****
// Inputs: the skeleton (parents come before children; each joint's offset [m] lives in its PARENT's
// frame) and the pose (local translations [m] and rotations). Output: every joint's world position [m]
// and world rotation.
// (1) One pass in index order is enough: every parent's world frame is known before its children's (the
//     recursive traversal of asst4, unrolled).
// (2) The root's world frame is its local one.
// (3) For any other joint: its offset is expressed in the parent's frame, so which rotation turns it
//     into world axes (the parent's local one, or everything above it)? In which order do the parent's
//     world rotation and the joint's local rotation compose?
// (4) Keep the quaternions unit length: a long chain of products drifts otherwise.
// Check: a planar two-link arm matches its closed form; translating the root moves every joint rigidly;
// each joint seen from its parent's world frame has its local offset and rotation.
// *****
std::vector<JointWorld> forwardKinematics(const Skeleton& skeleton, const Pose& pose) {
  // BEGIN SOLUTION
  const size_t n = skeleton.names.size();
  std::vector<JointWorld> world(n);
  for (size_t i = 0; i < n; ++i) {
    const int p = skeleton.parents[i];
    if (p < 0) {
      world[i] = {pose.translations[i], glm::normalize(pose.rotations[i])};
      continue;
    }
    const JointWorld& parent = world[static_cast<size_t>(p)];
    world[i].position = parent.position + parent.rotation * pose.translations[i];
    world[i].rotation = glm::normalize(parent.rotation * pose.rotations[i]);
  }
  return world;
  // END SOLUTION
  // STUB: return exercises::notImplemented("ANIM-3", std::vector<JointWorld>(skeleton.names.size()), pose);
}

}  // namespace pba::animation

namespace {
pba::animation::Skeleton probeSkeleton() {
  pba::animation::Skeleton s;
  s.add("root", -1, pba::Vec3(0.0));
  return s;
}
}  // namespace
PBA_EXERCISE_PROBE(pba::animation::forwardKinematics(probeSkeleton(), pba::animation::restPose(probeSkeleton())));
