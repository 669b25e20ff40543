#pragma once
// The IK Jacobian (Workbook §2.5; IK slides, "Columns" and "6-DOF end effector").
// Rows: 3 per position effector, 6 per position+orientation effector (orientation rows scaled by
// s [m/rad] so that metres and radians share one error norm). Columns ("variables"): every scalar
// DOF in Pose::dofs order, then one column per Free joint, about its "best axis" of the moment
// a = unit(Σ (e − r) × (g − e)) (IK slides, quaternion joint), remembered to apply the step.
// Each joint's position columns and DOF axes are the exercise IK-3 (jointJacobianColumns); the
// orientation rows of a rotational DOF are s times its world axis, of a prismatic one zero. A column is
// zero for effectors not below the joint.
#include <vector>

#include "physics/ik/effector.h"
#include "physics/ik/linalg.h"
#include "physics/ik/skeleton.h"

namespace pba::ik {

struct JacobianLayout {
  int rows = 0;
  int cols = 0;
  std::vector<int> rowOfEffector;  ///< first row of each effector
  std::vector<int> freeJoints;     ///< joint of column dofCount + k
  std::vector<Vec3> freeAxes;      ///< world axis of each free-joint column (unit or zero)
};

/// IK-3 (jacobian.cpp): what one joint contributes to the Jacobian of an effector at world point e.
struct JointColumns {
  Vec3 axis[3] = {Vec3(0.0), Vec3(0.0), Vec3(0.0)};    ///< world axis (unit) of each scalar DOF
  Vec3 column[3] = {Vec3(0.0), Vec3(0.0), Vec3(0.0)};  ///< ∂e/∂θ_k [m/rad] (rotational) or [m/m] (prismatic)
};
/// The joint's DOF axes and position columns (hinge and prismatic: entry 0; ball: entries 0–2; other
/// types: none); `frame` is the joint's frame from forward kinematics.
JointColumns jointJacobianColumns(const Joint& joint, const Pose& pose, const Frame& frame, const Vec3& effector);

/// Plans rows and columns and picks the free joints' axes for the current pose.
JacobianLayout planJacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
                            const std::vector<Frame>& frames, Real orientationScale);
/// The analytic Jacobian (effector weights not applied).
Matrix jacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
                const std::vector<Frame>& frames, const JacobianLayout& layout, Real orientationScale);
/// The same into J, reusing its storage (the solvers call it every iteration). Every column comes from
/// IK-3 (jointJacobianColumns), walking each effector's chain to the root.
void jacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
              const std::vector<Frame>& frames, const JacobianLayout& layout, Real orientationScale, Matrix& J);
/// Central finite differences of the same quantities, step h (JacobianSource::CentralDifferences and
/// tests: a reference independent of IK-3): position rows
/// (e(θ+h) − e(θ−h)) / 2h, orientation rows s · rotvec(E(θ+h) E(θ−h)⁻¹) / 2h.
Matrix numericalJacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
                         const JacobianLayout& layout, Real orientationScale, Real h);
/// Applies a change of the variables: dofs += Δ; free joints turn by Δ about their world axis.
void applyStep(const Skeleton& s, Pose& pose, const std::vector<Frame>& frames, const JacobianLayout& layout,
               const std::vector<Real>& delta);

}  // namespace pba::ik
