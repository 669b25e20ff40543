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
// (1) One world frame per joint; parents come before children in the skeleton, so a single pass in
//     index order sees every parent's frame before its children (the recursive traversal of asst4,
//     unrolled).
// (2) The root (parent −1) takes its local translation and rotation as its world frame.
// (3) Any other joint i with parent j: p_i = p_j + R_j c_i, R_i = R_j q_i (rotate the child's offset
//     by the parent's WORLD rotation, then compose the rotations in that order).
// (4) Keep the quaternions unit length: a long chain of products drifts otherwise.
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
