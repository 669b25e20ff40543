// Particles lab, scene "oscillator": the spring oscillator ẍ = −x (ω = 1, x₀ = 1, v₀ = 0) under every
// integrator side by side against the exact solution (Lobb notes, "ODE view"). Each panel is a phase
// portrait (x right, v up): the exact orbit is the grey unit circle; Euler spirals outward (energy × 1 + h²
// per step), symplectic Euler and the Verlets stay on a nearby ellipse, RK4 hugs the circle, implicit
// Euler spirals inward. Below, the energy of each method over time.
#include <cmath>
#include <deque>
#include <memory>

#include "app/scene_registry.h"
#include "common.h"
#include "physics/ode/oscillator.h"

namespace {
using namespace pba;

constexpr int kColumns = 4;
constexpr Real kPanel = 3.0;   // [m] spacing of the phase-plot panels in the scene
constexpr std::size_t kTrail = 2000;  // samples kept per trajectory
constexpr Color kMethodColors[] = {colors::kRed,    colors::kBlue,  colors::kGreen, colors::kPurple,
                                   colors::kOrange, colors::kYellow, colors::kDark,  colors::kGrey};

class OscillatorScene final : public app::Scene {
 public:
  OscillatorScene() {
    params_.real("h", &h_, 0.001, 0.5, "s",
                 "Integrator step h. ωh is what matters: Euler's energy grows by 1 + (ωh)² per step. Typical 0.1.")
        .logarithmic();
    params_.real("end_time", &endTime_, 1.0, 200.0, "s",
                 "The methods stop here and the error metric is taken against the closed form. 3 periods ≈ 18.85 s.")
        .needsReset();
    lab::addIntegratorParam(params_, &selected_, " Here: which method the energy/error metrics report.");
  }

  std::string description() const override {
    return "Every integrator on the spring oscillator (ω = 1): watch Euler spiral outward in phase space while "
           "symplectic Euler and RK4 stay on the exact circle.";
  }
  Real defaultDt() const override { return 1.0 / 60.0; }

  void reset() override {
    methods_.clear();
    for (ode::IntegratorKind k : ode::kAllIntegrators) {
      Method m{std::make_unique<ode::HarmonicOscillator>(), ode::Integrator(k), {}};
      m.integrator.adaptiveSettings.tolerance = 1e-6;
      methods_.push_back(std::move(m));
    }
    time_ = 0.0;
    accumulator_ = 0.0;
    record();
  }

  void step(Real dt) override {
    accumulator_ += dt;
    rate_.start();
    std::size_t updates = 0;
    while (accumulator_ >= h_ && time_ + 0.5 * h_ < endTime_) {
      accumulator_ -= h_;
      for (Method& m : methods_) m.integrator.step(*m.system, h_);
      time_ += h_;
      updates += methods_.size();
      record();
    }
    rate_.stop(updates);
  }

  void draw(DebugDraw& d) const override {
    for (std::size_t i = 0; i < methods_.size(); ++i) {
      const Vec3 c = panelCenter(i);
      const Color color = kMethodColors[i];
      d.circle(c, Vec3(0, 0, 1), 1.0, colors::kGrey);  // exact orbit (radius √(2E) = 1)
      d.line(c - Vec3(1.3, 0, 0), c + Vec3(1.3, 0, 0), colors::kGrey);
      d.line(c - Vec3(0, 1.3, 0), c + Vec3(0, 1.3, 0), colors::kGrey);
      const auto& trail = methods_[i].trail;
      for (std::size_t k = 1; k < trail.size(); ++k) d.line(c + clampPhase(trail[k - 1]), c + clampPhase(trail[k]), color);
      const ode::HarmonicOscillator& s = *methods_[i].system;
      d.sphere(c + clampPhase({s.positions()[0], s.velocities()[0]}), 0.06, color);
      d.sphere(c + clampPhase({s.exactPosition(time_), s.exactVelocity(time_)}), 0.04, colors::kGrey);
      char label[96];
      std::snprintf(label, sizeof label, "%s  E/E0 = %.3g", std::string(ode::integratorName(methods_[i].integrator.kind())).c_str(),
                    s.energy() / 0.5);
      d.text(c + Vec3(-1.3, 1.45, 0), label, selected(i) ? colors::kRed : colors::kDark);
    }
    // Energy plot below the panels: E/E₀ over time, one polyline per method (clipped to [0, 4]).
    const Vec3 origin(-1.4, -3.8, 0.0);
    const Real width = kColumns * kPanel, tScale = width / endTime_;
    d.line(origin, origin + Vec3(width, 0, 0), colors::kDark);
    d.line(origin, origin + Vec3(0, 2.0, 0), colors::kDark);
    d.line(origin + Vec3(0, 0.5, 0), origin + Vec3(width, 0.5, 0), colors::kGrey);  // E/E₀ = 1
    d.text(origin + Vec3(-0.1, 2.1, 0), "E/E0 (1 at the grey line)", colors::kDark);
    for (std::size_t i = 0; i < methods_.size(); ++i) {
      const auto& e = methods_[i].energy;
      for (std::size_t k = 1; k < e.size(); ++k) {
        auto pt = [&](std::size_t j) {
          return origin + Vec3(e[j].x * tScale, 0.5 * std::clamp(e[j].y, 0.0, 4.0), 0.0);
        };
        d.line(pt(k - 1), pt(k), kMethodColors[i]);
      }
    }
  }

