#pragma once
// The ODE layer's solver half (Lobb notes, "ODE view" and "Solver/state separation"): time integrators
// that step any OdeSystem / SecondOrderSystem, interchangeable by name at run time.
//
//   name               order  kind                       source
//   euler              1      explicit                   Lobb notes, Euler            (PART-1)
//   symplectic-euler   1      semi-implicit, symplectic  Lobb "simple loop"; CMU asst4 (PART-2)
//   midpoint           2      explicit RK2               Lobb notes, Midpoint         (PART-7)
//   rk4                4      explicit RK4               Lobb notes, RK4              (PART-3)
//   verlet             2      position Verlet, symplectic Ragdoll paper §Verlet (Jakobsen) (PART-6)
//   velocity-verlet    2      symplectic                 Swope et al. 1982
//   implicit-euler     1      linearised backward Euler  Baraff & Witkin 1998 eq. 16–18, CG
//   adaptive           5(4)   embedded RK (Dormand–Prince 1980) with error control (Lobb "adaptive", PART-8)
//
// Stability on the undamped oscillator ẍ = −ω²x (amplification of the energy per step, z = ωh):
//   euler 1 + z² (always grows) · symplectic Euler bounded for z < 2 · midpoint 1 + z⁴/4 ·
//   rk4 1 − z⁶/72 + z⁸/576 (stable for z < 2√2) · verlet family bounded for z < 2 ·
//   implicit Euler 1/(1 + z²) (always decays: unconditionally stable, and dissipative).
#include <array>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "physics/core/enum_names.h"
#include "physics/core/result.h"
#include "physics/ode/ode_system.h"

namespace pba::ode {

enum class IntegratorKind {
  Euler,
  SymplecticEuler,
  Midpoint,
  Rk4,
  Verlet,
  VelocityVerlet,
  ImplicitEuler,
  Adaptive,
};

/// The names for the command line, scene files and the UI.
inline constexpr auto kIntegratorNames =
    enumNames<IntegratorKind>({{IntegratorKind::Euler, "euler"},
                               {IntegratorKind::SymplecticEuler, "symplectic-euler"},
                               {IntegratorKind::Midpoint, "midpoint"},
                               {IntegratorKind::Rk4, "rk4"},
                               {IntegratorKind::Verlet, "verlet"},
                               {IntegratorKind::VelocityVerlet, "velocity-verlet"},
                               {IntegratorKind::ImplicitEuler, "implicit-euler"},
                               {IntegratorKind::Adaptive, "adaptive"}});
inline constexpr std::array kAllIntegrators = kIntegratorNames.values();
inline std::string_view integratorName(IntegratorKind kind) { return kIntegratorNames.name(kind); }
/// Inverse of integratorName(); nothing for an unknown name.
inline std::optional<IntegratorKind> parseIntegrator(std::string_view name) { return kIntegratorNames.parse(name); }
/// All names in kAllIntegrators order (for UI choices).
inline std::vector<std::string> integratorNames() { return kIntegratorNames.names(); }
/// Asymptotic order of the global error (1, 2, 4; 5 for adaptive's propagated solution).
int integratorOrder(IntegratorKind kind);

/// Scratch buffers of the integrators, reused between steps so that stepping never allocates.
struct Workspace {
  /// The state a generic method advances, set by its first helper (ode/step_helpers.h): the system's own
  /// storage when it lends it (OdeSystem::stateStorage()), else `state` holding a copy. Valid during a step.
  std::span<Real> s;
  std::vector<Real> state;  ///< the copy of s for a system that does not lend its storage; adaptive's s
  std::vector<Real> k1, k2, k3, k4, k5, k6, k7, tmp, tmp2;
  std::vector<Mat3> blocks, blocks2;  ///< implicit Euler: Jacobian diagonal blocks, then the preconditioner

