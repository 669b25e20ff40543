// IK lab, scene "comparison": the same chain solved by every iterative method of the library's
// solver table (CCD, FABRIK, Jacobian transpose, pseudo-inverse, DLS, SDLS, gradient descent with
// Armijo backtracking, L-BFGS) toward the same moving goal (IK slides, "Comparison"; Workbook §2.6).
// Every method runs as published by default: no step clamp, no line search of the Jacobian methods,
// no restarts (the panel's max_joint_step, jacobian_line_search and restarts turn them on).
// Each method has its own colour; the chains stand side by side (or overlaid as ghosts on one base),
// and a window on the right plots each method's residual after every iteration of the last solve
// (log scale, one line per method) — the convergence curves of the methods, live. The metrics
// residual_<method> and iterations_<method> can also be plotted by the runner.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "app/window/overlay_window.h"

#include "ik_scene.h"

namespace pba::lab {

using namespace pba::ik;
namespace {

struct Method {
  SolverKind kind;
  Color color;
};
// The palette's yellow, orange and pink read faintly on white panels and a projector: darker shades,
// each at least 3:1 in contrast against white (tests/labs/ik_comparison_legend_test.cpp).
constexpr Color kDarkGold{0.72f, 0.52f, 0.0f, 1.0f};
constexpr Color kDeepOrange{0.90f, 0.45f, 0.05f, 1.0f};
constexpr Color kDeepPink{0.84f, 0.22f, 0.52f, 1.0f};
// Each method's colour (the switch has no default: a new SolverKind must get one, or -Wswitch says so).
Color colorOf(SolverKind kind) {
  switch (kind) {
    case SolverKind::Analytic:
      return colors::kDark;
    case SolverKind::Ccd:
      return colors::kRed;
    case SolverKind::Fabrik:
      return colors::kGreen;
    case SolverKind::JacobianTranspose:
      return kDeepOrange;
    case SolverKind::PseudoInverse:
      return kDarkGold;
    case SolverKind::DampedLeastSquares:
      return colors::kBlue;
    case SolverKind::SelectivelyDamped:
      return colors::kPurple;
    case SolverKind::GradientDescent:
      return colors::kTeal;
    case SolverKind::Lbfgs:
      return kDeepPink;
  }
  return colors::kDark;
}
// Every method of the solver table except the closed-form one (it applies to 1–2 links only).
std::vector<Method> comparedMethods() {
  std::vector<Method> methods;
  for (const SolverInfo& s : solverTable())
    if (s.value != SolverKind::Analytic) methods.push_back({s.value, colorOf(s.value)});
  return methods;
}
const std::vector<Method> kMethods = comparedMethods();
constexpr Real kPlotFloor = -7.0;  // [log10 m] bottom of the residual plot
constexpr Real kSpacing = 0.8;     // [chain lengths] between neighbouring bases
// The runner's default camera yaw (graphics/camera.h, OrbitCamera::yaw): the row of chains, their
// bending plane and the plot face the default view, so nothing is foreshortened on a projector.
constexpr Real kViewYaw = 0.6;

enum class Layout { Overlay, SideBySide };
constexpr auto kLayoutNames = enumNames<Layout>({{Layout::Overlay, "overlay"}, {Layout::SideBySide, "side-by-side"}});
enum class CompareJoint { Hinge, Ball };
constexpr auto kCompareJointNames =
    enumNames<CompareJoint>({{CompareJoint::Hinge, "hinge"}, {CompareJoint::Ball, "ball"}});
enum class ComparePath { Figure8, Mouse };
constexpr auto kComparePathNames =
    enumNames<ComparePath>({{ComparePath::Figure8, "figure8"}, {ComparePath::Mouse, "mouse"}});

class ComparisonScene final : public app::Scene {
 public:
  ComparisonScene() {
    options_.maxIterations = 60;
    options_.recordHistory = true;
    params_.integer("links", &desc_.links, 2, 50, "", "Links of every chain. Typical 8.").needsReset();
    params_
        .choiceEnum("joint", &joint_, kCompareJointNames,
                    "Joint type of every link (hinges alternate z/y axes; FABRIK handles hinges poorly: compare).")
        .needsReset();
    params_.choiceEnum(
        "layout", &layout_, kLayoutNames,
        "Chains overlaid on one base as ghosts of one another (compact, best on a projector), or side by side.");
    params_.integer("max_iterations", &options_.maxIterations, 1, 1000, "",
                    "Iteration cap per solve, for every method. Typical 60.");
    params_
        .real("tolerance", &options_.tolerance, 1e-6, 0.1, "m", "Success tolerance, for every method. Typical 1e-4 m.")
        .logarithmic();
    params_.real("damping", &options_.damping, 0.0, 1.0, "m", "Lambda of DLS. Typical 0.05 m.");
    params_.choiceEnum("line_search", &options_.lineSearch, lineSearchNames(),
                       "Step length of gradient descent: backtracking (Armijo, the default here: golden-section costs "
                       "~30 FK per step), golden, or fixed (asst4's plain method, gradient_step 0.2).");
    declareMethodOptions(params_, options_, false);
    params_.flag("from_rest", &options_.fromRest,
                 "Start every solve from the rest pose (the plot then shows full convergence curves every frame).");
    params_.choiceEnum("path", &path_, kComparePathNames,
                       "How the goal moves: along a figure-8, or only where the mouse or the arrow keys put it.");
    params_.real("path_speed", &speed_, 0.0, 2.0, "Hz", "Laps per second of the goal's figure-8. Typical 0.25 Hz.");
    options_.lineSearch = LineSearch::Backtracking;
    desc_.links = 8;
    desc_.axes = HingeAxes::Alternating;
    options_.fromRest = true;
  }
  std::string description() const override {
    return "Eight methods, eight identical chains, one goal: watch the residual-per-iteration curves on the right (log "
           "scale) and the poses.";
  }
  void reset() override {
    ChainDesc d = desc_;
    d.joint = joint_ == CompareJoint::Hinge ? JointType::Hinge : JointType::Ball;
    rig_ = buildIkChain(d).value();
    // Stand the chain up (+x → +y) and turn it to face the default view.
    rig_.skeleton.joint(0).restRotation = facing() * glm::angleAxis(kPi / 2.0, Vec3(0, 0, 1));
    poses_.assign(kMethods.size(), rig_.skeleton.restPose());
    results_.assign(kMethods.size(), SolveResult{});
    workspaces_.resize(kMethods.size());
    time_ = 0.0;
    goal_ = pathGoal(0.0);
    step(0.0);
  }
  void step(Real dt) override {
    time_ += dt;
    if (!dragging_ && path_ == ComparePath::Figure8) goal_ = pathGoal(2.0 * kPi * speed_ * time_);
    solveAll();
  }
  void draw(DebugDraw& d) const override {
    const Real L = desc_.totalLength, r = std::clamp(0.08 * L / desc_.links, 0.006, 0.04);
    for (size_t m = 0; m < kMethods.size(); ++m) {
      const Vec3 base = baseOf(m);
      const std::vector<Frame> f = forwardKinematics(rig_.skeleton, poses_[m]);
      const Color c = kMethods[m].color;
      for (int j = 1; j < rig_.skeleton.jointCount(); ++j)
        d.capsule(base + f[static_cast<size_t>(rig_.skeleton.joint(j).parent)].position,
                  base + f[static_cast<size_t>(j)].position, r, c);
      d.capsule(base + f.back().position, base + effectorPosition(rig_.effectors[0], f), r, c);
      d.sphere(base, 2.0 * r, colors::kDark);
      if (layout_ == Layout::SideBySide || m == 0) d.sphere(base + goal_, 2.5 * r, colors::kDark);
      if (layout_ == Layout::SideBySide) {  // a name under each chain (overlaid: the plot's legend)
        char label[96];
        std::snprintf(label, sizeof label, "%s: %d it", solverName(kMethods[m].kind), results_[m].iterations);
        d.text(base + facing() * Vec3(-0.15 * L, -0.06 * L, 0.2 * L), label, c);
      }
    }
  }
  bool wantsOverlay() const override { return true; }
  void overlayUi(const app::ScreenRect& column) override { plotWindow(column); }
  nlohmann::json metrics() const override {
    nlohmann::json j = {{"links", desc_.links}, {"residual_max", 0.0}};
    Real worst = 0.0;
    for (size_t m = 0; m < kMethods.size(); ++m) {
      const std::string n = solverName(kMethods[m].kind);
      j["residual_" + n] = results_[m].positionResidual;
      j["iterations_" + n] = results_[m].iterations;
      j["status_" + n] = statusName(results_[m].status);
      j[n + "_solve_us"] = results_[m].seconds * 1e6;
      worst = std::max(worst, results_[m].positionResidual);
    }
    j["residual_max"] = worst;
    return j;
  }
  // The residual window on the right is the plot of this scene; no runner plot by default.
  std::vector<std::string> defaultPlots() const override { return {}; }
  std::optional<std::string> nonFiniteState() const override {
    for (size_t m = 0; m < poses_.size(); ++m)
      for (Real v : poses_[m].dofs)
        if (!isFinite(v))
          return std::string("a joint angle of the ") + solverName(kMethods[m].kind) + " chain is not finite";
    return std::nullopt;
  }
  std::optional<app::PickHit> pick(const app::Ray& ray) const override {
    return app::pickSphere(ray, baseOf(0) + goal_, 0.1 * desc_.totalLength, 0);
  }
  void drag(int, const Vec3& target) override {
    dragging_ = true;
    goal_ = target - baseOf(0);
  }
  void release(int) override { dragging_ = false; }
  /// The arrow keys move the one goal of every chain; it then stays put (path: mouse).
  bool nudge(const Vec3& delta) override {
    goal_ += delta;
    path_ = ComparePath::Mouse;
    return true;
  }
  /// A drag or nudge while paused: every method solves toward the goal where it is now.
  void refresh() override { solveAll(); }
  std::vector<app::DragHandle> dragHandles() const override { return {{0, baseOf(0) + goal_}}; }
  /// Each method's colour with its iterations, final residual and status: the key to the chains and
  /// to the curves, kept on screen while Tab hides the panels.
  std::vector<app::LegendEntry> legend() const override {
    std::vector<app::LegendEntry> out;
    for (size_t m = 0; m < kMethods.size(); ++m) {
      char text[96];
      std::snprintf(text, sizeof text, "%-6s %3d it  %.1e m  %s", solverName(kMethods[m].kind), results_[m].iterations,
                    results_[m].positionResidual, statusName(results_[m].status));
      out.push_back({kMethods[m].color, text});
    }
    out.push_back({colors::kDark, "goal (black ball): drag it"});
    return out;
  }
  Real nudgeStep() const override { return 0.03 * desc_.totalLength; }

