// Particles lab, scene "oscillator": the spring oscillator ẍ = −x (ω = 1, x₀ = 1, v₀ = 0) under every
// integrator side by side against the exact solution (Lobb notes, "ODE view"). Each panel is a phase
// portrait (x right, v up): the exact orbit is the grey unit circle; Euler spirals outward (energy × 1 + h²
// per step), symplectic Euler and the Verlets stay on a nearby ellipse, RK4 hugs the circle, implicit
// Euler spirals inward. A 2-D plot beside the portraits (the scene's own window in the right-hand column)
// shows the energy of each method over time.
//
// Time: every method steps with the scene's own h (the parameter), not the runner's dt. The runner's dt
// advances the scene's clock; h-steps are taken as they fall due on that clock (ode::nextDueStep), and
// the step that would pass end_time is shortened to end there, so the error metric is taken against the
// closed form at end_time exactly (3 periods with h = 0.1: 188 steps of 0.1 s and one of 0.0496 s).
#include <cmath>
#include <deque>
#include <memory>
#include <string>

#include "app/runner/scene_registry.h"
#include "app/window/overlay_window.h"
#include "common.h"
#include "physics/ode/oscillator.h"

namespace pba::lab {
namespace {

// The figure is a 3 × 3 grid facing the camera (preferredView frames it to fill the view between the
// control panel and the energy plot's column): eight phase portraits in rows of three, the ninth cell
// (bottom right) empty. Nearly square, it keeps the portraits as large as the free area allows.
constexpr int kColumns = 3;
constexpr int kRows = 3;
constexpr Real kPanel = 3.4;            // [m] horizontal spacing of the cells in the scene
constexpr Real kPanelHeight = 3.7;      // [m] vertical spacing (room for the labels above and below)
constexpr Real kPhaseLimit = 1.4;       // [m] half-size of a cell; |(x, v)| beyond it is drawn at the rim
constexpr Real kBottom = 0.6;           // [m] lowest cell edge above the ground (its label sits below it)
constexpr Real kFacingYaw = 0.6;        // [rad] the figure faces the lab's default camera (OrbitCamera::yaw)
constexpr std::size_t kTrail = 2000;    // samples kept per trajectory
constexpr double kEnergyPlotTop = 4.0;  // E/E₀ at the top of the energy plot (Euler's growth is clipped there)
constexpr Color kMethodColors[] = {colors::kRed,    colors::kBlue,   colors::kGreen, colors::kPurple,
                                   colors::kOrange, colors::kYellow, colors::kDark,  colors::kGrey};

class OscillatorScene final : public app::Scene {
 public:
  OscillatorScene() {
    params_
        .real("h", &h_, 0.001, 0.5, "s",
              "Integrator step h of every method (the runner's dt only paces the clock on which h-steps fall "
              "due; set coarse steps here, --set h=0.3). ωh is what matters: Euler's energy grows by 1 + (ωh)² "
              "per step. Typical 0.1.")
        .logarithmic();
    params_
        .real("end_time", &endTime_, 1.0, 200.0, "s",
              "The methods stop here (the last step is shortened to end exactly here) and the error metric "
              "sqrt(dx² + dv²) is taken against the closed form. 3 periods ≈ 18.85 s.")
        .needsReset();
    lab::addIntegratorParam(params_, &selected_, " Here: which method the energy/error metrics report.");
    params_.flag("only_selected", &onlySelected_,
                 "Step only the selected integrator; the other portraits stay at the start (one method's "
                 "cost and code alone, e.g. to time it).");
  }

  std::string description() const override {
    return "Every integrator on the spring oscillator (ω = 1): watch Euler spiral outward in phase space while "
           "symplectic Euler and RK4 stay on the exact circle.";
  }
  Real defaultDt() const override { return 1.0 / 60.0; }

  void reset() override {
    methods_.clear();
    for (ode::IntegratorKind k : ode::kAllIntegrators) {
      Method m{ode::HarmonicOscillator(), ode::Integrator(k), {}};
      (void)m.integrator.setAdaptiveSettings({.tolerance = 1e-6});  // valid: a constant
      methods_.push_back(std::move(m));
    }
    time_ = 0.0;
    clock_ = 0.0;
    record();
  }

  void step(Real dt) override {
    clock_ += dt;
    rate_.start();
    std::size_t updates = 0;
    while (const std::optional<ode::DueStep> due = ode::nextDueStep(time_, h_, clock_, endTime_)) {
      for (std::size_t i = 0; i < methods_.size(); ++i) {
        if (onlySelected_ && !selected(i)) continue;
        Method& m = methods_[i];
        m.integrator.step(m.system, due->h);
        // The schedule's end time exactly (no rounding drift), unless the method fell short of it.
        if (m.integrator.lastShortfall() == 0.0) m.system.setTime(due->end);
      }
      time_ = due->end;
      updates += onlySelected_ ? 1 : methods_.size();
      record();
    }
    rate_.stop(updates);
  }

