#pragma once
// Kinematic skeletons for inverse kinematics (Workbook §2.1 task 1; IK slides "columns"; CMU asst4
// "Character"): a tree of joints, each placed at a rest offset in its parent's frame and carrying
// 0–3 scalar degrees of freedom (DOFs) or one free quaternion rotation.
//
// Frames. Joint j's world frame is
//   R_j = R_parent · Q_rest · R_dof(θ),      p_j = p_parent + R_parent · (o_j + Q_rest · a d)
// where o_j is the rest offset [m], Q_rest the rest rotation, R_dof the joint's own rotation
// (hinge: angle about axis a; ball: Rx(θ0)·Ry(θ1)·Rz(θ2), the XYZ Euler order of the IK slides;
// free: a unit quaternion) and d the prismatic displacement [m] along a. "Pre-rotation"
// R_pre = R_parent · Q_rest is the frame in which the DOF axes are fixed.
//
// The skeleton (description: structure, limits, weights) is separate from the Pose (the DOF
// values), so solvers, ghosts and tests can hold many poses of one skeleton.
#include <string>
#include <vector>

#include "physics/core/result.h"
#include "physics/core/types.h"

namespace pba::ik {

enum class JointType {
  Fixed,      ///< 0 DOFs: a rigid offset (e.g. a finger tip site)
  Hinge,      ///< 1 rotational DOF about `axis` [rad]
  Ball,       ///< 3 rotational DOFs: XYZ Euler angles [rad] (IK slides, 3-DOF joints)
  Free,       ///< a unit quaternion (IK slides, "quaternion joint"); limited by a maximum rotation angle
  Prismatic,  ///< 1 translational DOF along `axis` [m]
};

/// Number of scalar DOFs a joint type carries (Free carries its quaternion separately: 0).
int dofCount(JointType type);
const char* jointTypeName(JointType type);

/// One joint. Angles [rad], lengths [m]; limits per scalar DOF.
struct Joint {
  std::string name;
  int parent = -1;                ///< index of the parent joint, −1 for the root; always < own index
  Vec3 offset{0.0};               ///< [m] rest position in the parent's frame (root: world position)
  Quat restRotation{1, 0, 0, 0};  ///< rest orientation relative to the parent's frame
  JointType type = JointType::Hinge;
  Vec3 axis{0.0, 0.0, 1.0};          ///< unit; hinge/prismatic axis in the pre-rotation frame
  int firstDof = 0;                  ///< index of this joint's first DOF in Pose::dofs (set by Skeleton::add)
  Real lo[3] = {-kPi, -kPi, -kPi};   ///< [rad] or [m] lower limit per DOF
  Real hi[3] = {kPi, kPi, kPi};      ///< [rad] or [m] upper limit per DOF
  Real weight[3] = {1.0, 1.0, 1.0};  ///< [1] > 0: a larger weight lets the DOF move more (IK slides, "Units")
  Real maxRotation = kPi;            ///< [rad] Free joints only: largest rotation angle away from rest
};

/// The DOF values of one configuration of a skeleton.
struct Pose {
  std::vector<Real> dofs;       ///< [rad] or [m], Skeleton::dofCount() entries
  std::vector<Quat> rotations;  ///< per joint; used by Free joints only (identity otherwise)
};

/// A joint's world frame after forward kinematics.
struct Frame {
  Vec3 position{0.0};         ///< [m] world position of the joint (its pivot)
  Quat rotation{1, 0, 0, 0};  ///< world orientation of the joint's frame (after its own DOFs)
  Quat pre{1, 0, 0, 0};       ///< R_pre = R_parent · Q_rest: the frame of the DOF axes
};

class Skeleton {
 public:
  /// Appends a joint (parent must already exist). Returns its index, or an error naming the field.
  Result<int> add(Joint joint);

  int jointCount() const { return static_cast<int>(joints_.size()); }
  int dofCount() const { return dofTotal_; }
  const Joint& joint(int j) const { return joints_[static_cast<size_t>(j)]; }
  Joint& joint(int j) { return joints_[static_cast<size_t>(j)]; }
  const std::vector<Joint>& joints() const { return joints_; }
  /// Children of joint j, in index order.
  const std::vector<int>& children(int j) const { return children_[static_cast<size_t>(j)]; }
  /// Joint of DOF i.
  int dofJoint(int i) const { return dofJoint_[static_cast<size_t>(i)]; }
  Real dofLo(int i) const;
  Real dofHi(int i) const;
  Real dofWeight(int i) const;
  /// −1 when absent.
  int find(const std::string& name) const;

  /// The rest pose: every DOF 0 clamped into its limits, every quaternion identity.
  Pose restPose() const;

 private:
  std::vector<Joint> joints_;
  std::vector<std::vector<int>> children_;
  std::vector<int> dofJoint_;
  int dofTotal_ = 0;
};

/// Checks the pose has the right sizes and finite values; message names the field.
Status validate(const Skeleton& skeleton, const Pose& pose);

/// Local rotation R_dof of joint j in pose (identity for Fixed/Prismatic).
Quat jointRotation(const Joint& joint, const Pose& pose, int jointIndex);
/// Local translation o_j + Q_rest · a d (d only for Prismatic).
Vec3 jointTranslation(const Joint& joint, const Pose& pose);
/// World frame of one joint from its parent's frame (nullptr for the root). O(1).
Frame childFrame(const Joint& joint, const Pose& pose, int jointIndex, const Frame* parent);
/// Forward kinematics: world frames of every joint, parents before children. O(n).
void forwardKinematics(const Skeleton& skeleton, const Pose& pose, std::vector<Frame>& frames);
std::vector<Frame> forwardKinematics(const Skeleton& skeleton, const Pose& pose);

/// XYZ Euler angles (a, b, c) with R = Rx(a)·Ry(b)·Rz(c); b in [−π/2, π/2]. Safe at gimbal lock.
Vec3 eulerXYZFromQuat(const Quat& q);
Quat quatFromEulerXYZ(const Vec3& angles);
/// cos ½θ and sin ½θ of a ball joint's first two Euler angles (θ₀ about x, θ₁ about y) as
/// quatFromEulerXYZ computes them, with the angles they belong to: the Jacobian's axes reuse them
/// (jacobian.h) instead of calling sin and cos again. A pure function of (angle0, angle1).
struct EulerHalfAngles {
  Real angle0 = 0.0, angle1 = 0.0;  ///< [rad] θ₀, θ₁
  Real c0 = 1.0, s0 = 0.0, c1 = 1.0, s1 = 0.0;
};
/// quatFromEulerXYZ, also writing the half angles of θ₀ and θ₁ to *half.
Quat quatFromEulerXYZ(const Vec3& angles, EulerHalfAngles* half);
/// Rotation vector (axis · angle, angle in [0, π]) of a unit quaternion, without acos/asin traps.
Vec3 rotationVector(const Quat& q);
/// Unit quaternion of a rotation vector.
Quat quatFromRotationVector(const Vec3& v);
/// The shortest-arc rotation taking direction u onto direction v (identity when either is ~0;
/// a half turn about a perpendicular axis when they are opposite). Eigen's two-vector quaternion.
Quat shortestArc(const Vec3& u, const Vec3& v);
/// A unit vector perpendicular to v ≠ 0: v × x̂, or v × ŷ when v is nearly along x̂.
Vec3 anyPerpendicular(const Vec3& v);

/// Largest amount by which any DOF (or Free joint angle) exceeds its limits [rad or m]; 0 when inside.
Real limitViolation(const Skeleton& skeleton, const Pose& pose);

}  // namespace pba::ik
