// Particles lab, scene "orbit": a planet on an eccentric Kepler orbit under every integrator at once.
// Energy and angular momentum are conserved exactly by the true motion; the metrics show each method's
// drift: Euler spirals out, implicit Euler falls in, the symplectic methods keep the energy bounded and
// (being built from central kicks) the angular momentum exact up to rounding.
#include <cmath>
#include <deque>
#include <limits>
#include <memory>

#include <imgui.h>

#include "app/runner/scene_registry.h"
#include "common.h"
#include "physics/ode/oscillator.h"

namespace pba::lab {
namespace {

constexpr std::size_t kOrbitTrail = 600;
// The orbital plane is y = 0 in the simulation; it is drawn this high so the ground grid hides nothing.
constexpr Vec3 kDrawOffset{0.0, 0.6, 0.0};  // [m]
constexpr int kEllipseSegments = 128;
constexpr Color kColors[] = {colors::kRed,    colors::kBlue,   colors::kGreen, colors::kPurple,
                             colors::kOrange, colors::kYellow, colors::kDark,  colors::kGrey};

class OrbitScene final : public app::Scene {
 public:
  OrbitScene() {
    params_
        .real("h", &h_, 0.001, 0.2, "s",
              "Integrator step h of every method (the period is ≈ 11 s at the default). The runner's dt only "
              "paces the clock (3× sped up) on which h-steps fall due. Typical 0.05.")
        .logarithmic();
    params_.real("speed", &speed_, 0.6, 1.35, "m/s", "Initial tangential speed at 1 m (1 = circular).").needsReset();
    lab::addIntegratorParam(params_, &selected_, " Here: which method the energy metrics report.");
  }
  std::string description() const override {
    return "A planet orbiting a sun under eight integrators at once: compare their energy and angular momentum "
           "drift.";
  }
  Real defaultDt() const override { return 1.0 / 60.0; }