  void draw(DebugDraw& d) const override {
    // Eight phase portraits in rows of three, all above the ground (y > 0) and in a vertical plane
    // turned to face the lab's default camera yaw.
    for (std::size_t i = 0; i < methods_.size(); ++i) {
      const Vec3 c = panelCenter(i);
      const Color color = kMethodColors[i];
      d.circle(c, facingNormal(), 1.0, colors::kGrey);  // exact orbit (radius √(2E) = 1)
      d.line(c - kPhaseLimit * right(), c + kPhaseLimit * right(), colors::kGrey);
      d.line(c - kPhaseLimit * kUp, c + kPhaseLimit * kUp, colors::kGrey);
      const auto& trail = methods_[i].trail;
      for (std::size_t k = 1; k < trail.size(); ++k) d.line(c + onPanel(trail[k - 1]), c + onPanel(trail[k]), color);
      const ode::HarmonicOscillator& s = methods_[i].system;
      d.sphere(c + onPanel({s.positions()[0], s.velocities()[0]}), 0.07, color);
      d.sphere(c + onPanel({s.exactPosition(time_), s.exactVelocity(time_)}), 0.05, colors::kGrey);
      // The selected method is highlighted, not alarmed: red means danger (the guard, a violated limit).
      const Color labelColor = selected(i) ? colors::kBlue : colors::kDark;
      const std::string name(ode::integratorName(methods_[i].integrator.kind()));
      d.text(c + (kPhaseLimit + 0.15) * kUp - kPhaseLimit * right(), selected(i) ? name + "  (selected)" : name,
             labelColor);
      char energy[48];
      std::snprintf(energy, sizeof energy, "E/E0 = %.3g", s.energy() / 0.5);
      d.text(c - (kPhaseLimit + 0.05) * kUp - kPhaseLimit * right(), energy, labelColor);
    }
    // What the figure shows, above the grid: the step and the methods' time against end_time.
    char header[128];
    std::snprintf(header, sizeof header, "h = %.3g s (every method)   t = %.2f / %.2f s%s", h_, time_, endTime_,
                  time_ >= endTime_ ? "  (end: error taken here)" : "");
    d.text(panelCenter(0) + (kPhaseLimit + 0.75) * kUp - kPhaseLimit * right(), header, colors::kDark);
  }

  /// E/E₀ of every method over t, a 2-D plot in the right-hand column (its own window, docked above the
  /// runner's plots): the eight curves in the portraits' colours against the grey line E/E₀ = 1.
  bool wantsOverlay() const override { return true; }
  void overlayUi(const app::ScreenRect& column) override { energyPlotWindow(column); }

  nlohmann::json metrics() const override {
    const Method& m = methods_[index(selected_)];
    nlohmann::json j = lab::baseMetrics(selected_, 1, m.system.energy(), 0.5, rate_);
    j["time_s"] = time_;
    j["h"] = h_;
    j["end_time"] = endTime_;
    j["error"] = errorOf(m);
    for (const Method& other : methods_) {
      const std::string name(ode::integratorName(other.integrator.kind()));
      j["energy_" + name] = other.system.energy();
      j["error_" + name] = errorOf(other);
    }
    return j;
  }
  std::optional<std::string> nonFiniteState() const override {
    for (const Method& m : methods_) {
      if (!isFinite(m.system.positions()[0]) || !isFinite(m.system.velocities()[0]))
        return "the " + std::string(ode::integratorName(m.integrator.kind())) + " oscillator's state is not finite";
    }
    return std::nullopt;
  }
  // No energy(): the runaway guard must not stop Euler's outward spiral, which is the point here.
  // The selected method's error against the closed form and its energy (the energy window plots every
  // method's; switch "integrator" to plot another here).
  std::vector<std::string> defaultPlots() const override { return {"error", "energy"}; }
  std::vector<app::Preset> presets() const override {
    return {{"Lobb: h = 0.1", {{"h", 0.1}}},
            {"coarse h = 0.3", {{"h", 0.3}}},
            {"fine h = 0.01", {{"h", 0.01}}},
            {"very coarse h = 0.5", {{"h", 0.5}}}};
  }

