// Particles lab, scene "bouncing": balls with restitution and Coulomb friction falling on the ground, a
// sphere and a box, bouncing lower each time and coming to rest without jitter (PART-5).
#include <random>

#include "app/runner/scene_registry.h"
#include "common.h"
#include "physics/particles/spatial_hash.h"

namespace pba::lab {
namespace {

class BouncingScene final : public app::Scene {
 public:
  BouncingScene() {
    params_.integer("particles", &count_, 1, 2000, "", "Number of balls. Typical 40.").needsReset();
    params_.real("radius", &radius_, 0.02, 0.3, "m", "Ball radius. Typical 0.12 m.").needsReset();
    params_.real("restitution", &obstacles_.material.restitution, 0.0, 1.0, "",
                 "Share of the normal speed kept by a bounce (0 clay, 1 superball). Typical 0.7.");
    params_.real("static_friction", &obstacles_.material.staticFriction, 0.0, 2.0, "",
                 "μ_s: a contact sticks while the tangential speed ≤ μ_s × normal speed change. Typical 0.6.");
    params_.real("kinetic_friction", &obstacles_.material.kineticFriction, 0.0, 2.0, "",
                 "μ_k: sliding loses μ_k × normal speed change of tangential speed. Typical 0.4.");
    params_.flag("ball_collisions", &ballCollisions_, "Collide the balls with each other (spatial hash grid).");
    sim_.declareParams(params_);
  }

  std::string description() const override {
    return "Balls bounce lower each time (apex × restitution²), slide, stick by friction and come to rest "
           "without jitter.";
  }

  void reset() override {
    sim_.system = particles::ParticleSystem{};
    std::mt19937_64 rng(seed());
    std::uniform_real_distribution<Real> u(-1.0, 1.0);
    for (int i = 0; i < count_; ++i) {
      const Vec3 x(1.5 * u(rng), 2.0 + 1.5 * (u(rng) + 1.0), 1.5 * u(rng));
      const Color c = i % 3 == 0 ? colors::kOrange : (i % 3 == 1 ? colors::kBlue : colors::kGreen);
      sim_.system.particles.add(x, Vec3(1.5 * u(rng), 0.0, 1.5 * u(rng)), 0.2, c);
    }
    obstacles_.planes = {particles::PlaneObstacle{}};
    obstacles_.spheres = {particles::SphereObstacle{Vec3(0.6, 0.0, 0.0), 0.8}};
    obstacles_.boxes = {
        particles::BoxObstacle{Vec3(-1.2, 0.3, 0.2), Vec3(0.5, 0.3, 0.5), glm::angleAxis(0.4, Vec3(0.0, 1.0, 0.0))}};
    sim_.finishReset();
  }

  void step(Real dt) override {
    sim_.integrate(dt);
    particles::Particles& p = sim_.system.particles;
    if (ballCollisions_) particles::collideParticlePairs(p, radius_, obstacles_.material.restitution, hash_);
    particles::collideWithObstacles(p, obstacles_, radius_, sim_.contactStep(dt));
    sim_.finishStep();
  }

  void draw(DebugDraw& d) const override {
    lab::drawGroundSquare(d, 3.0);
    for (const auto& s : obstacles_.spheres) d.sphere(s.center, s.radius, colors::kGrey);
    for (const auto& b : obstacles_.boxes) d.box(b.center, b.halfExtents, b.orientation, colors::kGrey);
    lab::drawParticles(d, sim_.system.particles, radius_, 2000);
  }

  nlohmann::json metrics() const override {
    nlohmann::json j = sim_.metrics();
    const particles::Particles& p = sim_.system.particles;
    std::size_t resting = 0;
    Real lowest = 1e9;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (glm::length(p.velocity[i]) < 1e-3) ++resting;
      lowest = std::min(lowest, p.position[i].y - radius_);
    }
    j["resting"] = resting;
    j["lowest_m"] = lowest;
    return j;
  }
  std::optional<std::string> nonFiniteState() const override { return sim_.nonFiniteState(); }
  std::optional<Real> energy() const override { return sim_.system.energy(); }
  std::vector<std::string> defaultPlots() const override { return {"energy", "resting"}; }
  // Close on the obstacles and the 6 m ground square (the balls start up to 5 m high and fall onto it).
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.4, 1.4, -0.3), 11.25, 0.6, 0.3};
  }
  std::vector<app::Preset> presets() const override {
    return {{"superballs", {{"restitution", 0.95}, {"static_friction", 0.1}, {"kinetic_friction", 0.05}}},
            {"clay", {{"restitution", 0.1}}},
            {"ice", {{"static_friction", 0.0}, {"kinetic_friction", 0.0}}},
            {"a crowd", {{"particles", 400}, {"radius", 0.06}}}};
  }
  std::optional<app::PickHit> pick(const app::Ray& ray) const override {
    return lab::pickParticle(ray, sim_.system.particles, radius_);
  }
  std::vector<app::DragHandle> dragHandles() const override { return lab::particleHandles(sim_.system.particles); }
  void drag(int handle, const Vec3& target) override {
    auto i = static_cast<std::size_t>(handle);
    sim_.system.particles.position[i] = Vec3(target.x, std::max(target.y, radius_), target.z);
    sim_.system.particles.velocity[i] = Vec3(0.0);
  }

 private:
  int count_ = 40;
  Real radius_ = 0.12;
  bool ballCollisions_ = true;
  lab::IntegratedSystem sim_;
  particles::Obstacles obstacles_{{}, {}, {}, particles::ContactMaterial{0.7, 0.6, 0.4, 0.1}};
  particles::SpatialHash hash_;
};

}  // namespace

PBA_REGISTER_SCENE("Particles", "bouncing", BouncingScene);

}  // namespace pba::lab
