#pragma once
// One interface for every IK method of the course texts (Workbook §2.2–2.5, IK slides, CMU asst4,
// Aristidou & Lasenby 2011, Buss & Kim 2005). A solve moves a Pose so that the effectors reach their
// goals, and reports how it stopped (IK slides, "Stopping"): success within tolerance, target
// unreachable, stalled (no progress over k iterations: a local minimum), iteration cap or time cap.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "physics/core/enum_names.h"
#include "physics/core/result.h"
#include "physics/ik/effector.h"
#include "physics/ik/skeleton.h"

namespace pba::ik {

enum class SolverKind {
  Analytic,            ///< single joint (dot & cross product) or two bones (law of cosines + pole)
  Ccd,                 ///< cyclic coordinate descent (Workbook §2.4, Algorithm 1)
  Fabrik,              ///< forward and backward reaching IK (Aristidou & Lasenby 2011), sub-bases for trees
  JacobianTranspose,   ///< Δθ = α Jᵀ Δe, α by Buss 2004 §4
  PseudoInverse,       ///< Δθ = J⁺ Δe, J⁺ from the SVD with a singular-value cut-off (Workbook §2.5)
  DampedLeastSquares,  ///< Δθ = Jᵀ (J Jᵀ + λ² I)⁻¹ Δe
  SelectivelyDamped,   ///< Buss & Kim 2005: per-singular-vector damping, clamped by γ_max = π/4
  GradientDescent,  ///< CMU asst4: descent on ½|g − e|², step by SolveOptions::lineSearch, projected on the limits
  Lbfgs,            ///< quasi-Newton L-BFGS (CMU asst4 extension; Nocedal & Wright Alg. 7.4), projected
};

/// The one table of the methods' names, in SolverKind order: menus, command-line choices, metrics
/// keys and tests all read it, so a new method is one row here (and one case in makeMethod).
/// A method's entry: `value`, its short `name` ("ccd", "dls", …: menus, --solver, metrics keys) and its
/// `description` ("Cyclic coordinate descent", …).
using SolverInfo = EnumName<SolverKind>;
std::span<const SolverInfo> solverTable();
const char* solverName(SolverKind kind);
const char* solverLongName(SolverKind kind);
bool solverFromName(const std::string& name, SolverKind* kind);
/// Every solver's short name, in SolverKind order (for menus and command-line choices).
std::vector<std::string> solverNames();

/// Step-length rule of the gradient-descent solver (CMU asst4 and its extensions).
enum class LineSearch {
  Fixed,          ///< α = SolveOptions::gradientStep every step (asst4's plain method)
  Backtracking,   ///< halve α from the quadratic model's minimiser until Armijo's sufficient decrease holds
  GoldenSection,  ///< minimise f along the direction by golden-section search (an exact line search)
};
/// "fixed", "backtracking", "golden", in LineSearch order (lineSearchNames() and the rest are the tables in
/// solve_options.cpp, physics/core/enum_names.h).
const std::vector<std::string>& lineSearchNames();
const char* lineSearchName(LineSearch search);

enum class SolveStatus {
  Success,        ///< every effector within tolerance
  Unreachable,    ///< a goal lies beyond the reach of its effector: the chain was stretched toward it
  Stalled,        ///< the residual stopped decreasing for `stallIterations` iterations (local minimum)
  IterationCap,   ///< maxIterations reached
  TimeCap,        ///< maxSeconds reached
  NotApplicable,  ///< the method cannot handle this skeleton (e.g. analytic on a 5-link chain)
  InvalidInput,   ///< bad skeleton, pose, effector or option: see SolveResult::message
};
const char* statusName(SolveStatus status);

/// Joint limits in Jacobian methods (IK slides, "Joint limits"): clamp the pose after each step, or
/// also zero the columns of DOFs sitting at a limit and pushed outward (one-sided derivative).
enum class JacobianLimitMode { Clamp, ZeroColumns };
/// "clamp", "zero_columns", in JacobianLimitMode order.
const std::vector<std::string>& jacobianLimitModeNames();

/// Where the Jacobian-family methods (JT, pinv, DLS, SDLS, gradient, L-BFGS) take J from.
enum class JacobianSource {
  Analytic,            ///< IK-3's columns a × (e − r) (jacobian.cpp): one pass over the joints
  CentralDifferences,  ///< central differences of forward kinematics (numericalJacobian, h = kJacobianStep):
                       ///< 2 FK per column, independent of IK-3 (tests grade the methods apart from it)
};
/// "analytic", "differences", in JacobianSource order.
const std::vector<std::string>& jacobianSourceNames();
inline constexpr Real kJacobianStep = 1e-6;  ///< [rad or m] h of JacobianSource::CentralDifferences

/// The settings of one solve. Defaults are the methods as their sources state them; the options
/// marked "departure" are safeguards of ours, off by default (docs/workbook/01-inverse-kinematics.md).
struct SolveOptions {
  SolverKind solver = SolverKind::DampedLeastSquares;
  Real tolerance = 1e-4;       ///< [m] > 0: success when every effector is this close
  Real angleTolerance = 1e-3;  ///< [rad] > 0: and 6-DOF effectors are this well aligned
  int maxIterations = 200;     ///< ≥ 1: iteration cap (CCD/FABRIK: passes; Jacobian: steps)
  Real maxSeconds = 0.0;       ///< [s] ≥ 0: time cap; 0 = none (never used by tests: not deterministic)
  int stallIterations =
      20;  ///< k ≥ 0: stalled when the residual has not dropped by stallRatio in k iterations; 0 = never
  Real stallRatio = 1e-3;     ///< [1] in [0, 1): relative progress that counts as progress
  bool fromRest = false;      ///< repeatability (IK slides): start every solve from the rest pose
  bool enforceLimits = true;  ///< clamp to joint limits (IK-6; CCD/FABRIK/analytic) or per limitMode
  JacobianLimitMode limitMode = JacobianLimitMode::ZeroColumns;
  JacobianSource jacobian = JacobianSource::Analytic;
  Real damping = 0.05;         ///< [m] ≥ 0: λ of DLS; typical 0.01–0.5 × the bone length
  Real singularCutoff = 1e-3;  ///< [1] in [0, 1): pinv drops singular values below cutoff · σ_max
  Real maxErrorStep = 0.0;     ///< [m] ≥ 0: clamp of each effector's error per step (Buss's D_max; Buss & Kim
                               ///< 2005 clamp the targets the same way); 0 = automatic (mean bone length)
  /// Departure (ours): [rad] ≥ 0, clamp of the largest DOF change of one JT, pinv, DLS or SDLS step
  /// (uniform scaling of the step); 0 = none, as published. SDLS always applies its own γ_max = π/4.
  Real maxJointStep = 0.0;
  /// Departure (ours): JT, pinv, DLS, SDLS halve each step until the objective decreases (JT: by
  /// Armijo's amount, from Buss's α); no acceptable step leaves the pose unchanged (a stall).
  bool jacobianLineSearch = false;
  Real orientationScale = 0.0;  ///< [m/rad] ≥ 0: weight of orientation rows; 0 = automatic (mean bone length)
  bool usePole = false;         ///< analytic two-bone: bend toward polePoint (else keep the current bend plane)
  Vec3 polePoint{0.0};          ///< [m] finite: world point the elbow should point toward (the "pole target")
  bool recordHistory = false;   ///< keep the residual and effector position of every iteration
  LineSearch lineSearch = LineSearch::GoldenSection;  ///< gradient descent's step length
  Real gradientStep = 0.2;  ///< [rad²/m²] > 0: α of LineSearch::Fixed: Δθ = −α ∇f, f in m²; stable below
                            ///< 2/λ_max(JᵀJ) (≈ 0.5 for a 1 m, 10-link chain); typical 0.05–0.5
  Real lineSearchMaxStep = 0.5;  ///< [rad] > 0: gradient descent and L-BFGS: the largest DOF change of one
                                 ///< step (the golden-section bracket; caps fixed and backtracking steps)
  int lbfgsMemory = 7;           ///< ≥ 1: pairs (s, y) L-BFGS remembers; typical 5–10
  /// Departure (IK slides, "Stopping": when stuck, randomise the pose or switch algorithm), ≥ 0, off
  /// by default. With joint limits or one-sided hinges a method can stall in a local minimum short
  /// of a reachable goal, or crawl toward it (CCD along a limit). On a stall, or a crawl too slow to
  /// finish within the cap, the solve restarts the method from a random pose inside the limits of
  /// the joints that move the effectors, at most `restarts` times, within the same maxIterations
  /// (and only while 2 × stallIterations of them remain), and returns the attempt with the smallest
  /// residual; never on an unreachable goal or a closed-form method. The random poses come from
  /// `restartSeed` alone, so a solve stays deterministic. SolveResult::restarts counts them.
  /// 0: a stall ends the solve, as the methods are published.
  int restarts = 0;
  unsigned long long restartSeed = 0x5EEDull;  ///< seed of the restart poses
  /// Departure (ours), FABRIK on hinges: in the backward pass, before a hinge relates its parent's
  /// body to the part of the tree already placed below it, that part may turn as one rigid piece
  /// about the line from the hinge's pivot to the goal of the one position effector it carries (a
  /// turn that keeps the effector on its goal and the part's shape, so the point rule allows it).
  /// The turn sets the plane the hinge bends in: of no turn and the turns that lay the plane through
  /// the parent's previous pivot, the one whose hinge-constrained pivot lies nearest that pivot (ties:
  /// the smallest turn). Without it the plane is the one the shortest-arc rule inherits, and a
  /// straight one-way hinge (a finger) whose plane faces the wrong way cannot bend toward its goal.
  /// false: the published passes.
  bool fabrikHingeTwist = false;
  /// Departure (ours), FABRIK with joint limits: when the forward pass's best rotation of a ball
  /// joint leaves its Euler limits, the joint takes the rotation inside them that best carries its
  /// points (coordinate sweeps of the exact one-angle optimum over its three angles, each clamped by
  /// IK-6), instead of IK-6's clamp of the best rotation's angles, which can land far from the best
  /// allowed rotation. false: the clamp.
  bool fabrikLimitFit = false;
  /// Departure (ours), CCD: [rad] ≥ 0, the largest turn of one joint in one pass; each joint's update
  /// (Workbook §2.4's rotation, IK-2) is cut to this angle about its own axis before the limits clamp
  /// it. On long chains with tight limits plain CCD bends the joints near the tip to their limits in
  /// the first pass (the tip curls up) and then crawls or stalls; with the cap every joint bends a
  /// little each pass and the chain curves as a whole. 0: each joint takes its full update, as published.
  Real ccdMaxTurn = 0.0;
};

/// Checks every field of the options at its boundary (ranges, finiteness, enum values); the message
/// names the field: "options.damping: must be a finite number >= 0, got -1".
Status validate(const SolveOptions& options);

struct SolveResult {
  SolveStatus status = SolveStatus::InvalidInput;
  int iterations = 0;
  Real positionResidual = 0.0;     ///< [m] largest effector distance to its goal at the end
  Real orientationResidual = 0.0;  ///< [rad] largest 6-DOF orientation error at the end
  int restarts = 0;                ///< stall recoveries used (SolveOptions::restarts)
  Real seconds = 0.0;   ///< [s] wall time of the solve (measurement only, never used for control unless maxSeconds)
  std::string message;  ///< for InvalidInput / NotApplicable
  std::vector<Real> residualHistory;            ///< [m] position residual after each iteration (recordHistory)
  std::vector<std::vector<Vec3>> effectorPath;  ///< per effector: world positions after each iteration (recordHistory)
};

namespace detail {
struct SolveStorage;
}

/// What a solve keeps for the next one, so that a warm solve allocates nothing: the working storage of
/// the skeleton, the last method (reused when the next solve asks for the same kind) and the driver's
/// lists. Own one where solves repeat (a scene, a loop), as Jolt's update takes a TempAllocator. It
/// serves one solve at a time: solves on several threads at once need one each. Its contents are never
/// state: a copy starts empty, and a solve gives the same result with a fresh workspace.
class SolveWorkspace {
 public:
  SolveWorkspace();
  ~SolveWorkspace();
  SolveWorkspace(const SolveWorkspace&);
  SolveWorkspace& operator=(const SolveWorkspace&);
  SolveWorkspace(SolveWorkspace&&) noexcept;
  SolveWorkspace& operator=(SolveWorkspace&&) noexcept;
  detail::SolveStorage& storage();  ///< for solve(); a moved-from workspace starts empty again

 private:
  std::unique_ptr<detail::SolveStorage> storage_;
};

/// Solves in place: moves `pose` toward the goals of `effectors`. Never throws; never produces NaN.
SolveResult solve(const Skeleton& skeleton, Pose& pose, const std::vector<Effector>& effectors,
                  const SolveOptions& options, SolveWorkspace& workspace);
/// The same with a workspace of its own (its storage is allocated anew: for one-off solves).
SolveResult solve(const Skeleton& skeleton, Pose& pose, const std::vector<Effector>& effectors,
                  const SolveOptions& options);

/// [m] Mean distance between a joint and its parent, effector offsets included (≥ 1e-6): the scale
/// of the automatic error clamp and orientation weight.
Real meanBoneLength(const Skeleton& skeleton, const std::vector<Effector>& effectors);
/// [m/rad] The orientation-row weight solve() uses: options.orientationScale, or the mean bone length.
Real resolvedOrientationScale(const Skeleton& skeleton, const std::vector<Effector>& effectors,
                              const SolveOptions& options);

}  // namespace pba::ik