 private:
  struct Method {
    ode::HarmonicOscillator system;  // a value: the scene copies itself for rewind
    ode::Integrator integrator;
    std::deque<Vec2> trail;        // (x, v)
    std::deque<Vec2> energy = {};  // (t, E/E₀)
  };
  // The figure's plane: x of the phase plot along right(), v along +y.
  static Vec3 right() { return Vec3(std::cos(kFacingYaw), 0.0, -std::sin(kFacingYaw)); }
  static Vec3 facingNormal() { return Vec3(std::sin(kFacingYaw), 0.0, std::cos(kFacingYaw)); }
  static Vec3 onPanel(const Vec2& p) {
    const Real r = glm::length(p);
    const Vec2 q = r > kPhaseLimit ? p * (kPhaseLimit / r) : p;  // keep runaway spirals inside the panel
    return q.x * right() + q.y * kUp;
  }
  static std::size_t index(ode::IntegratorKind k) { return static_cast<std::size_t>(k); }
  bool selected(std::size_t i) const { return i == index(selected_); }
  // Cell i of the grid, row by row from the top left.
  static Vec3 panelCenter(std::size_t i) {
    const Real column = static_cast<Real>(i % kColumns) - 0.5 * (kColumns - 1);
    const Real rowFromBottom = static_cast<Real>(kRows - 1 - static_cast<int>(i / kColumns));
    return column * kPanel * right() + (kBottom + kPhaseLimit + rowFromBottom * kPanelHeight) * kUp;
  }
  // Head-on and nearly level, the whole figure (labels and header included) filling the view's height.
  std::optional<app::CameraView> preferredView() const override {
    const Real top = kBottom + 2.0 * kPhaseLimit + (kRows - 1) * kPanelHeight + 1.0;  // header line
    const Real height = top - (kBottom - 0.5);                                        // bottom labels
    const Real pitch = 0.08;
    // 45° vertical field of view: the visible height at distance D is 2 D tan 22.5°; 5 % margin.
    const Real distance = 1.05 * height / (2.0 * std::tan(0.5 * degToRad(45.0)));
    return app::CameraView{Vec3(0.0, 0.5 * (top + kBottom - 0.5), 0.0), distance, kFacingYaw, pitch};
  }
  /// The energy window: E/E₀ ∈ [0, 4] against t ∈ [0, end_time], ticks at whole E/E₀, the grey line
  /// E/E₀ = 1 (exact), then the methods' names in their curves' colours.
  void energyPlotWindow(const app::ScreenRect& column) const {
    app::beginColumnWindow(column, "E/E0 over t, every method");
    const app::PlotArea area("4", 0.4f, 8.0f);
    ImDrawList* draw = area.draw();
    const float font = area.font();
    auto point = [&](double t, double ratio) {
      return area.at(std::clamp(t / endTime_, 0.0, 1.0), std::clamp(ratio, 0.0, kEnergyPlotTop) / kEnergyPlotTop);
    };
    const auto rgba = app::imguiColor;
    draw->AddRectFilled(point(0.0, kEnergyPlotTop), point(endTime_, 0.0), ImGui::GetColorU32(ImGuiCol_FrameBg));
    for (int tick = 0; tick <= static_cast<int>(kEnergyPlotTop); ++tick) {
      const ImVec2 a = point(0.0, tick);
      draw->AddLine(a, point(endTime_, tick), rgba(tick == 1 ? colors::kGrey : Color{0.75f, 0.76f, 0.78f, 0.6f}),
                    tick == 1 ? 0.12f * font : 1.0f);
      area.tick(a, std::to_string(tick).c_str(), ImGui::GetColorU32(ImGuiCol_Text));
    }
    for (std::size_t i = 0; i < methods_.size(); ++i) {
      std::vector<ImVec2> line;
      for (const Vec2& e : methods_[i].energy) line.push_back(point(e.x, e.y));
      area.line(line, rgba(kMethodColors[i]), (selected(i) ? 0.2f : 0.12f) * font);
    }
    area.reserve();
    ImGui::Text("t = 0 … %.3g s; grey: E/E0 = 1", endTime_);
    for (std::size_t i = 0; i < methods_.size(); ++i) {  // the key, wrapped to the window's width
      const std::string name(ode::integratorName(methods_[i].integrator.kind()));
      if (i > 0) {
        const float next =
            ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + ImGui::CalcTextSize(name.c_str()).x;
        if (next < ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
      }
      const Color c = kMethodColors[i];
      ImGui::TextColored(ImVec4(c.r, c.g, c.b, 1.0f), "%s", name.c_str());
    }
    ImGui::End();
  }
  Real errorOf(const Method& m) const {
    return std::hypot(m.system.positions()[0] - m.system.exactPosition(time_),
                      m.system.velocities()[0] - m.system.exactVelocity(time_));
  }
  void record() {
    for (Method& m : methods_) {
      m.trail.push_back({m.system.positions()[0], m.system.velocities()[0]});
      m.energy.push_back({time_, m.system.energy() / 0.5});
      if (m.trail.size() > kTrail) m.trail.pop_front();
      if (m.energy.size() > kTrail) m.energy.pop_front();
    }
  }

  Real h_ = 0.1;
  Real endTime_ = 3.0 * 2.0 * kPi;
  ode::IntegratorKind selected_ = ode::IntegratorKind::Rk4;
  bool onlySelected_ = false;
  std::vector<Method> methods_;
  Real time_ = 0.0;   ///< [s] time of the methods (the last h-step's end)
  Real clock_ = 0.0;  ///< [s] the runner's time (sum of its dt)
  lab::UpdateRate rate_;
};

}  // namespace

PBA_REGISTER_SCENE("ODE", "oscillator", OscillatorScene);

}  // namespace pba::lab