  nlohmann::json metrics() const override {
    const Method& m = methods_[index(selected_)];
    nlohmann::json j = lab::baseMetrics(selected_, 1, m.system->energy(), 0.5, rate_);
    j["time_s"] = time_;
    j["error"] = errorOf(m);
    for (const Method& other : methods_) {
      const std::string name(ode::integratorName(other.integrator.kind()));
      j["energy_" + name] = other.system->energy();
      j["error_" + name] = errorOf(other);
    }
    return j;
  }
  std::optional<std::string> nonFiniteState() const override {
    for (const Method& m : methods_) {
      if (!isFinite(m.system->positions()[0]) || !isFinite(m.system->velocities()[0]))
        return "the " + std::string(ode::integratorName(m.integrator.kind())) + " oscillator's state is not finite";
    }
    return std::nullopt;
  }
  // No energy(): the runaway guard must not stop Euler's outward spiral, which is the point here.
  std::vector<std::string> defaultPlots() const override { return {"energy_euler", "energy_symplectic-euler", "energy_rk4"}; }
  std::vector<app::Preset> presets() const override {
    return {{"Lobb: h = 0.1", {{"h", 0.1}}}, {"coarse h = 0.3", {{"h", 0.3}}}, {"fine h = 0.01", {{"h", 0.01}}},
            {"very coarse h = 0.5", {{"h", 0.5}}}};
  }

 private:
  struct Method {
    std::unique_ptr<ode::HarmonicOscillator> system;
    ode::Integrator integrator;
    std::deque<Vec2> trail;   // (x, v)
    std::deque<Vec2> energy = {};  // (t, E/E₀)
  };
  static Vec3 clampPhase(const Vec2& p) {
    const Real r = glm::length(p);
    const Vec2 q = r > 1.4 ? p * (1.4 / r) : p;  // keep runaway spirals inside the panel
    return Vec3(q.x, q.y, 0.0);
  }
  static std::size_t index(ode::IntegratorKind k) { return static_cast<std::size_t>(k); }
  bool selected(std::size_t i) const { return i == index(selected_); }
  Vec3 panelCenter(std::size_t i) const {
    return Vec3(static_cast<Real>(i % kColumns) * kPanel, (i < kColumns ? 1.0 : 0.0) * kPanel, 0.0);
  }
  Real errorOf(const Method& m) const {
    return std::hypot(m.system->positions()[0] - m.system->exactPosition(time_),
                      m.system->velocities()[0] - m.system->exactVelocity(time_));
  }
  void record() {
    for (Method& m : methods_) {
      m.trail.push_back({m.system->positions()[0], m.system->velocities()[0]});
      m.energy.push_back({time_, m.system->energy() / 0.5});
      if (m.trail.size() > kTrail) m.trail.pop_front();
      if (m.energy.size() > kTrail) m.energy.pop_front();
    }
  }

  Real h_ = 0.1;
  Real endTime_ = 3.0 * 2.0 * kPi;
  ode::IntegratorKind selected_ = ode::IntegratorKind::Rk4;
  std::vector<Method> methods_;
  Real time_ = 0.0, accumulator_ = 0.0;
  lab::UpdateRate rate_;
};

}  // namespace

PBA_REGISTER_SCENE("ODE", "oscillator", OscillatorScene);
