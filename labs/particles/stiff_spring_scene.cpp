// Particles lab, scene "stiff-spring": a cantilever beam of very stiff springs (a lattice pinned at one
// end). Implicit Euler (Baraff & Witkin 1998) is stable at the lab's step; switch to any explicit method
// and it explodes within a few steps — the runner pauses and names the first particle that blew up.
#include <cmath>

#include "app/scene_registry.h"
#include "common.h"
#include "physics/springs/builders.h"

namespace {
using namespace pba;

class StiffSpringScene final : public app::Scene {
 public:
  StiffSpringScene() {
    params_.real("stiffness", &beam_.stiffness, 100.0, 1e7, "N/m",
                 "Spring constant. ω ≈ 2√(k/m): explicit methods need h < 2/ω. Typical 1e5.")
        .logarithmic()
        .needsReset();
    params_.real("damping", &beam_.damping, 0.0, 50.0, "N·s/m", "Damping along each spring. Typical 1.").needsReset();
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
  }

  void step(Real dt) override {
    sim_.integrate(dt);
    sim_.finishStep();
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
    const Real omega = 2.0 * std::sqrt(beam_.stiffness / beam_.particleMass);
    char label[128];
    std::snprintf(label, sizeof label, "explicit limit h < 2/ω = %.2g s", 2.0 / omega);
    d.text(Vec3(-1.0, 3.0, 0.0), label, colors::kDark);
  }

  nlohmann::json metrics() const override {
    nlohmann::json j = sim_.metrics();
    j["cg_iterations"] = sim_.integrator.lastImplicitStats().iterations;
    j["max_stretch"] = springs::maxRelativeStretch(sim_.system.springs, sim_.system.particles.position);
    j["tip_y_m"] = sim_.system.particles.position.back().y;
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
            {"soft + symplectic", {{"stiffness", 200.0}, {"integrator", "symplectic-euler"}}}};
  }

 private:
  springs::LatticeDesc beam_{Vec3(0.0), 10, 3, 3, 0.2, 0.05, 1e5, 1.0, true, false};
  lab::IntegratedSystem sim_;
};

}  // namespace

PBA_REGISTER_SCENE("Mass-spring", "stiff-spring", StiffSpringScene);
