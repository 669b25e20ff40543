#pragma once
// End effectors and their goals (IK slides, "Multiple end effectors" and "6-DOF end effector").
// An effector is a point fixed in a joint's frame; its goal is a world position (3 DOF) or a world
// position and orientation (6 DOF). Any number of effectors may sit anywhere on the tree.
//
// Orientation error (IK slides): the quaternion that rotates the effector frame E into the goal G is
// q = G · E⁻¹ (world); its scaled axis (axis · angle) is the 3-vector of orientation error [rad].
#include <vector>

#include "physics/ik/skeleton.h"

namespace pba::ik {

enum class EffectorKind { Position, PositionOrientation };

struct Effector {
  int joint = 0;          ///< the joint the effector point is fixed to
  Vec3 localOffset{0.0};  ///< [m] in that joint's frame, e.g. (bone length, 0, 0) for a tip
  EffectorKind kind = EffectorKind::Position;
  Vec3 targetPosition{0.0};            ///< [m] world goal g
  Quat targetOrientation{1, 0, 0, 0};  ///< world goal frame G (PositionOrientation only)
  Real weight = 1.0;                   ///< [1] > 0: relative importance among effectors
};

/// World position of the effector point: p_j + R_j · offset.
inline Vec3 effectorPosition(const Effector& e, const std::vector<Frame>& frames) {
  const Frame& f = frames[static_cast<size_t>(e.joint)];
  return f.position + f.rotation * e.localOffset;
}
inline Quat effectorOrientation(const Effector& e, const std::vector<Frame>& frames) {
  return frames[static_cast<size_t>(e.joint)].rotation;
}
/// Scaled axis of G · E⁻¹ [rad].
Vec3 orientationError(const Effector& e, const std::vector<Frame>& frames);

/// Largest position error over the effectors [m] and largest orientation error over the 6-DOF ones [rad].
struct Residual {
  Real position = 0.0;     ///< [m]
  Real orientation = 0.0;  ///< [rad]
};
Residual residual(const std::vector<Effector>& effectors, const std::vector<Frame>& frames);

/// True when joint `ancestor` is `joint` or lies on its path to the root.
bool isAncestorOrSelf(const Skeleton& s, int ancestor, int joint);
/// Per joint: indices of the effectors whose joint is that joint or lies below it. O(m · depth).
std::vector<std::vector<int>> effectorsBelowJoints(const Skeleton& s, const std::vector<Effector>& effectors);
/// Maximum distance from joint `from` (an ancestor) to the effector point over all poses, ignoring
/// limits: the sum of the bone lengths on the path [m] (prismatic DOFs add their upper limit).
Real reach(const Skeleton& s, int from, const Effector& e);

}  // namespace pba::ik