  /// Makes each of `buffers` (members of a Workspace) n long; a buffer that changes size is zeroed,
  /// one that already fits is left alone (no allocation once sized).
  static void fit(std::size_t n, std::initializer_list<std::vector<Real>*> buffers) {
    for (std::vector<Real>* b : buffers) {
      if (b->size() != n) b->assign(n, 0.0);
    }
  }
};

// ----- Generic methods: any OdeSystem (state copied out, advanced, copied back) -----
// (explicit Euler, PART-1, works on the split s = (q, v) in place: it is with the methods below.)

// ***** PART-3: classical Runge–Kutta 4 (Lobb notes, RK4) *****
// One step of length h [s] of ds/dt = f(s, t) on the system's whole state s (getState/setState), its
// clock the system's time [s].
// (1) Four slopes, each taken at a trial state built from the previous slope: at the start of the step,
//     twice at its middle, and at its end. Work out each trial state and its time. (The notes scale each
//     slope by h; here a slope is the derivative itself, so h multiplies when you use it.)
// (2) Combine the four with RK4's weights (Simpson's rule) into the step.
// (3) Write the state back and advance the clock by h.
// (ode/step_helpers.h has the helpers every generic method uses: beginGenericStep() reads the state and
// the first slope into w.s and w.k1, endGenericStep() writes back and advances the clock.)
// Check: exact when ds/dt is a polynomial in t alone of degree ≤ 3; halving h divides the error by 16.
// *****
void rk4Step(OdeSystem& system, Real h, Workspace& w);

// ----- Methods that use the split s = (q, v) of a SecondOrderSystem (in place) -----

// ***** PART-1: the ODE view and its Euler step (Lobb notes, "ODE view": Euler; "Solver/state separation") *****
// One explicit Euler step of length h [s] of a second-order system seen as the first-order ODE
// ds/dt = f(s, t): the state s = (q, v) is its positions q [m] (or rad) and velocities v [m/s], both
// the system's own arrays (positions(), velocities(), n = dofCount() values each, updated in place).
// (1) Assemble the state derivative at the start of the step from what the system knows: the rate of
//     change of q is one of the state's own halves (which?); that of v comes from the generalised force
//     f(t, q, v) [N] (force(), into a scratch array of the workspace sized with Workspace::fit) and the
//     inverse masses M⁻¹ [1/kg] (inverseMasses(); 0 on a pinned coordinate, which must not accelerate).
// (2) Move every coordinate and every velocity along its slope for the length of the step. Every slope
//     must be the one of the START of the step: mind the order in which you overwrite q and v.
// (3) Tell the system its state changed (stateChanged()) and advance its clock (setTime) by h.
// Check: on ẍ = −ω²x one step is the first-degree Taylor polynomial of the exact rotation and multiplies
// the energy by exactly 1 + (ωh)²; a pinned coordinate under a force stays put; halving h halves the
// error after a fixed time (first order).
// *****
void explicitEulerStep(SecondOrderSystem& system, Real h, Workspace& w);

// ***** PART-2: symplectic (semi-implicit) Euler (Lobb notes, "simple loop"; CMU asst4 pendulum) *****
// One step of length h [s] of a second-order system: positions q [m], velocities v [m/s], accelerations
// from the forces at the start of the step.
// (1) Get the acceleration at the start of the step.
// (2) Update both velocity and position, in the order that makes the method symplectic: which changes
//     first, and which velocity then moves the position? (The other order is explicit Euler, whose
//     energy grows every step: Lobb's "simple loop" explains the difference.)
// (3) Tell the system its state changed and advance its clock by h.
// (ode/step_helpers.h has two helpers the other in-place methods use: startInPlace() does the
// bookkeeping and step (1), finishInPlace() step (3).)
// Check: on a spring the energy stays bounded over thousands of steps; first order in h.
// *****
void symplecticEulerStep(SecondOrderSystem& system, Real h, Workspace& w);

// ***** PART-7: midpoint, second-order Runge–Kutta (Lobb notes, "ODE view": Midpoint (RK2)) *****
// One step of length h [s] of a second-order system, in place on its arrays: positions q [m], velocities
// v [m/s]; the state is s = (q, v) and its derivative f = (v, a), a = M⁻¹ F [m/s²] (acceleration()).
// (1) Get the slope at the start of the step (startInPlace() gives it, as for PART-2).
// (2) Build the trial state at the middle of the step from that slope, both its positions and its
//     velocities (two scratch arrays of the workspace, sized with Workspace::fit), and work out its time.
// (3) Get the acceleration at that trial state and time: together with the trial velocities it is the
//     slope at the middle.
// (4) Move the whole state over the full step along the middle slope; then finishInPlace().
// Check: exact under a constant acceleration (the parabola) and under one linear in t; on the oscillator
// ẍ = −ω²x one step multiplies the energy by 1 + z⁴/4 (z = ωh); halving h divides the error by 4.
// *****
void midpointStep(SecondOrderSystem& system, Real h, Workspace& w);

/// Velocity Verlet: q += h v + h²a/2; v_half = v + h a/2; v = v_half + h a(q_new, v_half)/2.
/// Forces that depend on v see the half-step velocity (exact for position-only forces).
void velocityVerletStep(SecondOrderSystem& system, Real h, Workspace& w);

/// What position Verlet remembers between steps: q(t − h), and the (q, v, h) it produced last, so that
/// it notices when someone else changed the state (collision, mouse drag, reset, new dt) and restarts.
struct VerletHistory {
  std::vector<Real> previous;  ///< q(t − h)
  std::vector<Real> lastQ, lastV;
  Real lastH = 0.0;
  bool valid = false;
};

// ***** PART-6: position Verlet (Ragdoll paper §2, after Jakobsen 2001) *****
// The update (verletRecurrence in position_verlet.cpp) receives q(t), the previous positions q(t − h)
// and the acceleration at time t; it returns true once it has stepped.
// (1) New positions from the two last positions and the acceleration, for every coordinate: no velocity
//     is used (Jakobsen §3 derives the recurrence from two Taylor expansions).
// (2) The state still needs a velocity: estimate it from the positions, to second order (exact under
//     constant acceleration).
// (3) Shift the history so that the next call sees the right two positions.
// Check: under constant acceleration the positions follow the parabola exactly; the step keeps a
// spring's energy bounded; halving h divides the error by 4.
// *****
void verletStep(SecondOrderSystem& system, Real h, VerletHistory& history, Workspace& w);

struct ImplicitEulerSettings {
  int maxIterations = 200;         ///< cap on conjugate-gradient iterations per step, ≥ 1
  Real relativeTolerance = 1e-10;  ///< stop when |b − A Δv| ≤ tol·|b|; in (0, 1)
};
/// "implicit.maxIterations: …" when a setting is out of range (non-finite, tolerance ≤ 0 or ≥ 1, cap < 1).
Status validate(const ImplicitEulerSettings& settings);
struct ImplicitEulerStats {
  int iterations = 0;           ///< CG iterations of the last step
  Real relativeResidual = 0.0;  ///< |b − A Δv| / |b| of the returned Δv (recomputed, not CG's recursive estimate)
  bool converged = true;        ///< relativeResidual ≤ tolerance; false when the cap stopped CG first
  bool blockPreconditioner = false;  ///< the system gave its Jacobian's diagonal blocks (else mass Jacobi)
  /// An uncoupled system (SecondOrderSystem::uncoupledGroupSize()): each block solved directly, no CG
  /// (iterations 0; relativeResidual 0: a direct solve's residual is rounding, not computed).
  bool direct = false;
};
/// Linearised backward Euler (Baraff & Witkin 1998, eq. 16–18): solve
///   (M − h ∂f/∂v − h² ∂f/∂q) Δv = h (f₀ + h (∂f/∂q) v₀),   v ← v₀ + Δv,  q ← q₀ + h v,
/// by preconditioned conjugate gradients, matrix-free through forceDifferential(). The preconditioner is
/// block Jacobi: the inverse of A's 3×3 diagonal blocks M_i − h D_ii − h² K_ii, from the system's
/// forceJacobianDiagonalBlocks() (the mass alone, M⁻¹, when it has none). Pinned coordinates (M⁻¹ = 0)
/// are filtered out of the solve (Baraff & Witkin §5.3, the S projection): their Δv is 0. An uncoupled
/// system (SecondOrderSystem::uncoupledGroupSize() 1 or 3) has a block-diagonal A: each block is solved
/// directly instead, in one pass (stats.direct).
/// The settings must be valid (validate()); Integrator checks them when they are set.
ImplicitEulerStats implicitEulerStep(SecondOrderSystem& system, Real h, const ImplicitEulerSettings& settings,
                                     Workspace& w);

struct AdaptiveSettings {
  Real tolerance = 1e-6;     ///< local error per unit time, relative to max(1, |s_i|) [1/s]; > 0
  Real minStep = 1e-9;       ///< [s] > 0: a finite error estimate is accepted at this size whatever it is
  int maxSubsteps = 100000;  ///< per call, ≥ 1 (accepted and rejected substeps together)
};
/// "adaptive.tolerance: …" when a setting is out of range (non-finite, ≤ 0, cap < 1).
Status validate(const AdaptiveSettings& settings);
struct AdaptiveState {
  Real nextStep = 0.0;  ///< step size proposed by the controller [s]; 0 = start with the full interval
  long accepted = 0, rejected = 0, evaluations = 0;  ///< running totals
  long nonFiniteRejections = 0;  ///< running total of substeps rejected for a NaN or ±∞ error estimate
  Real shortfall = 0.0;  ///< [s] of the last call's interval left undone (0 = reached its end; see adaptiveStep)
};
/// What the step-size controller decides about one substep: keep it or not, and the size of the next try.
struct StepDecision {
  bool accept = true;
  Real next = 0.0;  ///< [s] the size of the next substep (after an accepted one) or of the retry
};

// ***** PART-8: the adaptive step-size controller (Lobb notes, "ODE view": Adaptive step size) *****
// adaptiveStep() has just taken a trial substep of size d [s] and estimated its local error `error` (a
// dimensionless max-norm, relative to max(1, |s_i|)) from the embedded pair: the notes' idea of comparing
// two solutions of different order over the same interval. Decide whether to keep the substep and propose
// the next size.
// (1) The bound is on the error per unit step: work out the error allowed for a substep of size d from
//     settings.tolerance [1/s]. Keep the substep when its error is within it; a substep at (or below)
//     settings.minStep is kept whatever its error (nothing smaller will be tried).
// (2) Work out how the error per unit step scales with d (the kept solution is 5th order: its local error
//     goes as d⁵), and from that the factor that would bring this substep's error exactly to the bound.
// (3) Be cautious: multiply that factor by a safety of 0.9, and never shrink by more than 5× nor grow by
//     more than 5× in one decision (an error of exactly 0 means: grow as much as allowed).
// (4) The proposal is d times the factor, never below settings.minStep.
// Check: an error exactly at the bound is kept and the next size is 0.9 d; a huge error is rejected and
// retried at d/5; an error below the bound grows the step. Tightening the tolerance 10⁴× makes ~10× more
// substeps (work out why from step (2)).
// *****
StepDecision controlStep(Real error, Real d, const AdaptiveSettings& settings);

/// Advances h with as many Dormand–Prince 5(4) substeps as the error control needs
/// (Dormand & Prince 1980; Hairer, Nørsett & Wanner, Solving ODEs I, §II.5). The embedded 4th-order
/// solution estimates the local error e of each substep; a substep of size δ is accepted when
/// controlStep() (PART-8) accepts it and proposes the next size ("error per unit step", so the global
/// error stays ≲ tolerance × duration). The notes' step doubling is the same idea with two half steps in
/// place of the embedded pair.
/// A substep whose error estimate is not finite (NaN or ±∞ in a stage) is rejected and retried at a fifth
/// of its size; it is never committed. The call ends early, with the state and the system's time at the
/// last accepted substep and `state.shortfall` = the time left, when maxSubsteps substeps were spent or
/// a non-finite estimate persists down to minStep: state and clock always agree.
void adaptiveStep(OdeSystem& system, Real h, const AdaptiveSettings& settings, AdaptiveState& state, Workspace& w);

/// A step of a fixed-step schedule: its size [s] and the time it ends at [s].
struct DueStep {
  Real h = 0.0;
  Real end = 0.0;
};
/// Scenes that integrate with their own step h while the runner's clock advances by its dt (the
/// oscillator and orbit scenes): the next step of size h starting at time t that has fallen due by the
/// clock time `until` (t + h ≤ until), never passing `stopAt`: the step that would cross stopAt is
/// shortened to end on it exactly, so a comparison at stopAt is taken at stopAt and not up to h before.
/// nullopt when no step is due (or t has reached stopAt). Times are compared with a tolerance of 1e-9 h.
std::optional<DueStep> nextDueStep(Real t, Real h, Real until, Real stopAt);

/// One object that steps a SecondOrderSystem with the method chosen by name; owns the workspace and
/// the per-method memory (Verlet history, adaptive step size). Scenes keep one per system.
class Integrator {
 public:
  explicit Integrator(IntegratorKind kind = IntegratorKind::SymplecticEuler) : kind_(kind) {}

