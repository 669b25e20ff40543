#include "posing.h"

#include <cmath>

#include "physics/ik/analytic.h"
#include "physics/ik/skeleton.h"

namespace pba::lab {

namespace an = pba::animation;

void aimBone(const an::Skeleton& s, an::Pose& pose, std::vector<an::JointWorld>& world, int joint, int child,
             const Vec3& target) {
  const an::JointWorld& j = world[static_cast<size_t>(joint)];
  const Vec3 now = world[static_cast<size_t>(child)].position - j.position;
  const Vec3 want = target - j.position;
  if (glm::length(now) < 1e-9 || glm::length(want) < 1e-9) return;
  const Quat turn = pba::ik::shortestArc(now, want);  // world-space rotation
  const int p = s.parents[static_cast<size_t>(joint)];
  const Quat parent = p < 0 ? Quat(1, 0, 0, 0) : world[static_cast<size_t>(p)].rotation;
  // R_j' = turn · R_j and R_j' = R_parent · q_j'  ⇒  q_j' = R_parent⁻¹ · turn · R_j.
  pose.rotations[static_cast<size_t>(joint)] = glm::normalize(glm::conjugate(parent) * turn * j.rotation);
  world = an::forwardKinematics(s, pose);
}

Limb findLimb(const an::Skeleton& s, const std::string& root, const std::string& mid, const std::string& end) {
  return {s.find(root), s.find(mid), s.find(end)};
}

bool reachWithLimb(const an::Skeleton& s, an::Pose& pose, std::vector<an::JointWorld>& world, const Limb& limb,
                   const Vec3& goal, const Vec3& pole) {
  if (!limb.valid() || world.size() != s.names.size()) return false;
  const Vec3 a = world[static_cast<size_t>(limb.root)].position;
  const Real upper = glm::length(world[static_cast<size_t>(limb.mid)].position - a);
  const Real lower =
      glm::length(world[static_cast<size_t>(limb.end)].position - world[static_cast<size_t>(limb.mid)].position);
  const pba::ik::TwoBonePose solved = pba::ik::twoBoneGeometry(a, upper, lower, goal, pole);
  aimBone(s, pose, world, limb.root, limb.mid, solved.elbow);
  aimBone(s, pose, world, limb.mid, limb.end, solved.wrist);
  return solved.reachable;
}

namespace {

constexpr Real kLimbTolerance = 1e-4;           // [m] a tenth of a millimetre: the end on its goal
constexpr int kLimbIterations = 500;            // enough for the slowest method (Jacobian transpose) on 4 DOFs
constexpr int kLimbRestarts = 4;                // stall recoveries within those iterations
constexpr Real kFlexMax = 150.0 * kPi / 180.0;  // [rad] a knee or elbow bends this far from straight
constexpr Real kStraight = 1e-4;                // [rad] a limb bent less than this is straight

Real distance(const std::vector<an::JointWorld>& w, int a, int b) {
  return glm::length(w[static_cast<size_t>(a)].position - w[static_cast<size_t>(b)].position);
}

}  // namespace

pba::ik::SolveResult solveLimb(const an::Skeleton& s, an::Pose& pose, std::vector<an::JointWorld>& world,
                               const Limb& limb, const Vec3& goal, const Vec3& pole, pba::ik::SolverKind method) {
  namespace ik = pba::ik;
  ik::SolveResult result;
  if (!limb.valid() || world.size() != s.names.size()) {
    result.message = "limb: not found in the skeleton";
    return result;
  }
  if (method == ik::SolverKind::Analytic) {
    const bool reachable = reachWithLimb(s, pose, world, limb, goal, pole);
    result.status = reachable ? ik::SolveStatus::Success : ik::SolveStatus::Unreachable;
    result.positionResidual = glm::length(world[static_cast<size_t>(limb.end)].position - goal);
    return result;
  }
  const an::JointWorld root = world[static_cast<size_t>(limb.root)], mid = world[static_cast<size_t>(limb.mid)];
  const Vec3 end = world[static_cast<size_t>(limb.end)].position;
  const Vec3 upper = mid.position - root.position, lower = end - mid.position;
  if (distance(world, limb.root, limb.mid) < 1e-9 || distance(world, limb.mid, limb.end) < 1e-9) {
    result.message = "limb: a bone of length 0";
    return result;
  }
  // The hinge: about n with lower = R(bend, n) · upper (directions), so flexing is a positive angle.
  // A straight limb takes n = d × u, d the pole's direction across the upper bone: flexing then turns
  // the lower bone away from the pole, i.e. the middle joint toward it (as ik::twoBoneGeometry bends).
  const Vec3 u = glm::normalize(upper), l = glm::normalize(lower);
  Real bend = std::atan2(glm::length(glm::cross(u, l)), glm::dot(u, l));
  Vec3 n = glm::cross(u, l);
  if (bend < kStraight) {
    const Vec3 toPole = pole - mid.position;
    const Vec3 across = toPole - glm::dot(toPole, u) * u;
    n = glm::length(across) > 1e-9 ? glm::cross(glm::normalize(across), u) : ik::anyPerpendicular(u);
    bend = 0.0;
  }
  n = glm::normalize(n);
  // The chain: its rest pose is the pose as it is (every DOF 0), in world coordinates.
  ik::Skeleton chain;
  ik::Joint j0;
  j0.name = s.names[static_cast<size_t>(limb.root)];
  j0.type = ik::JointType::Ball;
  j0.offset = root.position;
  j0.restRotation = root.rotation;
  ik::Joint j1;
  j1.name = s.names[static_cast<size_t>(limb.mid)];
  j1.parent = 0;
  j1.type = ik::JointType::Hinge;
  j1.offset = glm::inverse(root.rotation) * upper;
  j1.restRotation = glm::normalize(glm::inverse(root.rotation) * mid.rotation);
  j1.axis = glm::normalize(glm::inverse(mid.rotation) * n);
  j1.lo[0] = -bend;
  j1.hi[0] = std::max(kFlexMax - bend, 0.0);
  ik::Joint j2;
  j2.name = s.names[static_cast<size_t>(limb.end)];
  j2.parent = 1;
  j2.type = ik::JointType::Fixed;
  j2.offset = glm::inverse(mid.rotation) * lower;
  for (const ik::Joint& j : {j0, j1, j2})
    if (const Result<int> added = chain.add(j); !added) {
      result.message = added.error();
      return result;
    }
  ik::Effector e;
  e.joint = 2;
  e.targetPosition = goal;
  ik::SolveOptions o;
  o.solver = method;
  o.tolerance = kLimbTolerance;
  o.maxIterations = kLimbIterations;
  o.damping = 0.05 * (glm::length(upper) + glm::length(lower));  // [m] a twentieth of the limb's reach
  // CCD and the Jacobian methods can stall against the elbow's straight limit (a local minimum of a
  // one-sided hinge): restart from random poses within the limits, deterministically (SolveOptions).
  o.restarts = kLimbRestarts;
  ik::Pose solved = chain.restPose();
  result = ik::solve(chain, solved, {e}, o);
  const std::vector<ik::Frame> frames = ik::forwardKinematics(chain, solved);
  // Back to local rotations: R_root' = R_parent · q_root', and the same for the middle joint.
  const int p = s.parents[static_cast<size_t>(limb.root)];
  const Quat parent = p < 0 ? Quat(1, 0, 0, 0) : world[static_cast<size_t>(p)].rotation;
  pose.rotations[static_cast<size_t>(limb.root)] = glm::normalize(glm::conjugate(parent) * frames[0].rotation);
  world = an::forwardKinematics(s, pose);
  const Quat midParent = world[static_cast<size_t>(s.parents[static_cast<size_t>(limb.mid)])].rotation;
  pose.rotations[static_cast<size_t>(limb.mid)] = glm::normalize(glm::conjugate(midParent) * frames[1].rotation);
  world = an::forwardKinematics(s, pose);
  return result;
}

}  // namespace pba::lab
