#pragma once
// Internals shared by the IK methods (not part of the public interface): the state of one solve and
// the per-method iteration functions called by solve() in solver.cpp.
#include <memory>
#include <vector>

#include "physics/ik/solver.h"

namespace pba::ik::detail {

/// Everything one solve works on. `frames` is kept up to date with `pose` by the driver after every
/// iteration (methods that change the pose call refresh() before reading frames again).
struct Context {
  const Skeleton& skeleton;
  Pose& pose;
  const std::vector<Effector>& effectors;
  const SolveOptions& options;
  std::vector<Frame> frames;
  Real meanBone = 1.0;          ///< [m] mean distance between a joint and its parent (≥ 1e-6)
  Real orientationScale = 1.0;  ///< [m/rad] resolved options.orientationScale
  Real maxErrorStep = 1.0;      ///< [m] resolved options.maxErrorStep
  /// Per joint: indices of the effectors in its subtree (joint is an ancestor of the effector's joint).
  std::vector<std::vector<int>> effectorsBelow;
  /// Per joint: true when it lies on the path from the root to some effector.
  std::vector<char> active;

  void refresh() { forwardKinematics(skeleton, pose, frames); }
};

/// One IK method: iterate() does one pass (CCD, FABRIK) or one step (Jacobian methods).
class Method {
 public:
  virtual ~Method() = default;
  virtual void iterate(Context& c) = 0;
  /// True when the method solved the problem in closed form and needs no more iterations.
  virtual bool finished() const { return false; }
};

std::unique_ptr<Method> makeCcd();
std::unique_ptr<Method> makeFabrik();
std::unique_ptr<Method> makeJacobianMethod(SolverKind kind);
/// nullptr with *why set when the skeleton/effectors are not a single joint or a two-bone limb.
std::unique_ptr<Method> makeAnalytic(const Context& c, std::string* why);

/// Rotates/translates joint j (whose world pre-rotation and pivot are `frame`) to best carry the
/// points `from[i]` (world, currently attached below j) onto `to[i]` with weights w[i]:
/// minimises Σ wᵢ |T(fromᵢ) − toᵢ|² over the joint's DOFs, exactly for a hinge, prismatic or a single
/// point on a ball/free joint, by a few per-axis sweeps otherwise. Clamps to limits when asked.
/// Returns the world rotation actually applied about the pivot (identity for prismatic) and, through
/// *translation, the world translation applied (prismatic).
/// `useExercise` routes single-point ball/free updates through IK-2 (ccdJointUpdate), as CCD does.
Quat alignJoint(const Skeleton& s, Pose& pose, int j, const Frame& frame, const std::vector<Vec3>& from,
                const std::vector<Vec3>& to, const std::vector<Real>& w, bool clampLimits, bool useExercise,
                Vec3* translation);

/// The straight pose toward the goal for a single unreachable position effector: each joint on the
/// path, from the root, turns its bone toward the goal (Aristidou & Lasenby 2011, Algorithm 1, lines
/// 3–8). Exact for ball and free joints without limits; best effort otherwise.
void stretchToward(Context& c, const Effector& e);

}  // namespace pba::ik::detail