  IntegratorKind kind() const { return kind_; }
  /// Switches method; forgets the per-method memory.
  void setKind(IntegratorKind kind);
  /// Forgets the per-method memory (call after a reset of the system).
  void reset();

  /// Advances the system by h [s] and its time by h (adaptive: by h − adaptiveState().shortfall, which is
  /// 0 unless its substep cap or a persistent non-finite state stopped it; the time always matches the state).
  void step(SecondOrderSystem& system, Real h);

  /// Settings of implicit Euler and of the adaptive method; an invalid one is refused with a message that
  /// names the field, and the previous settings stay.
  Status setImplicitSettings(const ImplicitEulerSettings& settings);
  Status setAdaptiveSettings(const AdaptiveSettings& settings);
  const ImplicitEulerSettings& implicitSettings() const { return implicitSettings_; }
  const AdaptiveSettings& adaptiveSettings() const { return adaptiveSettings_; }
  const ImplicitEulerStats& lastImplicitStats() const { return implicitStats_; }
  const AdaptiveState& adaptiveState() const { return adaptive_; }
  /// [s] of the last step's h left undone: adaptive's shortfall, 0 for every other method.
  Real lastShortfall() const { return kind_ == IntegratorKind::Adaptive ? adaptive_.shortfall : 0.0; }

 private:
  IntegratorKind kind_;
  ImplicitEulerSettings implicitSettings_;
  AdaptiveSettings adaptiveSettings_;
  Workspace work_;
  VerletHistory verlet_;
  AdaptiveState adaptive_;
  ImplicitEulerStats implicitStats_;
};

}  // namespace pba::ode
