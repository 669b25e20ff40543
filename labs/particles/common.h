#pragma once
// Shared pieces of the particles lab's scenes: the integrator parameter, particle drawing, metrics,
// picking. Nothing here is reusable physics (that lives in framework/physics/{ode,particles,springs}).
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

#include "app/runner/scene.h"
#include "physics/collision/ray.h"
#include "physics/ode/integrators.h"
#include "physics/particles/collision.h"
#include "physics/particles/particle_system.h"

namespace pba::lab {

inline constexpr float kPointPixels = 4.0f;
/// Above this many particles a scene draws a subsample as points (keeps the window responsive).
inline constexpr std::size_t kMaxDrawn = 20000;

/// Declares the "integrator" choice parameter (the lab flag --integrator sets it).
inline void addIntegratorParam(app::Params& params, ode::IntegratorKind* kind, const std::string& extra = {}) {
  params.choiceEnum("integrator", kind, ode::integratorNames(),
                    "Time integrator (switch live): euler (1st order, gains energy), symplectic-euler (1st, "
                    "energy bounded), midpoint (2nd), rk4 (4th), verlet / velocity-verlet (2nd, symplectic), "
                    "implicit-euler (stable at any step, dissipative), adaptive (DOPRI5 with error control)." +
                        extra);
}

/// Wall-clock timer for the particle_updates_per_s metric.
class UpdateRate {
 public:
  void start() { t0_ = std::chrono::steady_clock::now(); }
  void stop(std::size_t updates) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    if (s > 0.0) rate_ = 0.9 * rate_ + 0.1 * static_cast<double>(updates) / s;
    if (rate_ == 0.0 && s > 0.0) rate_ = static_cast<double>(updates) / s;
  }
  double perSecond() const { return rate_; }

 private:
  std::chrono::steady_clock::time_point t0_{};
  double rate_ = 0.0;
};

/// The metrics every particles scene reports (issue 4): integrator, particles, energy, energy_drift,
/// particle_updates_per_s.
inline nlohmann::json baseMetrics(ode::IntegratorKind kind, std::size_t particles, Real energy, Real initialEnergy,
                                  const UpdateRate& rate) {
  const Real scale = std::max(std::abs(initialEnergy), 1e-9);
  return {{"integrator", std::string(ode::integratorName(kind))},
          {"particles", particles},
          {"energy", energy},
          {"energy_drift", (energy - initialEnergy) / scale},
          {"particle_updates_per_s", rate.perSecond()}};
}

/// What the ParticleSystem scenes (bouncing, granular, rope, stiff-spring) each repeated: the system,
/// its integrator with the kind the `integrator` parameter selects, gravity as a parameter, the
/// particle_updates_per_s timer and the energy at reset that energy_drift compares with.
struct IntegratedSystem {
  particles::ParticleSystem system;
  ode::Integrator integrator;
  ode::IntegratorKind kind = ode::IntegratorKind::SymplecticEuler;
  Real gravity = kStandardGravity;  ///< [m/s²] downwards
  Real initialEnergy = 0.0;         ///< [J] at the last reset
  UpdateRate rate;

