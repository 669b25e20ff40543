#pragma once
// The character of the animation lab (CMU asst4, "Character"): a tree of joints, each with a local
// translation (its pivot in the parent's frame) and a local rotation, posed by forward kinematics.
//
//   R_i = R_parent(i) · q_i,   p_i = p_parent(i) + R_parent(i) · c_i
// with c_i the local translation [m] and q_i the local rotation (unit quaternion). This is asst4's
// pᵢ = pⱼ + R(Θⱼ)(cᵢ − cⱼ) in 3-D: the cumulative angle Θ becomes the product of the ancestors'
// quaternions, and cᵢ − cⱼ, the offset of the child's centre from the parent's, is c_i. The root's
// parent frame is the world. A pose stores every joint's (c_i, q_i), so a clip may move any joint (BVH
// moves the root; some files translate other joints too).
#include <string>
#include <vector>

#include "physics/core/result.h"
#include "physics/core/types.h"

namespace pba::animation {

struct Skeleton {
  std::vector<std::string> names;
  std::vector<int> parents;            ///< −1 for the root; parents[i] < i
  std::vector<Vec3> restTranslations;  ///< [m] c_i of the rest pose, in the parent's frame
  std::vector<Quat> restRotations;     ///< q_i of the rest pose

  int size() const { return static_cast<int>(names.size()); }
  int find(const std::string& name) const;  ///< −1 when absent
  /// Appends a joint; returns its index.
  int add(const std::string& name, int parent, const Vec3& translation, const Quat& rotation = Quat(1, 0, 0, 0));
};

/// Checks sizes, parents before children, finite unit rotations; the message names the field.
Status validate(const Skeleton& skeleton);

/// Local transforms of every joint.
struct Pose {
  std::vector<Vec3> translations;  ///< [m] c_i
  std::vector<Quat> rotations;     ///< q_i, unit
};

/// World pivot and orientation of one joint.
struct JointWorld {
  Vec3 position{0.0};                 ///< [m] p_i
  Quat rotation{1.0, 0.0, 0.0, 0.0};  ///< R_i
};

Pose restPose(const Skeleton& skeleton);

/// World frames of every joint, parents first. Exercise ANIM-3.
std::vector<JointWorld> forwardKinematics(const Skeleton& skeleton, const Pose& pose);

/// World position of a point given in joint j's frame.
inline Vec3 toWorld(const JointWorld& joint, const Vec3& local) { return joint.position + joint.rotation * local; }

}  // namespace pba::animation
