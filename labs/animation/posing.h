#pragma once
// Posing the character by hand and by IK (the keyframes and reach-while-walking scenes): turn a joint
// so that its bone points at a target, and a two-bone limb (shoulder, elbow, wrist) solved so that its
// end lands on a goal, by the IK library's law of cosines (ik::twoBoneGeometry) or by any of its
// iterative solvers (CCD, FABRIK, Jacobian transpose, pseudo-inverse, DLS, SDLS, gradient, L-BFGS).
#include <string>

#include "physics/animation/skeleton.h"
#include "physics/ik/solver.h"

namespace pba::lab {

/// Rotates joint `joint` (changing pose.rotations[joint] only) so that the direction from it to its
/// child `child` points at `target`, by the shortest arc in world space; world is recomputed.
void aimBone(const pba::animation::Skeleton& s, pba::animation::Pose& pose,
             std::vector<pba::animation::JointWorld>& world, int joint, int child, const Vec3& target);

/// The joints of a two-bone limb, e.g. {"LeftArm", "LeftForeArm", "LeftHand"}.
struct Limb {
  int root = -1, mid = -1, end = -1;
  bool valid() const { return root >= 0 && mid >= 0 && end >= 0; }
};
Limb findLimb(const pba::animation::Skeleton& s, const std::string& root, const std::string& mid,
              const std::string& end);

/// Solves the limb so its end reaches `goal` (as near as it can), the middle joint bending toward
/// `pole`. Changes the rotations of limb.root and limb.mid; world is recomputed. True when reachable.
bool reachWithLimb(const pba::animation::Skeleton& s, pba::animation::Pose& pose,
                   std::vector<pba::animation::JointWorld>& world, const Limb& limb, const Vec3& goal,
                   const Vec3& pole);

/// Solves the limb with the IK library's `method` (CMU asst4: "IK posing into keyframes", with any
/// solver). The limb becomes a three-joint IK chain built from the pose as it is: a ball joint at
/// limb.root, a hinge at limb.mid about the normal of the current bend plane (of the pole's plane when
/// the limb is straight, so that the middle joint bends toward the pole), flexing from straight to 150°,
/// and the effector at limb.end. The solved world rotations are written back as the two joints' local
/// rotations; world is recomputed. Analytic uses reachWithLimb. Returns the solver's result.
pba::ik::SolveResult solveLimb(const pba::animation::Skeleton& s, pba::animation::Pose& pose,
                               std::vector<pba::animation::JointWorld>& world, const Limb& limb, const Vec3& goal,
                               const Vec3& pole, pba::ik::SolverKind method);

}  // namespace pba::lab