  void reset() override {
    planets_.clear();
    ode::OrbitDesc desc;
    desc.velocity = Vec3(0.0, 0.0, -speed_);
    for (ode::IntegratorKind k : ode::kAllIntegrators) {
      Planet p{ode::KeplerOrbit(desc), ode::Integrator(k), {}};
      (void)p.integrator.setAdaptiveSettings({.tolerance = 1e-6});  // valid: a constant
      planets_.push_back(std::move(p));
    }
    e0_ = planets_[0].orbit.energy();
    l0_ = glm::length(planets_[0].orbit.angularMomentum());
    time_ = clock_ = 0.0;
  }
  void step(Real dt) override {
    // Steps of h as they fall due on the scene's clock (ode::nextDueStep; no end time here).
    clock_ += dt * kTimeScale;
    rate_.start();
    std::size_t updates = 0;
    while (const std::optional<ode::DueStep> due =
               ode::nextDueStep(time_, h_, clock_, std::numeric_limits<Real>::infinity())) {
      time_ = due->end;
      for (Planet& p : planets_) {
        // Stop a method that has crashed into the sun or escaped: the point is made, keep the rest going.
        if (glm::length(p.orbit.position()) < 0.05 || glm::length(p.orbit.position()) > 50.0) continue;
        p.integrator.step(p.orbit, due->h);
        ++updates;
      }
    }
    for (Planet& p : planets_) {
      p.trail.push_back(p.orbit.position());
      if (p.trail.size() > kOrbitTrail) p.trail.pop_front();
    }
    rate_.stop(updates);
  }
  void draw(DebugDraw& d) const override {
    d.sphere(kDrawOffset, 0.08, colors::kYellow);
    drawExactOrbit(d);
    for (std::size_t i = 0; i < planets_.size(); ++i) {
      const auto& t = planets_[i].trail;
      for (std::size_t k = 1; k < t.size(); ++k) d.line(t[k - 1] + kDrawOffset, t[k] + kDrawOffset, kColors[i]);
      d.sphere(planets_[i].orbit.position() + kDrawOffset, 0.06, kColors[i]);
    }
  }
  // The legend (which colour is which method, and its drift so far), in the panel under the parameters.
  void ui() override {
    if (!ImGui::BeginTable("planets", 3, ImGuiTableFlags_SizingFixedFit)) return;
    ImGui::TableSetupColumn("method");
    ImGui::TableSetupColumn("ΔE/E₀");
    ImGui::TableSetupColumn("ΔL/L₀");
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < planets_.size(); ++i) {
      const ode::KeplerOrbit& o = planets_[i].orbit;
      const Color c = kColors[i];
      const std::string name(ode::integratorName(planets_[i].integrator.kind()));
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      const float side = ImGui::GetTextLineHeight();
      ImGui::ColorButton(("##" + name).c_str(), ImVec4(c.r, c.g, c.b, 1.0f), ImGuiColorEditFlags_NoTooltip,
                         ImVec2(side, side));
      ImGui::SameLine();
      ImGui::TextUnformatted(name.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%+.2e", (o.energy() - e0_) / std::abs(e0_));
      ImGui::TableNextColumn();
      ImGui::Text("%+.2e", (glm::length(o.angularMomentum()) - l0_) / l0_);
    }
    ImGui::EndTable();
  }
  // The true Kepler ellipse of the initial state (grey): r(θ) = p / (1 + e cos θ) about the sun,
  // with eccentricity vector e = v × L / GM − r̂ and semi-latus rectum p = |L|² / GM.
  void drawExactOrbit(DebugDraw& d) const {
    const ode::OrbitDesc desc;
    const Vec3 r0 = desc.position, v0(0.0, 0.0, -speed_);
    const Vec3 L = glm::cross(r0, v0);
    const Vec3 ecc = glm::cross(v0, L) / desc.gm - glm::normalize(r0);
    const Real e = glm::length(ecc);
    if (e >= 1.0) return;  // not bound: no ellipse
    const Real semiLatus = glm::dot(L, L) / desc.gm;
    const Vec3 u = e > 1e-9 ? ecc / e : glm::normalize(r0);
    const Vec3 w = glm::normalize(glm::cross(glm::normalize(L), u));
    Vec3 previous(0.0);
    for (int k = 0; k <= kEllipseSegments; ++k) {
      const Real theta = 2.0 * kPi * k / kEllipseSegments;
      const Vec3 p =
          kDrawOffset + semiLatus / (1.0 + e * std::cos(theta)) * (std::cos(theta) * u + std::sin(theta) * w);
      if (k > 0) d.line(previous, p, colors::kGrey);
      previous = p;
    }
  }
  nlohmann::json metrics() const override {
    const Planet& s = planets_[static_cast<std::size_t>(selected_)];
    nlohmann::json j = lab::baseMetrics(selected_, 1, s.orbit.energy(), e0_, rate_);
    j["time_s"] = time_;
    j["angular_momentum"] = glm::length(s.orbit.angularMomentum());
    j["angular_momentum_drift"] = (glm::length(s.orbit.angularMomentum()) - l0_) / l0_;
    for (const Planet& p : planets_) {
      const std::string name(ode::integratorName(p.integrator.kind()));
      j["energy_drift_" + name] = (p.orbit.energy() - e0_) / std::abs(e0_);
      j["angular_momentum_drift_" + name] = (glm::length(p.orbit.angularMomentum()) - l0_) / l0_;
    }
    return j;
  }
  std::optional<std::string> nonFiniteState() const override {
    for (const Planet& p : planets_) {
      if (!isFinite(p.orbit.position()) || !isFinite(p.orbit.velocity()))
        return "the " + std::string(ode::integratorName(p.integrator.kind())) + " planet's state is not finite";
    }
    return std::nullopt;
  }
  std::vector<std::string> defaultPlots() const override {
    // The selected method's drifts (switch "integrator" to compare); per-method keys are in the metrics.
    return {"energy_drift", "angular_momentum_drift"};
  }

 private:
  struct Planet {
    ode::KeplerOrbit orbit;  // a value: the scene copies itself for rewind
    ode::Integrator integrator;
    std::deque<Vec3> trail;
  };
  static constexpr Real kTimeScale = 3.0;  // simulated seconds per displayed second
  Real h_ = 0.05, speed_ = 1.2, e0_ = 0.0, l0_ = 0.0;
  Real time_ = 0.0, clock_ = 0.0;  ///< [s] the methods' time and the scene's clock (kTimeScale × runner time)
  ode::IntegratorKind selected_ = ode::IntegratorKind::SymplecticEuler;
  std::vector<Planet> planets_;
  lab::UpdateRate rate_;
};

}  // namespace

PBA_REGISTER_SCENE("ODE", "orbit", OrbitScene);

}  // namespace pba::lab