 private:
  void solveAll() {
    for (size_t m = 0; m < kMethods.size(); ++m) {
      std::vector<Effector> effectors = rig_.effectors;
      effectors[0].targetPosition = goal_;  // chains are solved at the origin and drawn at their base
      SolveOptions o = options_;
      o.solver = kMethods[m].kind;
      results_[m] = solve(rig_.skeleton, poses_[m], effectors, o, workspaces_[m]);
    }
  }
  /// The goal on the figure-8 at `phase` [rad], relative to the chains' base.
  Vec3 pathGoal(Real phase) const {
    const Real L = desc_.totalLength;
    return facing() *
           (L * Vec3(0.35 * std::sin(phase), 0.6 + 0.2 * std::sin(2.0 * phase), 0.25 + 0.15 * std::cos(phase)));
  }
  static Quat facing() { return glm::angleAxis(kViewYaw, Vec3(0, 1, 0)); }
  Vec3 baseOf(size_t m) const {
    if (layout_ == Layout::Overlay) return Vec3(0.0);
    return facing() * Vec3((Real(m) - 0.5 * Real(kMethods.size() - 1)) * kSpacing * desc_.totalLength, 0.0, 0.0);
  }
  /// Residual after each iteration of the last solve, log10 scale, one curve per method, with the
  /// tolerance as a dark line and a legend (iterations, final residual, status).
  void plotWindow(const app::ScreenRect& column) const {
    app::beginColumnWindow(column, "Residual per iteration (log scale)");
    size_t longest = 2;
    Real top = -1.0;
    for (const SolveResult& r : results_) {
      longest = std::max(longest, r.residualHistory.size());
      for (Real v : r.residualHistory) top = std::max(top, std::ceil(std::log10(std::max(v, 1e-12))));
    }
    const app::PlotArea area("1e-7", 0.3f, 9.0f);
    ImDrawList* draw = area.draw();
    auto point = [&](Real i, Real residual) {
      const Real y = std::clamp((std::log10(std::max(residual, 1e-12)) - kPlotFloor) / (top - kPlotFloor), 0.0, 1.0);
      return area.at(i / Real(longest - 1), y);
    };
    const auto rgba = app::imguiColor;
    const ImU32 grid = ImGui::GetColorU32(ImVec4(0.6f, 0.6f, 0.62f, 0.6f));
    for (Real e = kPlotFloor; e <= top; e += 1.0) {
      const ImVec2 a = point(0, std::pow(10.0, e)), b = point(Real(longest - 1), std::pow(10.0, e));
      draw->AddLine(a, b, grid);
      char tick[16];
      std::snprintf(tick, sizeof tick, "1e%.0f", e);
      area.tick(a, tick, ImGui::GetColorU32(ImGuiCol_TextDisabled));
    }
    draw->AddLine(point(0, options_.tolerance), point(Real(longest - 1), options_.tolerance), rgba(colors::kDark),
                  1.5f);
    for (size_t m = 0; m < kMethods.size(); ++m) {
      const std::vector<Real>& hist = results_[m].residualHistory;
      std::vector<ImVec2> line;
      for (size_t i = 0; i < hist.size(); ++i) line.push_back(point(Real(i), hist[i]));
      area.line(line, rgba(kMethods[m].color), 0.15f * area.font());
    }
    area.reserve();
    ImGui::TextDisabled("0 … %zu iterations; black: tolerance", longest - 1);
    ImGui::End();
  }

  ChainDesc desc_;
  CompareJoint joint_ = CompareJoint::Ball;
  Layout layout_ = Layout::Overlay;
  ComparePath path_ = ComparePath::Figure8;
  SolveOptions options_;
  Real speed_ = 0.25;
  Rig rig_;
  std::vector<Pose> poses_;
  std::vector<SolveResult> results_;
  std::vector<SolveWorkspace> workspaces_;  // one per method: each keeps its method between solves
  bool dragging_ = false;
  Vec3 goal_{0.0};
  Real time_ = 0.0;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Chains", "comparison", pba::lab::ComparisonScene);
