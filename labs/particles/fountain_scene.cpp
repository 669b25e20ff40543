// Particles lab, scene "fountain": an emitter sprays particles into gusty wind and a vortex; they bounce
// off sphere obstacles and the ground, change colour over their life and are recycled when they expire.
// Scales to 1,000,000 particles (--particles 1000000): above kFusedAbove particles with velocity Verlet
// (the scene's default integrator) the whole step is particles::stepFountain (kernels.h): ageing and
// removal, gravity, drag towards the wind, vortex, plane and sphere contacts (the library's contact model),
// the guard's finiteness test and the energy sums in one sweep,
// instead of the emitter's update and the generic force-array path. Huge counts are drawn as a
// subsample of points, coloured over life only for the drawn ones.
#include "app/runner/scene_registry.h"
#include "common.h"
#include "physics/particles/emitter.h"
#include "physics/particles/kernels.h"

namespace pba::lab {
namespace {

constexpr Real kRadius = 0.02;      // [m] particle radius for contacts
constexpr int kFusedAbove = 20000;  // pools larger than this use the fused kernel (velocity Verlet only)

class FountainScene final : public app::Scene {
 public:
  FountainScene() {
    params_.integer("particles", &maxParticles_, 100, 1000000, "", "Pool size (live particles at most). Typical 5000.")
        .needsReset();
    params_.real("rate", &emitter_.rate, 10.0, 1e6, "1/s", "Particles emitted per second. Typical 1500.").logarithmic();
    params_.flag("keep_full", &keepFull_,
                 "Emit at least pool / shortest lifetime per second, so a large pool fills and stays full "
                 "(--particles 1000000 then really simulates about a million).");
    params_.real("lifetime", &emitter_.lifetime, 0.2, 20.0, "s", "Mean particle lifetime. Typical 3 s.");
    params_.angle("spread", &emitter_.spread, 0.0, 60.0, "Half-angle of the emission cone. Typical 12°.");
    params_.real("speed", &emitter_.speed, 0.0, 30.0, "m/s", "Initial speed. Typical 8 m/s.");
    params_.real("wind", &windSpeed_, 0.0, 20.0, "m/s", "Mean wind speed along +x (acts through drag). Typical 2.");
    params_.real("gust", &forces_.wind.gust, 0.0, 10.0, "m/s", "Amplitude of the travelling gusts. Typical 1.5.");
    params_.real("drag", &forces_.drag.linear, 0.0, 0.1, "N·s/m", "Linear air drag per particle. Typical 0.005.");
    params_.real("vortex", &vortexStrength_, -20.0, 20.0, "m²/s²", "Swirl strength of a vortex around the y axis.");
    params_.real("restitution", &obstacles_.material.restitution, 0.0, 1.0, "", "Bounce of the ground and spheres.");
    params_.real("gravity", &gravity_, 0.0, 30.0, "m/s²", "Gravitational acceleration. Earth 9.81.");
    lab::addIntegratorParam(params_, &kind_,
                            " Default velocity-verlet: pools above 20,000 then take the fused one-pass kernel.");
  }

  std::string description() const override {
    return "A fountain in gusty wind: particles fan out, bounce off the spheres and ground, fade from blue to "
           "orange and are recycled.";
  }

  void reset() override {
    system_ = particles::ParticleSystem{};
    emitter_.maxParticles = static_cast<std::size_t>(maxParticles_);
    system_.particles.reserve(emitter_.maxParticles);
    emitterState_ = particles::Emitter(emitter_, seed());
    obstacles_.planes = {particles::PlaneObstacle{}};
    obstacles_.spheres = {{Vec3(1.2, 1.0, 0.0), 0.6}, {Vec3(-0.8, 0.5, 1.0), 0.5}, {Vec3(0.2, 0.4, -1.3), 0.4}};
    integrator_.reset();
    system_.setTime(0.0);
    fused_ = nonFinite_ = false;
    fusedEnergy_ = 0.0;
  }

  void step(Real dt) override {
    emitterState_.desc() = emitter_;
    emitterState_.desc().maxParticles = static_cast<std::size_t>(maxParticles_);
    if (keepFull_) {
      const Real shortest = emitter_.lifetime * (1.0 - emitter_.lifetimeJitter);
      emitterState_.desc().rate = std::max(emitter_.rate, maxParticles_ / shortest);
    }
    forces_.gravity = Vec3(0.0, -gravity_, 0.0);
    forces_.wind.base = Vec3(windSpeed_, 0.0, 0.0);
    forces_.vortices = {particles::VortexDesc{Vec3(0.0), kUp, vortexStrength_, 0.5}};
    system_.forces = forces_;
    integrator_.setKind(kind_);
    rate_.start();
    fused_ = kind_ == ode::IntegratorKind::VelocityVerlet && maxParticles_ > kFusedAbove;
    if (fused_) {
      stepFused(dt);
    } else {
      emitterState_.update(system_.particles, dt);
      system_.syncMasses();
      integrator_.step(system_, dt);
      particles::collideWithObstacles(system_.particles, obstacles_, kRadius, {forces_.gravity, dt});
    }
    rate_.stop(system_.particles.size());
  }