  /// Declares the `gravity` and `integrator` parameters (integratorNote is appended to the latter's help).
  void declareParams(app::Params& params, const std::string& integratorNote = {}) {
    params.real("gravity", &gravity, 0.0, 30.0, "m/s²", "Gravitational acceleration. Earth 9.81.");
    addIntegratorParam(params, &kind, integratorNote);
  }
  /// The end of reset(), after the particles were built: inverse masses synced, the integrator's
  /// memory forgotten, time 0, gravity applied and the energy recorded.
  void finishReset() {
    system.syncMasses();
    integrator.reset();
    system.setTime(0.0);
    system.forces.gravity = Vec3(0.0, -gravity, 0.0);
    initialEnergy = system.energy();
  }
  /// The start of step(dt): gravity and integrator kind from the parameters (both may change live),
  /// the timer started, one integrator step. Collisions follow; then finishStep().
  void integrate(Real dt) {
    system.forces.gravity = Vec3(0.0, -gravity, 0.0);
    integrator.setKind(kind);
    rate.start();
    integrator.step(system, dt);
  }
  /// What collideWithObstacles needs of the step just taken (gravity, dt) to find the approach speed at
  /// the contact time and tell resting contact from an impact.
  particles::ContactStep contactStep(Real dt) const { return {system.forces.gravity, dt}; }
  /// The end of step(dt): stops the timer (every particle counts as one update).
  void finishStep() { rate.stop(system.particles.size()); }
  /// For Scene::nonFiniteState(): names the first particle whose state is not finite.
  std::optional<std::string> nonFiniteState() const { return particles::describeNonFinite(system.particles); }
  /// baseMetrics() of this system, and momentum = |P| = |Σ mᵢ vᵢ| [kg·m/s] of the free particles
  /// (pinned ones have no mass here). Gravity, the ground and pins change P; the springs do not.
  nlohmann::json metrics() const {
    nlohmann::json j = baseMetrics(kind, system.particles.size(), system.energy(), initialEnergy, rate);
    Vec3 momentum(0.0);
    for (std::size_t i = 0; i < system.particles.size(); ++i)
      momentum += system.particles.mass(i) * system.particles.velocity[i];
    j["momentum"] = glm::length(momentum);
    return j;
  }
};

/// Draws at most about kMaxDrawn of the particles as points, an even stride through the arrays, in the
/// colour colorOf(i) (evaluated for the drawn ones only).
template <typename ColorOf>
void drawPointSubsample(DebugDraw& d, const particles::Particles& p, ColorOf&& colorOf) {
  const std::size_t stride = std::max<std::size_t>(1, p.size() / kMaxDrawn);
  for (std::size_t i = 0; i < p.size(); i += stride) d.point(p.position[i], kPointPixels, colorOf(i));
}

/// Draws particles as spheres (few), points (many) or a subsample of points (huge).
inline void drawParticles(DebugDraw& d, const particles::Particles& p, Real radius, std::size_t sphereLimit = 600) {
  if (p.size() <= sphereLimit) {
    for (std::size_t i = 0; i < p.size(); ++i) d.sphere(p.position[i], radius, p.color[i]);
    return;
  }
  drawPointSubsample(d, p, [&](std::size_t i) { return p.color[i]; });
}

/// The particle whose sphere of radius `radius` the ray hits first.
inline std::optional<app::PickHit> pickParticle(const app::Ray& ray, const particles::Particles& p, Real radius) {
  std::optional<app::PickHit> best;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::optional<app::PickHit> hit = app::pickSphere(ray, p.position[i], radius, static_cast<int>(i));
    if (hit && (!best || hit->distance < best->distance)) best = hit;
  }
  return best;
}

/// The particles as drag handles (Scene::dragHandles): every one up to `max`, else an even sample.
inline std::vector<app::DragHandle> particleHandles(const particles::Particles& p, std::size_t max = 48) {
  std::vector<app::DragHandle> out;
  const std::size_t stride = std::max<std::size_t>(1, (p.size() + max - 1) / max);
  for (std::size_t i = 0; i < p.size(); i += stride) out.push_back({static_cast<int>(i), p.position[i]});
  return out;
}

/// A ground grid line set (the renderer has its own grid; this marks the collision plane's extent).
inline void drawGroundSquare(DebugDraw& d, Real half, Real y = 0.0) {
  const Vec3 a(-half, y, -half), b(half, y, -half), c(half, y, half), e(-half, y, half);
  d.line(a, b, colors::kGrey);
  d.line(b, c, colors::kGrey);
  d.line(c, e, colors::kGrey);
  d.line(e, a, colors::kGrey);
}

}  // namespace pba::lab
