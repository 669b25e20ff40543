#pragma once
// A ragdoll from any skeleton: the library sees only joint names, parents and rest positions (a lab
// reads them from a file with Assimp). Both methods land and rest with every BVH file of resources/ and of
// Debian's assimp-testmodels (tests/labs/ragdoll_bvh_rest_test.cpp; the constraint method with
// skeletonRagdollWorldSettings()). Joints within 2 cm of their parent's joint (helper joints of
// motion-capture files) merge into it; bones that start at one point with a sibling start clear of it.
// One box per joint that has children:
//   * one child: a box along the segment to it, as thick as `thickness` × length within
//     [minHalfThickness, maxHalfThickness];
//   * several children (hips, chest): the axis-aligned box around the joint and its children, inflated by
//     minHalfThickness.
// Each bone is joined to its nearest ancestor's bone at its joint: knees and elbows (by name: "knee",
// "calf", "shin", "lowerleg", "leg" but not "upleg"; "elbow", "forearm", "lowerarm") are hinges flexing
// 0°…150° (knees backwards, elbows forwards), the others balls with a cone about the bone by name pattern
// (spine/chest/neck/head 30°, clavicle/shoulder/collar 20°, hip/upleg/thigh 60°, arm 80°, hand/foot 40°,
// toe 60°: toes bend far, and a figure lying face down presses them up; else `defaultCone`). Masses are
// in proportion to volume, at least `minMassShare` of the total each.
// Forward is lateral × up, with lateral the mean of Left* minus Right* joints (+z when there are none).
#include <string>
#include <vector>

#include "physics/ragdoll/ragdoll_desc.h"

namespace pba::ragdoll {

struct SkeletonJoint {
  std::string name;
  int parent = -1;     ///< index of the parent joint (parents before children), −1 for the root
  Vec3 position{0.0};  ///< [m] world, rest pose
};

struct SkeletonRagdollDesc {
  Real totalMass = 70.0;          ///< [kg]
  Real thickness = 0.22;          ///< box width over bone length
  Real minHalfThickness = 0.025;  ///< [m]
  Real maxHalfThickness = 0.06;   ///< [m]
  Real defaultCone = degToRad(45.0);
  Real minMassShare = 0.02;  ///< no bone lighter than this share of the total mass
};

/// Errors: no joints, a parent after its child, non-finite positions, no segment long enough for a bone.
Result<RagdollDesc> buildSkeletonRagdoll(const std::vector<SkeletonJoint>& joints,
                                         const SkeletonRagdollDesc& desc = {});

}  // namespace pba::ragdoll
