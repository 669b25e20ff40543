#pragma once
// One description of a ragdoll that builds either kind (docs/architecture.md §2: a description apart from
// the runtime object): the particle ragdoll of the Ragdoll paper §3 (after Jakobsen 2001) and the
// constraint ragdoll of §4 on the rigid module. Bones are boxes; joints are balls (with an optional
// cone limit) or hinges (with optional limits). Everything is given in world coordinates at the start
// pose, which is also the rest pose of every joint (hinge angle 0, cone axis along the bone).
#include <string>
#include <vector>

#include "physics/core/result.h"
#include "physics/core/types.h"

namespace pba::ragdoll {

struct BoneDesc {
  std::string name;              ///< "thigh.l"; for messages and the panel
  Vec3 center{0.0};              ///< [m] world, centre of the box at the start; e.g. (0, 1, 0)
  Vec3 halfExtents{0.1};         ///< [m] half sizes along the box's axes; e.g. (0.1, 0.25, 0.1)
  Quat orientation{1, 0, 0, 0};  ///< box → world
  Real mass = 1.0;               ///< [kg]; ignored for fixed bones
  bool fixed = false;            ///< never moves (a chain's top box)
  Vec3 velocity{0.0};            ///< [m/s] of the centre at the start
  Vec3 angularVelocity{0.0};     ///< [rad/s] world, at the start
};

enum class JointKind { Ball, Hinge };
const char* jointKindName(JointKind kind);

struct JointDesc {
  JointKind kind = JointKind::Ball;
  int boneA = 0;  ///< the parent (limits are measured in its frame)
  int boneB = 1;
  Vec3 anchor{0.0};  ///< [m] world, the joint centre at the start
  /// Hinge: the axis (unit, world); the angle of B about it is positive by the right-hand rule.
  /// Ball: the cone's axis (unit, world), usually from the joint along bone B.
  Vec3 axis{1.0, 0.0, 0.0};
  bool limited = false;
  Real lower = 0.0, upper = 0.0;  ///< [rad] hinge limits, lower ≤ 0 ≤ upper (the start is angle 0)
  Real coneAngle = 0.0;           ///< [rad] ball limit: largest angle of B's axis from the cone axis, in [0, π)
};

struct RagdollDesc {
  std::vector<BoneDesc> bones;
  std::vector<JointDesc> joints;
  Real friction = 0.5;  ///< Coulomb μ of the constraint ragdoll; the particle one uses its own fraction
};

/// Errors name `field` and the bone or joint: non-positive mass or size, non-finite values, a joint
/// between unknown or equal bones, a zero axis, lower > 0 or upper < 0, a cone angle outside [0, π).
Status validate(const RagdollDesc& desc, const std::string& field = "ragdoll");

/// The same ragdoll moved by `offset` [m] (the lab puts the two methods side by side).
RagdollDesc translated(RagdollDesc desc, const Vec3& offset);
/// Appends `other` (its joints renumbered): several ragdolls in one description.
void append(RagdollDesc& desc, const RagdollDesc& other);
/// Total mass of the moving bones [kg].
Real totalMass(const RagdollDesc& desc);

}  // namespace pba::ragdoll
