#include "ik_scene.h"

#include <algorithm>
#include <cmath>

#include "physics/collision/ray.h"

namespace pba::lab {

using namespace pba::ik;

namespace {
constexpr Real kJumpInterval = 1.5;  // [s] between random jumps
}  // namespace

IkScene::IkScene() { options_.recordHistory = true; }

void declareMethodOptions(app::Params& params, SolveOptions& options, bool jacobianOnly) {
  auto jacobian = [&options, jacobianOnly] { return !jacobianOnly || usesJacobian(options.solver); };
  auto stepMethod = [&options, jacobianOnly] {
    const SolverKind k = options.solver;
    return !jacobianOnly || k == SolverKind::JacobianTranspose || k == SolverKind::PseudoInverse ||
           k == SolverKind::DampedLeastSquares || k == SolverKind::SelectivelyDamped;
  };
  params
      .choiceEnum("jacobian", &options.jacobian, jacobianSourceNames(),
                  "Where the Jacobian methods take J from: analytic (IK-3's columns of each joint) or differences "
                  "(central differences of forward kinematics: 2 FK per column, slower, independent of IK-3).")
      .shownWhen(jacobian);
  params
      .angle("max_joint_step", &options.maxJointStep, 0.0, 180.0,
             "Not in the papers (our safeguard): JT, pinv, DLS and SDLS scale a step down so that no DOF turns by more "
             "than this. 0 = off, the methods as published (SDLS always applies its own gamma_max = 45 deg).")
      .shownWhen(stepMethod);
  params
      .flag("jacobian_line_search", &options.jacobianLineSearch,
            "Not in the papers (our safeguard): JT, pinv, DLS and SDLS halve a step until the residual decreases "
            "(JT: Armijo's sufficient decrease from Buss's step length). Off = the methods as published.")
      .shownWhen(stepMethod);
  auto fabrik = [&options, jacobianOnly] { return !jacobianOnly || options.solver == SolverKind::Fabrik; };
  params
      .flag("fabrik_hinge_twist", &options.fabrikHingeTwist,
            "Not in the paper (ours): FABRIK's backward pass may turn the part below a hinge about the line to its "
            "goal, so that the hinge bends toward its parent's place (a straight one-way finger finds the side it "
            "bends to). Off = the published passes.")
      .shownWhen(fabrik);
  params
      .flag("fabrik_limit_fit", &options.fabrikLimitFit,
            "Not in the paper (ours): when FABRIK's forward pass turns a ball joint beyond its limits, it takes the "
            "best rotation inside them instead of clamping the angles of the best rotation. Off = the clamp.")
      .shownWhen(fabrik);
  auto ccd = [&options, jacobianOnly] { return !jacobianOnly || options.solver == SolverKind::Ccd; };
  params
      .angle("ccd_max_turn", &options.ccdMaxTurn, 0.0, 180.0,
             "Not in the Workbook (ours): CCD turns each joint by at most this much per pass, so that on long "
             "chains with tight limits the joints near the tip do not all bend to their limits at once. 0 = off, "
             "CCD as published.")
      .shownWhen(ccd);
  params.integer(
      "restarts", &options.restarts, 0, 100, "",
      "Stall recovery, not in the papers (IK slides, 'when stuck, randomise the pose'): a stalled or crawling "
      "solve restarts from a random pose inside the limits at most this many times, within the same "
      "iteration cap, and keeps its best attempt. 0 = off: a stall ends the solve, as published.");
}

void IkScene::declareSolverParams(bool withPath) {
  // Table-driven from the library: every method it names appears in the dropdown.
  std::string methods;
  for (const SolverInfo& s : solverTable())
    methods += std::string(methods.empty() ? "" : ", ") + std::string(s.name) + " (" + std::string(s.description) + ")";
  params_.choiceEnum("solver", &options_.solver, solverNames(), "IK method: " + methods + ".");
  params_.integer("max_iterations", &options_.maxIterations, 1, 5000, "",
                  "Iteration cap per solve (CCD/FABRIK: passes; Jacobian methods: steps). Typical 100.");
  params_
      .real("tolerance", &options_.tolerance, 1e-6, 0.1, "m",
            "Success when the effector is this close to its goal. Typical 1e-4 m.")
      .logarithmic();
  params_.real("damping", &options_.damping, 0.0, 1.0, "m", "Lambda of damped least squares. Typical 0.05 m.")
      .shownWhen([this] { return options_.solver == SolverKind::DampedLeastSquares; });
  params_
      .choiceEnum("line_search", &options_.lineSearch, lineSearchNames(),
                  "Step length of gradient descent: fixed (asst4: gradient_step every step), backtracking "
                  "(Armijo's sufficient decrease) or golden (golden-section search, an exact line search).")
      .shownWhen([this] { return options_.solver == SolverKind::GradientDescent; });
  params_
      .real("gradient_step", &options_.gradientStep, 1e-4, 10.0, "rad²/m²",
            "Fixed step alpha of gradient descent: dtheta = -alpha grad f. Too large oscillates (stable below "
            "2 / largest eigenvalue of J^T J); too small crawls. Typical 0.2.")
      .logarithmic()
      .shownWhen([this] {
        return options_.solver == SolverKind::GradientDescent && options_.lineSearch == LineSearch::Fixed;
      });
  params_
      .real("cutoff", &options_.singularCutoff, 1e-6, 0.5, "",
            "Pseudo-inverse: singular values below cutoff x sigma_max are dropped (near-singular directions "
            "would give huge steps). Typical 1e-3.")
      .logarithmic()
      .shownWhen([this] { return options_.solver == SolverKind::PseudoInverse; });
  declareMethodOptions(params_, options_, true);
  params_.integer("stall_iterations", &options_.stallIterations, 0, 1000, "",
                  "Stop as 'stalled' when the residual has not dropped by 0.1 % over this many iterations (a local "
                  "minimum, IK slides). 0 = never. Typical 20.");
  params_.real("time_cap", &options_.maxSeconds, 0.0, 0.1, "s",
               "Stop a solve after this much wall time (status time_cap). 0 = no cap. Results then depend on the "
               "machine's speed.");
  params_.flag("from_rest", &options_.fromRest,
               "Repeatability: start every solve from the rest pose instead of the last pose.");
  params_.flag("limits", &options_.enforceLimits,
               "Enforce the joint limits (clamping; Jacobian methods also zero blocked columns).");
  params_
      .choiceEnum("limit_mode", &options_.limitMode, jacobianLimitModeNames(),
                  "Jacobian methods at a limit: clamp the pose after each step, or also zero the columns of DOFs "
                  "pushed against their limit (one-sided derivative, IK slides).")
      .shownWhen([this] {
        const SolverKind k = options_.solver;
        return options_.enforceLimits && (k == SolverKind::JacobianTranspose || k == SolverKind::PseudoInverse ||
                                          k == SolverKind::DampedLeastSquares || k == SolverKind::SelectivelyDamped);
      });
  if (withPath) {
    params_.choiceEnum("path", &path_, kTargetPathNames,
                       "How the goal moves: dragged with the mouse, or along a scripted path for lectures.");
    params_.real("path_speed", &pathSpeed_, 0.0, 2.0, "Hz", "Laps per second of the scripted path. Typical 0.5 Hz.");
  }
}

void IkScene::reset() {
  rig_ = build();
  pose_ = rig_.skeleton.restPose();
  liftAboveGround();
  centers_.clear();
  for (const Effector& e : rig_.effectors) centers_.push_back(e.targetPosition);
  time_ = 0.0;
  nextJump_ = 0.0;
  if (selected_ >= rig_.effectors.size()) selected_ = 0;
  rng_.seed(seed());
  boneRadius_ = std::clamp(0.12 * meanBoneLength(rig_.skeleton, rig_.effectors), 0.004, 0.05);
  step(0.0);
}

// The ground grid at y = 0 hides whatever goes below it, so a rig whose goals' paths (±1.5 path
// radii for random jumps) would dip under it is lifted, roots and goals alike.
void IkScene::liftAboveGround() {
  const std::vector<Frame> f = forwardKinematics(rig_.skeleton, pose_);
  Real lowest = 0.0;
  for (const Frame& frame : f) lowest = std::min(lowest, frame.position.y);
  for (const Effector& e : rig_.effectors) lowest = std::min({lowest, effectorPosition(e, f).y, e.targetPosition.y});
  const Real lift = groundClearance() - lowest;
  if (lift <= 0.0) return;
  for (int j = 0; j < rig_.skeleton.jointCount(); ++j)
    if (rig_.skeleton.joint(j).parent < 0) rig_.skeleton.joint(j).offset.y += lift;
  for (Effector& e : rig_.effectors) e.targetPosition.y += lift;
}

void IkScene::step(Real dt) {
  time_ += dt;
  if (!dragging_ && path_ != TargetPath::Mouse) {
    const Real w = 2.0 * kPi * pathSpeed_ * time_;
    for (size_t k = 0; k < rig_.effectors.size(); ++k) {
      if (path_ != TargetPath::RandomJumps)
        rig_.effectors[k].targetPosition = centers_[k] + pathOffset(k, w + 0.7 * Real(k));
    }
    if (path_ == TargetPath::RandomJumps && time_ >= nextJump_) {
      nextJump_ = time_ + kJumpInterval;
      std::uniform_real_distribution<Real> u(-1.0, 1.0);
      for (size_t k = 0; k < rig_.effectors.size(); ++k)
        rig_.effectors[k].targetPosition =
            centers_[k] + 1.5 * pathRadius() * Vec3(u(rng_) - 0.5, u(rng_), 0.5 * u(rng_));
    }
  }
  solveNow();
}

Vec3 IkScene::pathOffset(size_t, Real phase) const {
  const Real r = pathRadius();
  if (path_ == TargetPath::Figure8)
    return r * Vec3(std::sin(phase) - 0.5, std::sin(2.0 * phase), 0.3 * std::cos(phase));
  return r * Vec3(std::cos(phase) - 1.0, std::sin(phase), 0.3 * std::sin(phase));
}

void IkScene::solveNow() { last_ = solve(rig_.skeleton, pose_, rig_.effectors, options_, workspace_); }

nlohmann::json IkScene::metrics() const {
  return {{"solver", solverName(options_.solver)},
          {"iterations", last_.iterations},
          {"residual", last_.positionResidual},
          {"residual_rad", last_.orientationResidual},
          {"status", statusName(last_.status)},
          {"dofs", rig_.skeleton.dofCount()},
          {"limit_violation", limitViolation(rig_.skeleton, pose_)},
          {"solve_us", last_.seconds * 1e6}};
}

void IkScene::overlayUi(const app::ScreenRect& column) {
  drawJacobianWindow(computeJacobianView(rig_.skeleton, pose_, rig_.effectors, options_), options_, column);
}

std::optional<std::string> IkScene::nonFiniteState() const {
  for (Real v : pose_.dofs)
    if (!isFinite(v)) return "a joint angle is not finite";
  return std::nullopt;
}

std::optional<app::PickHit> IkScene::pick(const app::Ray& ray) const {
  std::optional<app::PickHit> best;
  for (size_t k = 0; k < rig_.effectors.size(); ++k) {
    const std::optional<Real> t =
        intersectRaySphere(ray, rig_.effectors[k].targetPosition, 2.0 * kTargetRadiusFactor * boneRadius_);
    if (t && (!best || *t < best->distance)) best = app::PickHit{static_cast<int>(k), *t, pointAt(ray, *t)};
  }
  return best;
}

void IkScene::drag(int handle, const Vec3& target) {
  if (handle < 0 || handle >= static_cast<int>(rig_.effectors.size())) return;
  dragging_ = true;
  selected_ = static_cast<size_t>(handle);
  rig_.effectors[selected_].targetPosition = target;
}

bool IkScene::nudge(const Vec3& delta) {
  if (rig_.effectors.empty()) return false;
  selected_ = std::min(selected_, rig_.effectors.size() - 1);
  rig_.effectors[selected_].targetPosition += delta;
  path_ = TargetPath::Mouse;  // the goal stays where the keys put it
  return true;
}

std::vector<app::DragHandle> IkScene::dragHandles() const {
  std::vector<app::DragHandle> out;
  for (size_t k = 0; k < rig_.effectors.size(); ++k)
    out.push_back({static_cast<int>(k), rig_.effectors[k].targetPosition});
  return out;
}

std::vector<app::LegendEntry> IkScene::legend() const {
  std::vector<app::LegendEntry> out = {{colors::kRed, "goal: drag it, or nudge it with the arrow keys"},
                                       {colors::kGreen, "effector"},
                                       {colors::kBlue, "bones"}};
  if (showLimits_) out.push_back({colors::kOrange, "joint limits"});
  if (showPath_) out.push_back({colors::kPurple, "effector path over the last solve's iterations"});
  return out;
}

namespace {
/// The name --pose-json gives an effector's point: its joint's name, or "<joint>.effector" when the
/// point sits at an offset from the joint (a chain's tip).
std::string effectorPointName(const Skeleton& s, const Effector& e) {
  const std::string& name = s.joint(e.joint).name;
  const std::string joint = name.empty() ? "joint" + std::to_string(e.joint) : name;
  return glm::length(e.localOffset) > 0.0 ? joint + ".effector" : joint;
}
}  // namespace

std::vector<app::NamedPoint> IkScene::jointPositions() const {
  std::vector<app::NamedPoint> out;
  if (rig_.skeleton.jointCount() == 0) return out;
  const std::vector<Frame> frames = forwardKinematics(rig_.skeleton, pose_);
  for (int j = 0; j < rig_.skeleton.jointCount(); ++j) {
    const std::string& name = rig_.skeleton.joint(j).name;
    out.push_back({name.empty() ? "joint" + std::to_string(j) : name, frames[static_cast<size_t>(j)].position});
  }
  for (const Effector& e : rig_.effectors)
    if (glm::length(e.localOffset) > 0.0)
      out.push_back({effectorPointName(rig_.skeleton, e), effectorPosition(e, frames)});
  return out;
}

std::vector<app::NamedPoint> IkScene::goalPositions() const {
  std::vector<app::NamedPoint> out;
  for (const Effector& e : rig_.effectors) out.push_back({effectorPointName(rig_.skeleton, e), e.targetPosition});
  return out;
}

}  // namespace pba::lab
