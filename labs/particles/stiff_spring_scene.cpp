// Particles lab, scene "stiff-spring": a cantilever beam of very stiff springs (a lattice pinned at one
// end). Implicit Euler (Baraff & Witkin 1998) is stable at the lab's step; switch to any explicit method
// and it explodes within a few steps — the runner pauses and names the first particle that blew up.
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "app/runner/scene_registry.h"
#include "common.h"
#include "physics/springs/builders.h"
#include "physics/springs/stability.h"

namespace pba::lab {
namespace {

class StiffSpringScene final : public app::Scene {
 public:
  StiffSpringScene() {
    params_
        .real("stiffness", &beam_.stiffness, 100.0, 1e7, "N/m",
              "Spring constant. Symplectic Euler needs h < 2/ω_max, ω_max the beam's highest mode (shown in the "
              "scene; above a chain's 2√(k/m): shear springs stiffen it). Typical 1e5.")
        .logarithmic()
        .needsReset();
    params_.real("damping", &beam_.damping, 0.0, 50.0, "N·s/m", "Damping along each spring. Typical 1.").needsReset();
    params_.integer("cg_max_iterations", &cg_.maxIterations, 1, 2000, "",
                    "Implicit Euler: cap on conjugate-gradient iterations per step. Typical 200; the metric "
                    "cg_iterations shows what a step needs (block-Jacobi preconditioned).");
    params_
        .real("cg_tolerance", &cg_.relativeTolerance, 1e-14, 1e-2, "",
              "Implicit Euler: CG stops when the residual |b − A Δv| ≤ tolerance·|b|. Typical 1e-10.")
        .logarithmic();
    sim_.kind = ode::IntegratorKind::ImplicitEuler;
    sim_.declareParams(params_, " Default implicit-euler; the explicit ones blow up here.");
  }

  std::string description() const override {
    return "A very stiff spring beam: implicit Euler holds it at a step where every explicit method explodes "
           "(try --integrator symplectic-euler).";
  }

  void reset() override {
    particles::ParticleSystem& system = sim_.system;
    system = particles::ParticleSystem{};
    beam_.nx = 10;
    beam_.ny = 3;
    beam_.nz = 3;
    beam_.spacing = 0.2;
    beam_.particleMass = 0.05;
    beam_.origin = Vec3(-1.0, 2.0, -0.2);
    (void)springs::appendLattice(beam_, system);
    for (int j = 0; j < beam_.ny; ++j)
      for (int k = 0; k < beam_.nz; ++k) system.particles.inverseMass[static_cast<std::size_t>(j * beam_.nz + k)] = 0.0;
    for (std::size_t i = 0; i < system.particles.size(); ++i) system.particles.color[i] = colors::kGreen;
    sim_.finishReset();
    capHit_.reset();
    // The beam's stiffest mode about its rest shape: the explicit methods' step limit (stability.h).
    omegaMax_ =
        springs::highestAngularFrequency(system.springs, system.particles.position, system.particles.inverseMass);
  }

  void step(Real dt) override {
    lastStep_ = dt;
    (void)sim_.integrator.setImplicitSettings(cg_);  // the sliders' ranges keep it valid
    sim_.integrate(dt);
    const ode::ImplicitEulerStats& cg = sim_.integrator.lastImplicitStats();
    if (sim_.kind == ode::IntegratorKind::ImplicitEuler && !cg.converged && !capHit_) {
      capHit_ = CapHit{sim_.system.time(), cg.iterations, cg.relativeResidual};  // kept until reset: once
    }
    sim_.finishStep();
  }

  // A one-time warning: the first step whose CG stopped at its cap before meeting the tolerance.
  void ui() override {
    if (!capHit_) return;
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.85f, 0.35f, 0.0f, 1.0f));
    ImGui::TextWrapped(
        "Implicit Euler: at t = %.3f s CG stopped at its cap of %d iterations with residual %.2g "
        "> tolerance %.2g; the step is not converged. Raise cg_max_iterations or cg_tolerance.",
        capHit_->time, capHit_->iterations, capHit_->residual, cg_.relativeTolerance);
    ImGui::PopStyleColor();
  }

