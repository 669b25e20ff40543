#pragma once
// The IK Jacobian (Workbook §2.5; IK slides, "Columns" and "6-DOF end effector").
// Rows: 3 per position effector, 6 per position+orientation effector (orientation rows scaled by
// s [m/rad] so that metres and radians share one error norm). Columns ("variables"): every scalar
// DOF in Pose::dofs order, then one column per Free joint, about its "best axis" of the moment
// a = unit(Σ (e − r) × (g − e)) (IK slides, quaternion joint), remembered to apply the step.
//   hinge:        ∂e/∂φ = a' × (e − r')           orientation rows: s a'
//   ball (XYZ):   three hinge columns; the world axis of x is R_pre x̂, of y is R_pre Rx ŷ, of z is
//                 R_pre Rx Ry ẑ (each axis carries the rotations applied before it)
//   prismatic:    ∂e/∂d = a'                        orientation rows: 0
// A column is zero for effectors not below the joint.
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

/// World axis of scalar DOF k (0–2) of joint j for rotational DOFs, or the translation axis.
Vec3 dofWorldAxis(const Joint& joint, const Pose& pose, const Frame& frame, int k);

/// Plans rows and columns and picks the free joints' axes for the current pose.
JacobianLayout planJacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
                            const std::vector<Frame>& frames, Real orientationScale);
/// The analytic Jacobian (effector weights not applied).
Matrix jacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
                const std::vector<Frame>& frames, const JacobianLayout& layout, Real orientationScale);
/// The same into J, reusing its storage (the solvers call it every iteration). `half`, when given:
/// per joint, the half angles of a ball joint's θ₀ and θ₁ from forward kinematics; an entry whose
/// angles equal the pose's saves the axes their sin and cos (the result is the same to the bit).
void jacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
              const std::vector<Frame>& frames, const JacobianLayout& layout, Real orientationScale, Matrix& J,
              const EulerHalfAngles* half = nullptr);
/// Central finite differences of the same quantities, step h (JacobianSource::CentralDifferences and
/// tests: a reference independent of IK-3): position rows
/// (e(θ+h) − e(θ−h)) / 2h, orientation rows s · rotvec(E(θ+h) E(θ−h)⁻¹) / 2h.
Matrix numericalJacobian(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
                         const JacobianLayout& layout, Real orientationScale, Real h);
/// Applies a change of the variables: dofs += Δ; free joints turn by Δ about their world axis.
void applyStep(const Skeleton& s, Pose& pose, const std::vector<Frame>& frames, const JacobianLayout& layout,
               const std::vector<Real>& delta);

}  // namespace pba::ik
