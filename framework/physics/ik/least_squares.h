#pragma once
// The weighted least-squares problem behind every Jacobian-based IK method (internal).
//
//   f(θ) = ½ Σₖ wₖ² ( |gₖ − eₖ(θ)|² + s² |ωₖ(θ)|² )            [m²]
//
// gₖ, eₖ: goal and effector positions; ωₖ: orientation error of a 6-DOF effector (IK slides, "6-DOF
// end effector"), s the orientation scale [m/rad]; wₖ the effector weight. The DOF weights W
// (IK slides, "Units": a per-DOF stiffness) act as a change of variables θ = θ₀ + W y, so the
// methods work with the scaled Jacobian J̃ = Wₑ J W and the gradient ∇_y f = −J̃ᵀ r, r = Wₑ (g − e).
#include <vector>

#include "physics/ik/jacobian.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik::detail {

struct LeastSquaresSystem {
  JacobianLayout layout;
  Matrix J;                      ///< J̃ = Wₑ J W: effector weights on the rows, DOF weights on the columns
  std::vector<Real> residual;    ///< r = Wₑ (g − e) (orientation rows s·ω)
  std::vector<Real> clamped;     ///< r with each effector's block clamped to maxErrorStep (Buss's D_max)
  std::vector<Real> dofWeights;  ///< diagonal of W (1 for free-joint columns)
  bool unitDofWeights = true;    ///< every entry of dofWeights is 1 (W = I: no column scaling)
};

/// The system at the current pose (c.frames must be current).
LeastSquaresSystem leastSquaresSystem(const Context& c);
/// The same into `sys`, reusing its storage: a method keeps one system for the whole solve (the
/// DOF weights, fixed by the skeleton, are read on the first call only).
void leastSquaresSystem(const Context& c, LeastSquaresSystem& sys);

/// f at `frames` (see above).
Real objective(const Context& c, const std::vector<Frame>& frames);

/// Projects c.pose onto the box of the joint limits (IK-6's clamp on every joint) when they are
/// enforced; otherwise leaves it alone.
void projectOntoLimits(Context& c);

/// The local rotations and frames of a trial pose (Context::evaluate).
struct TrialFrames {
  std::vector<Quat> local;
  std::vector<EulerHalfAngles> half;
  std::vector<Frame> frames;
};

/// Sets c.pose = start + Δθ (free joints turn about their column's axis in `layout`), projected onto
/// the box of the joint limits when they are enforced, and returns f there. `frames` are those of
/// `start`; `scratch` receives the trial pose's local rotations and frames. c.frames is left alone.
Real trialObjective(Context& c, const Pose& start, const std::vector<Frame>& frames, const JacobianLayout& layout,
                    const std::vector<Real>& delta, TrialFrames& scratch);
/// After the trial that left c.pose where it is: makes its frames c's (swaps the buffers), so c is
/// current without another forward kinematics.
void acceptTrial(Context& c, TrialFrames& scratch);

/// to = from. The rotations (read by free joints only) are copied only when `freeJoints` or when `to`
/// has none yet: without free joints no step changes them, so they are equal already.
void assignPose(Pose& to, const Pose& from, bool freeJoints);

/// Largest |entry| of v.
Real maxAbs(const std::vector<Real>& v);
/// Scales v uniformly so that its largest |entry| is at most `limit` (Buss & Kim 2005, ClampMaxAbs).
void clampMaxAbs(std::vector<Real>& v, Real limit);

inline constexpr Real kArmijo = 1e-4;    ///< c₁ of Armijo's sufficient-decrease condition (Nocedal & Wright §3.1)
inline constexpr int kMaxHalvings = 30;  ///< a backtracking search gives up after α has shrunk by 2³⁰

/// Backtracking line search (Nocedal & Wright 2006, Algorithm 3.1): tries α, α/2, α/4, … and
/// returns true at the first α with f(α) ≤ f0 + kArmijo α slope, where slope = ∇f·d < 0 is the
/// directional derivative along the search direction; slope = 0 (no derivative at hand: the
/// safeguard of pinv, DLS and SDLS) asks for a strict decrease f(α) < f0 instead. `f(α)` evaluates
/// the trial pose and leaves it in place, so on success the pose is the accepted one; false after
/// kMaxHalvings tries (the caller restores its start pose).
template <typename F>
bool backtrack(F&& f, Real f0, Real alpha, Real slope) {
  for (int h = 0; h < kMaxHalvings; ++h, alpha *= 0.5) {
    const Real value = f(alpha);
    if (slope < 0.0 ? value <= f0 + kArmijo * alpha * slope : value < f0) return true;
  }
  return false;
}

}  // namespace pba::ik::detail