  void draw(DebugDraw& d) const override {
    const particles::ParticleSystem& system = sim_.system;
    for (const springs::Spring& s : system.springs) {
      d.line(system.particles.position[s.i], system.particles.position[s.j], colors::kDark);
    }
    for (std::size_t i = 0; i < system.particles.size(); ++i) {
      const bool pinned = system.particles.inverseMass[i] == 0.0;
      d.sphere(system.particles.position[i], 0.035, pinned ? colors::kRed : colors::kGreen);
    }
    d.box(Vec3(-1.1, 2.2, 0.0), Vec3(0.1, 0.6, 0.6), Quat(1, 0, 0, 0), colors::kGrey);  // the wall
    char label[160];
    std::snprintf(label, sizeof label, "highest mode ω = %.0f rad/s: symplectic Euler needs h < 2/ω = %.2g s",
                  omegaMax_, omegaMax_ > 0.0 ? 2.0 / omegaMax_ : 0.0);
    d.text(Vec3(-2.6, 3.2, 0.0), label, colors::kDark);
    if (lastStep_ > 0.0) {
      std::snprintf(label, sizeof label, "(undamped; this run's step h = %.2g s)", lastStep_);
      d.text(Vec3(-2.6, 2.95, 0.0), label, colors::kDark);
    }
  }

  nlohmann::json metrics() const override {
    nlohmann::json j = sim_.metrics();
    const ode::ImplicitEulerStats& cg = sim_.integrator.lastImplicitStats();
    j["cg_iterations"] = cg.iterations;
    j["cg_relative_residual"] = cg.relativeResidual;
    j["cg_converged"] = cg.converged;
    j["cg_cap_hit"] = capHit_.has_value();  // since reset
    // The beam's energy balance: E₀ is almost all gravitational potential, so energy_drift says little;
    // what springs and damping did is the dissipated energy E₀ − E against the stored spring energy
    // (equal at static equilibrium for a linear structure, Clapeyron's theorem).
    j["dissipated_J"] = sim_.initialEnergy - sim_.system.energy();
    j["spring_energy_J"] = springs::springPotentialEnergy(sim_.system.springs, sim_.system.particles.position);
    j["kinetic_energy_J"] = sim_.system.particles.kineticEnergy();
    j["max_stretch"] = springs::maxRelativeStretch(sim_.system.springs, sim_.system.particles.position);
    j["tip_y_m"] = sim_.system.particles.position.back().y;
    j["highest_mode_rad_s"] = omegaMax_;  // about the rest shape, damping off
    j["symplectic_step_limit_s"] = omegaMax_ > 0.0 ? 2.0 / omegaMax_ : 0.0;
    return j;
  }
  std::optional<std::string> nonFiniteState() const override { return sim_.nonFiniteState(); }
  std::optional<Real> energy() const override { return sim_.system.energy(); }
  std::vector<std::string> defaultPlots() const override { return {"energy", "tip_y_m"}; }
  std::vector<app::Preset> presets() const override {
    // Short names: three buttons share a row of the panel.
    return {{"implicit: ok", {{"integrator", "implicit-euler"}}},
            {"symplectic: boom", {{"integrator", "symplectic-euler"}}},
            {"rk4: boom", {{"integrator", "rk4"}}},
            // Stable at the lab's h = 1/120 s (60 s headless, max stretch 50 %): the springs' damping is
            // explicit too, and with damping 1 N·s/m symplectic Euler exploded at k = 100 and 200 N/m.
            {"soft + symplectic", {{"stiffness", 100.0}, {"damping", 0.2}, {"integrator", "symplectic-euler"}}}};
  }

 private:
  struct CapHit {
    Real time;  // [s]
    int iterations;
    Real residual;  // relative
  };
  springs::LatticeDesc beam_{Vec3(0.0), 10, 3, 3, 0.2, 0.05, 1e5, 1.0, true, false};
  ode::ImplicitEulerSettings cg_;
  std::optional<CapHit> capHit_;
  Real omegaMax_ = 0.0;  ///< [rad/s] the beam's highest mode at rest (reset)
  Real lastStep_ = 0.0;  ///< [s] the step the runner passed last
  lab::IntegratedSystem sim_;
};

}  // namespace

PBA_REGISTER_SCENE("Mass-spring", "stiff-spring", StiffSpringScene);

}  // namespace pba::lab
