// Particles lab, scene "rope": a light mass-spring rope and a heavy chain (with bending springs), each
// pinned at one end; drag any particle with the left mouse button (it follows the cursor, pinned, and
// is let go on release). Damped springs of PART-4 (Lobb notes).
#include "app/runner/scene_registry.h"
#include "common.h"
#include "physics/springs/builders.h"

namespace pba::lab {
namespace {

constexpr Real kBeadRadius = 0.05;  // [m] drawn and picking radius
constexpr Real kPinHeight = 3.0;    // [m] both pins; the ropes are 2 m long

class RopeScene final : public app::Scene {
 public:
  RopeScene() {
    params_.integer("segments", &rope_.segments, 2, 200, "", "Springs per rope. Typical 20.").needsReset();
    params_.real("stiffness", &rope_.stiffness, 10.0, 1e5, "N/m", "Spring constant of each rope segment. Typical 2000.")
        .logarithmic()
        .needsReset();
    params_
        .real("damping", &rope_.damping, 0.0, 20.0, "N·s/m",
              "Damping along each spring (resists stretching speed, not swinging). Typical 2.")
        .needsReset();
    params_.real("drag", &drag_, 0.0, 2.0, "N·s/m", "Linear air drag on every particle. Typical 0.02.");
    sim_.declareParams(params_, " Explicit methods need h below 2/ω of the stiffest mode.");
  }

  std::string description() const override {
    return "A rope and a heavier chain swing from their pinned ends: drag a particle with the mouse and let go.";
  }
  Real defaultDt() const override { return 1.0 / 1000.0; }

  void reset() override {
    sim_.system = particles::ParticleSystem{};
    // Both start horizontal, 0.6 m apart, pinned at opposite ends: they swing down in opposite
    // directions and hang 2 m apart, so the picture (and the camera's framing of the start) is the
    // 2.4 m × 3 m × 0.6 m box they sweep, not the whole floor.
    rope_.start = Vec3(-1.0, kPinHeight, 0.3);
    rope_.end = Vec3(1.0, kPinHeight, 0.3);
    (void)springs::appendRope(rope_, sim_.system);
    springs::RopeDesc chain = rope_;
    chain.start = Vec3(1.0, kPinHeight, -0.3);
    chain.end = Vec3(-1.0, kPinHeight, -0.3);
    chain.mass = 4.0 * rope_.mass;
    chain.stiffness = 4.0 * rope_.stiffness;
    chain.bending = true;
    chainFirst_ = springs::appendRope(chain, sim_.system).value();
    for (std::size_t i = chainFirst_; i < sim_.system.particles.size(); ++i)
      sim_.system.particles.color[i] = colors::kDark;
    sim_.system.forces.drag.linear = drag_;
    sim_.finishReset();
    dragged_ = -1;
  }

  void step(Real dt) override {
    sim_.system.forces.drag.linear = drag_;
    sim_.integrate(dt);
    particles::collideWithObstacles(sim_.system.particles, ground_, kBeadRadius, sim_.contactStep(dt));
    sim_.finishStep();
  }

  void draw(DebugDraw& d) const override {
    lab::drawGroundSquare(d, 1.2);
    for (const springs::Spring& s : sim_.system.springs) {
      if (s.j != s.i + 1) continue;  // skip bending springs
      // Shaded capsules rather than hairlines: the rope reads as a rope on a projector.
      d.capsule(sim_.system.particles.position[s.i], sim_.system.particles.position[s.j], 0.4 * kBeadRadius,
                s.i >= chainFirst_ ? colors::kDark : colors::kOrange);
    }
    const particles::Particles& p = sim_.system.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const bool pinned = p.inverseMass[i] == 0.0;
      d.sphere(p.position[i], pinned ? 1.6 * kBeadRadius : kBeadRadius,
               static_cast<int>(i) == dragged_ ? colors::kYellow : (pinned ? colors::kRed : p.color[i]));
    }
  }

  nlohmann::json metrics() const override {
    nlohmann::json j = sim_.metrics();
    j["max_stretch"] = springs::maxRelativeStretch(sim_.system.springs, sim_.system.particles.position);
    return j;
  }
  std::optional<std::string> nonFiniteState() const override { return sim_.nonFiniteState(); }
  std::optional<Real> energy() const override { return sim_.system.energy(); }
  std::vector<std::string> defaultPlots() const override { return {"energy", "max_stretch"}; }
  std::vector<app::Preset> presets() const override {
    return {{"slack", {{"stiffness", 200.0}}},
            {"stiff", {{"stiffness", 20000.0}}},
            {"undamped", {{"damping", 0.0}, {"drag", 0.0}}},
            {"implicit", {{"integrator", "implicit-euler"}}}};
  }
  std::optional<app::PickHit> pick(const app::Ray& ray) const override {
    return lab::pickParticle(ray, sim_.system.particles, 2.0 * kBeadRadius);
  }
  std::vector<app::DragHandle> dragHandles() const override { return lab::particleHandles(sim_.system.particles); }
  std::vector<app::LegendEntry> legend() const override {
    return {{colors::kOrange, "light rope"},
            {colors::kDark, "heavy chain (with bending springs)"},
            {colors::kRed, "pinned end"},
            {colors::kYellow, "the particle being dragged"}};
  }
  void drag(int handle, const Vec3& target) override {
    const auto i = static_cast<std::size_t>(handle);
    if (dragged_ != handle) {
      dragged_ = handle;
      savedInverseMass_ = sim_.system.particles.inverseMass[i];
      sim_.system.particles.inverseMass[i] = 0.0;  // kinematic while held
      sim_.system.syncMasses();
    }
    sim_.system.particles.position[i] = target;
    sim_.system.particles.velocity[i] = Vec3(0.0);
  }
  void release(int handle) override {
    if (handle != dragged_) return;
    sim_.system.particles.inverseMass[static_cast<std::size_t>(handle)] = savedInverseMass_;
    sim_.system.syncMasses();
    dragged_ = -1;
  }

 private:
  springs::RopeDesc rope_;
  Real drag_ = 0.02;
  lab::IntegratedSystem sim_;
  particles::Obstacles ground_{{particles::PlaneObstacle{}}, {}, {}, {}};
  std::size_t chainFirst_ = 0;
  int dragged_ = -1;
  Real savedInverseMass_ = 0.0;
};

}  // namespace

PBA_REGISTER_SCENE("Mass-spring", "rope", RopeScene);

}  // namespace pba::lab