  void draw(DebugDraw& d) const override {
    lab::drawGroundSquare(d, 4.0);
    for (const auto& s : obstacles_.spheres) d.sphere(s.center, s.radius, colors::kGrey);
    d.cone(emitter_.position, emitter_.direction, emitter_.spread, 0.4, colors::kDark);
    // Colour over life is evaluated here, for the drawn subsample only (the fused step leaves it).
    const particles::Particles& p = system_.particles;
    lab::drawPointSubsample(d, p,
                            [&](std::size_t i) { return particles::colorOverLife(emitter_, p.age[i], p.lifetime[i]); });
  }

  // The whole step in one pass over the pool (kernels.h: ageing and removal, motion, contacts, the
  // guard's finiteness test, energy sums), then the new particles. The generic path's spatial gusts
  // become the gust at the nozzle.
  void stepFused(Real dt) {
    particles::FusedFountainDesc f;
    f.gravity = forces_.gravity;
    f.dragRate = forces_.drag.linear / emitter_.particleMass;
    f.wind = particles::windVelocity(forces_.wind, emitter_.position, system_.time());
    f.vortexStrength = vortexStrength_;
    f.vortexCore = forces_.vortices.front().coreRadius;
    f.planes = obstacles_.planes;
    f.spheres = obstacles_.spheres;
    f.material = obstacles_.material;
    f.radius = kRadius;
    particles::Particles& p = system_.particles;
    const particles::FountainStepStats stats = particles::stepFountain(p, f, dt);
    nonFinite_ = stats.nonFinite;
    const std::size_t survivors = p.size();
    emitterState_.spawn(p, dt);
    // Energy of the survivors from the kernel's sums, plus the newly spawned particles'.
    fusedEnergy_ = emitter_.particleMass * (stats.kineticPerMass + stats.potentialPerMass);
    for (std::size_t i = survivors; i < p.size(); ++i) {
      fusedEnergy_ += p.mass(i) * (0.5 * glm::dot(p.velocity[i], p.velocity[i]) - glm::dot(f.gravity, p.position[i]));
    }
    system_.setTime(system_.time() + dt);
  }

  nlohmann::json metrics() const override {
    const Real e = fused_ ? fusedEnergy_
                          : system_.particles.kineticEnergy() +
                                particles::fieldPotentialEnergy(system_.forces, system_.particles.position,
                                                                system_.particles.inverseMass);
    // An emitter adds and removes energy all the time: there is no conserved total, so no drift (0).
    nlohmann::json j = lab::baseMetrics(kind_, system_.particles.size(), e, e, rate_);
    j["fused_kernel"] = fused_;
    j["pool"] = maxParticles_;  // live particles at most (particles = live now; keep_full fills it in ~2 s)
    return j;
  }
  // The fused step tests finiteness on the fly; the full scan runs only to name the culprit.
  std::optional<std::string> nonFiniteState() const override {
    if (fused_ && !nonFinite_) return std::nullopt;
    return particles::describeNonFinite(system_.particles);
  }
  std::vector<std::string> defaultPlots() const override { return {"particles", "particle_updates_per_s"}; }
  // Close enough that the jet (apex ≈ v²/2g ≈ 3.3 m) and the splash around the spheres fill the view,
  // shifted up and left of the plot window in the lower right.
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.7, 0.1, -0.4), 11.5, 0.785, 0.3};
  }
  std::vector<app::Preset> presets() const override {
    return {{"calm", {{"wind", 0.0}, {"gust", 0.0}, {"vortex", 0.0}}},
            {"storm", {{"wind", 8.0}, {"gust", 4.0}}},
            {"whirl", {{"vortex", 12.0}, {"wind", 0.0}}},
            {"100k", {{"particles", 100000}, {"rate", 40000.0}}}};
  }

 private:
  int maxParticles_ = 5000;
  bool keepFull_ = true, fused_ = false, nonFinite_ = false;
  Real fusedEnergy_ = 0.0;  // [J] of the pool after the last fused step
  Real windSpeed_ = 2.0, vortexStrength_ = 3.0, gravity_ = kStandardGravity;
  particles::EmitterDesc emitter_{
      Vec3(0.0, 0.1, 0.0), kUp, 1500.0, 3.0, 0.3, degToRad(12.0), 8.0, 0.1, 0.01, 5000, colors::kBlue, colors::kOrange};
  particles::Emitter emitterState_;
  particles::ForceDesc forces_{
      Vec3(0.0, -kStandardGravity, 0.0), {0.005, 0.0}, {Vec3(2.0, 0, 0), 1.5, 0.5, 8.0}, {}, {}};
  particles::Obstacles obstacles_{{}, {}, {}, particles::ContactMaterial{0.4, 0.3, 0.2, 0.1}};
  ode::IntegratorKind kind_ = ode::IntegratorKind::VelocityVerlet;
  ode::Integrator integrator_;
  particles::ParticleSystem system_;
  lab::UpdateRate rate_;
};

}  // namespace

PBA_REGISTER_SCENE("Particles", "fountain", FountainScene);

}  // namespace pba::lab
