#include "posing.h"

#include "physics/ik/analytic.h"
#include "physics/ik/skeleton.h"

namespace pba::labs::animation {

namespace an = pba::animation;

void aimBone(const an::Skeleton& s, an::Pose& pose, std::vector<an::JointWorld>& world, int joint, int child,
             const Vec3& target) {
  const an::JointWorld& j = world[static_cast<size_t>(joint)];
  const Vec3 now = world[static_cast<size_t>(child)].position - j.position;
  const Vec3 want = target - j.position;
  if (glm::length(now) < 1e-9 || glm::length(want) < 1e-9) return;
  const Quat turn = pba::ik::shortestArc(now, want);  // world-space rotation
  const int p = s.parents[static_cast<size_t>(joint)];
  const Quat parent = p < 0 ? Quat(1, 0, 0, 0) : world[static_cast<size_t>(p)].rotation;
  // R_j' = turn · R_j and R_j' = R_parent · q_j'  ⇒  q_j' = R_parent⁻¹ · turn · R_j.
  pose.rotations[static_cast<size_t>(joint)] = glm::normalize(glm::conjugate(parent) * turn * j.rotation);
  world = an::forwardKinematics(s, pose);
}

Limb findLimb(const an::Skeleton& s, const std::string& root, const std::string& mid, const std::string& end) {
  return {s.find(root), s.find(mid), s.find(end)};
}

bool reachWithLimb(const an::Skeleton& s, an::Pose& pose, std::vector<an::JointWorld>& world, const Limb& limb,
                   const Vec3& goal, const Vec3& pole) {
  if (!limb.valid() || world.size() != s.names.size()) return false;
  const Vec3 a = world[static_cast<size_t>(limb.root)].position;
  const Real upper = glm::length(world[static_cast<size_t>(limb.mid)].position - a);
  const Real lower =
      glm::length(world[static_cast<size_t>(limb.end)].position - world[static_cast<size_t>(limb.mid)].position);
  const pba::ik::TwoBonePose solved = pba::ik::twoBoneGeometry(a, upper, lower, goal, pole);
  aimBone(s, pose, world, limb.root, limb.mid, solved.elbow);
  aimBone(s, pose, world, limb.mid, limb.end, solved.wrist);
  return solved.reachable;
}

}  // namespace pba::labs::animation
