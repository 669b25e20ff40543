#pragma once
// Posing the character by hand and by IK (the keyframes and reach-while-walking scenes): turn a joint
// so that its bone points at a target, and a two-bone limb (shoulder, elbow, wrist) solved by the IK
// library's law of cosines (ik::twoBoneGeometry) so that its end lands on a goal.
#include <string>

#include "physics/animation/skeleton.h"

namespace pba::labs::animation {

/// Rotates joint `joint` (changing pose.rotations[joint] only) so that the direction from it to its
/// child `child` points at `target`, by the shortest arc in world space; world is recomputed.
void aimBone(const pba::animation::Skeleton& s, pba::animation::Pose& pose,
             std::vector<pba::animation::JointWorld>& world, int joint, int child, const Vec3& target);

/// The joints of a two-bone limb, e.g. {"LeftArm", "LeftForeArm", "LeftHand"}.
struct Limb {
  int root = -1, mid = -1, end = -1;
  bool valid() const { return root >= 0 && mid >= 0 && end >= 0; }
};
Limb findLimb(const pba::animation::Skeleton& s, const std::string& root, const std::string& mid,
              const std::string& end);

/// Solves the limb so its end reaches `goal` (as near as it can), the middle joint bending toward
/// `pole`. Changes the rotations of limb.root and limb.mid; world is recomputed. True when reachable.
bool reachWithLimb(const pba::animation::Skeleton& s, pba::animation::Pose& pose,
                   std::vector<pba::animation::JointWorld>& world, const Limb& limb, const Vec3& goal,
                   const Vec3& pole);

}  // namespace pba::labs::animation
