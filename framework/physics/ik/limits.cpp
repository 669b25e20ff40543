// Joint limits (Workbook §2.1 task 5, §2.7; IK slides, "Joint limits"): the simplest enforcement is to
// clamp the pose after every iteration. For a scalar DOF that is a clamp into [lo, hi]. For a free
// (quaternion) joint limited to a largest rotation angle φ_max, the pose is projected onto the
// allowed set along its own axis: q = (axis, φ) with φ > φ_max becomes (axis, φ_max) — the nearest
// allowed rotation about the same axis.
#include <algorithm>

#include "physics/exercises/not_implemented.h"
#include "physics/ik/builders.h"
#include "physics/ik/exercises.h"

namespace pba::ik {

// ***** IK-6: joint-limit clamping (Workbook §2.7; IK slides, "Joint limits") *****
// Inputs: the skeleton, a joint index j and the pose to correct in place. Scalar DOFs (hinge angles
// [rad], prismatic offsets [m]) live in pose.dofs, a free joint's rotation in pose.rotations[j].
// (1) Which DOFs does joint j own in the pose (Joint::firstDof, dofCount(type)), and where are their
//     limits? Bring each one back into its range.
// (2) A free joint is limited by its rotation ANGLE (joint.maxRotation): when it turns further, shorten
//     the rotation to exactly the limit while keeping its axis (rotationVector and
//     quatFromRotationVector convert between a quaternion and axis · angle).
// (3) Fixed joints have nothing to clamp.
// Check: values inside their ranges are untouched; a clamped free joint turns by exactly maxRotation
// about its old axis; other joints' DOFs never change.
// *****
void clampJointToLimits([[maybe_unused]] const Skeleton& skeleton, [[maybe_unused]] Pose& pose,
                        [[maybe_unused]] int j) {
  // BEGIN SOLUTION
  const Joint& joint = skeleton.joint(j);
  for (int k = 0; k < dofCount(joint.type); ++k) {
    Real& v = pose.dofs[static_cast<size_t>(joint.firstDof + k)];
    v = std::clamp(v, joint.lo[k], joint.hi[k]);
  }
  if (joint.type == JointType::Free) {
    const Vec3 r = rotationVector(pose.rotations[static_cast<size_t>(j)]);
    const Real angle = glm::length(r);
    if (angle > joint.maxRotation)
      pose.rotations[static_cast<size_t>(j)] = quatFromRotationVector(r * (joint.maxRotation / angle));
  }
  return;
  // END SOLUTION
  // STUB: exercises::markNotImplemented("IK-6");
}

// Start-up probe: tells the lab whether IK-6 is still a stub.
namespace {
void probeLimitClamping() {
  Result<Rig> rig = buildSingleJoint();
  if (!rig) return;
  Pose pose = rig.value().skeleton.restPose();
  clampJointToLimits(rig.value().skeleton, pose, 0);
}
}  // namespace
PBA_EXERCISE_PROBE(probeLimitClamping());

}  // namespace pba::ik
