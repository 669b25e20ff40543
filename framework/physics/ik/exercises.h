#pragma once
// The IK lab's exercises (docs/workbook/01-inverse-kinematics.md). Each function below carries a
// starred block with its steps in its .cpp file; the student release replaces the solution by a stub
// that reports "IK-n not implemented" and returns a safe default, so every scene still runs.
#include <vector>

#include "physics/ik/linalg.h"
#include "physics/ik/skeleton.h"

namespace pba::ik {

/// A rotation as a unit axis and an angle [rad] about it (right-hand rule).
struct AxisAngle {
  Vec3 axis{0.0, 0.0, 1.0};
  Real angle = 0.0;
};

/// IK-1 (analytic.cpp): the rotation that turns `boneDirection` onto `toTarget` (Workbook §2.1 task 2).
AxisAngle analyticSingleJoint(const Vec3& boneDirection, const Vec3& toTarget);

/// IK-2 (ccd.cpp): CCD's joint update (Workbook §2.4, Algorithm 1): the rotation about `pivot` that
/// takes the effector's direction onto the target's direction.
Quat ccdJointUpdate(const Vec3& pivot, const Vec3& effector, const Vec3& target);

/// IK-3 (jacobian.h, jacobian.cpp): one joint's columns of the Jacobian, for hinge, ball and prismatic
/// DOFs: jointJacobianColumns.

/// IK-4 (jacobian_solvers.cpp): the damped least-squares step (Workbook §2.6).
std::vector<Real> dampedLeastSquaresStep(const Matrix& J, const std::vector<Real>& error, Real lambda);

/// IK-5 (fabrik_passes.cpp): FABRIK's two passes on a chain of points p₀ … pₙ₋₁ with segment lengths
/// lengths[i] = |pᵢ₊₁ − pᵢ| (Aristidou & Lasenby 2011, Algorithm 1).
/// Backward ("reaching"): pₙ₋₁ = target, then each earlier point moves toward its successor.
void fabrikBackward(std::vector<Vec3>& points, const std::vector<Real>& lengths, const Vec3& target);
/// Forward: p₀ = base, then each later point moves toward its predecessor.
void fabrikForward(std::vector<Vec3>& points, const std::vector<Real>& lengths, const Vec3& base);

/// IK-7 (jacobian_solvers.cpp): the Jacobian-transpose step: its direction over the DOFs and its length α
/// (Buss 2004 §4); α = 0 at a stationary point.
struct TransposeStep {
  std::vector<Real> direction;
  Real alpha = 0.0;
};
TransposeStep jacobianTransposeStep(const Matrix& J, const std::vector<Real>& error);

/// IK-8 (jacobian_solvers.cpp): selectively damped least squares' damping choice for one singular
/// direction (Buss & Kim 2005 §4): the largest DOF change γᵢ [rad] its step may make, at most γ_max.
/// u: the left singular vector (J.rows entries, 3 per effector block), v: the right one (J.cols
/// entries), sigma > 0 its singular value, rho[j]: how far all effectors move per unit change of DOF j.
Real selectiveDampingLimit(const std::vector<Real>& u, const std::vector<Real>& v, Real sigma,
                           const std::vector<Real>& rho, Real gammaMax);

/// IK-6 (limits.cpp): clamps joint j of `pose` into its limits (Workbook §2.7; IK slides "Joint limits").
void clampJointToLimits(const Skeleton& skeleton, Pose& pose, int j);

}  // namespace pba::ik
