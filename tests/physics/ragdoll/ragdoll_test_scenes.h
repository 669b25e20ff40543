#pragma once
// Small ragdolls shared by the ragdoll tests.
#include "physics/ragdoll/ragdoll_desc.h"

namespace pba::ragdoll::test_scenes {

/// A fixed holder and an arm starting horizontal (+x) on a hinge about z with limits [lower, upper] [rad].
inline RagdollDesc hingeArm(Real lower, Real upper) {
  RagdollDesc d;
  BoneDesc holder;
  holder.center = Vec3(0.0, 2.0, 0.0), holder.halfExtents = Vec3(0.1), holder.fixed = true;
  BoneDesc arm;
  arm.center = Vec3(0.3, 2.0, 0.0), arm.halfExtents = Vec3(0.2, 0.05, 0.05), arm.mass = 2.0;
  d.bones = {holder, arm};
  JointDesc j;
  j.kind = JointKind::Hinge, j.boneA = 0, j.boneB = 1, j.anchor = Vec3(0.1, 2.0, 0.0), j.axis = Vec3(0.0, 0.0, 1.0);
  j.limited = true, j.lower = lower, j.upper = upper;
  d.joints = {j};
  return d;
}

}  // namespace pba::ragdoll::test_scenes
