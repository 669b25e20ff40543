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
    params_.real("gravity", &gravity_, 0.0, 30.0, "m/s²", "Gravitational acceleration. Earth 9.81.");
    lab::addIntegratorParam(params_, &kind_, " Default implicit-euler; the explicit ones blow up here.");
  }

  std::string description() const override {
    return "A very stiff spring beam: implicit Euler holds it at a step where every explicit method explodes "
           "(try --integrator symplectic-euler).";
  }

  void reset() override {
    system_ = particles::ParticleSystem{};
    beam_.nx = 10;
    beam_.ny = 3;
    beam_.nz = 3;
    beam_.spacing = 0.2;
    beam_.particleMass = 0.05;
    beam_.origin = Vec3(-1.0, 2.0, -0.2);
    (void)springs::appendLattice(beam_, system_);
    for (int j = 0; j < beam_.ny; ++j)
      for (int k = 0; k < beam_.nz; ++k) system_.particles.inverseMass[static_cast<std::size_t>(j * beam_.nz + k)] = 0.0;
    for (std::size_t i = 0; i < system_.particles.size(); ++i) system_.particles.color[i] = colors::kGreen;
    system_.syncMasses();
    integrator_.reset();
    system_.setTime(0.0);
    system_.forces.gravity = Vec3(0.0, -gravity_, 0.0);
    initialEnergy_ = system_.energy();
  }

  void step(Real dt) override {
    system_.forces.gravity = Vec3(0.0, -gravity_, 0.0);
    integrator_.setKind(kind_);
    rate_.start();
    integrator_.step(system_, dt);
    rate_.stop(system_.particles.size());
  }

  void draw(DebugDraw& d) const override {
    for (const springs::Spring& s : system_.springs) {
      d.line(system_.particles.position[s.i], system_.particles.position[s.j], colors::kDark);
    }
    for (std::size_t i = 0; i < system_.particles.size(); ++i) {
      const bool pinned = system_.particles.inverseMass[i] == 0.0;
      d.sphere(system_.particles.position[i], 0.035, pinned ? colors::kRed : colors::kGreen);
    }
    d.box(Vec3(-1.1, 2.2, 0.0), Vec3(0.1, 0.6, 0.6), Quat(1, 0, 0, 0), colors::kGrey);  // the wall
    const Real omega = 2.0 * std::sqrt(beam_.stiffness / beam_.particleMass);
    char label[128];
    std::snprintf(label, sizeof label, "explicit limit h < 2/ω = %.2g s", 2.0 / omega);
    d.text(Vec3(-1.0, 3.0, 0.0), label, colors::kDark);
  }

  nlohmann::json metrics() const override {
    nlohmann::json j = lab::baseMetrics(kind_, system_.particles.size(), system_.energy(), initialEnergy_, rate_);
    j["cg_iterations"] = integrator_.lastImplicitStats().iterations;
    j["max_stretch"] = springs::maxRelativeStretch(system_.springs, system_.particles.position);
    j["tip_y_m"] = system_.particles.position.back().y;
    return j;
  }
  std::optional<std::string> nonFiniteState() const override { return particles::describeNonFinite(system_.particles); }
  std::optional<Real> energy() const override { return system_.energy(); }
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
  Real gravity_ = kStandardGravity;
  ode::IntegratorKind kind_ = ode::IntegratorKind::ImplicitEuler;
  ode::Integrator integrator_;
  particles::ParticleSystem system_;
  Real initialEnergy_ = 0.0;
  lab::UpdateRate rate_;
};

}  // namespace

PBA_REGISTER_SCENE("Mass-spring", "stiff-spring", StiffSpringScene);
