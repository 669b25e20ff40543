#include "physics/ik/effector.h"

#include <algorithm>

namespace pba::ik {

Vec3 orientationError(const Effector& e, const std::vector<Frame>& frames) {
  return rotationVector(e.targetOrientation * glm::inverse(effectorOrientation(e, frames)));
}

Residual residual(const std::vector<Effector>& effectors, const std::vector<Frame>& frames) {
  Residual r;
  for (const Effector& e : effectors) {
    r.position = std::max(r.position, glm::length(e.targetPosition - effectorPosition(e, frames)));
    if (e.kind == EffectorKind::PositionOrientation)
      r.orientation = std::max(r.orientation, glm::length(orientationError(e, frames)));
  }
  return r;
}

bool isAncestorOrSelf(const Skeleton& s, int ancestor, int joint) {
  for (int j = joint; j >= 0; j = s.joint(j).parent)
    if (j == ancestor) return true;
  return false;
}

std::vector<std::vector<int>> effectorsBelowJoints(const Skeleton& s, const std::vector<Effector>& effectors) {
  std::vector<std::vector<int>> below(static_cast<size_t>(s.jointCount()));
  for (size_t k = 0; k < effectors.size(); ++k)
    for (int j = effectors[k].joint; j >= 0; j = s.joint(j).parent)
      below[static_cast<size_t>(j)].push_back(static_cast<int>(k));
  return below;
}

Real reach(const Skeleton& s, int from, const Effector& e) {
  Real total = glm::length(e.localOffset);
  for (int j = e.joint; j >= 0 && j != from; j = s.joint(j).parent) {
    const Joint& joint = s.joint(j);
    total += glm::length(joint.offset);
    if (joint.type == JointType::Prismatic) total += std::max(std::abs(joint.lo[0]), std::abs(joint.hi[0]));
  }
  return total;
}

}  // namespace pba::ik
