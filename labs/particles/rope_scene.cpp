// Particles lab, scene "rope": a light mass-spring rope and a heavy chain (with bending springs), each
// pinned at one end; drag any particle with the left mouse button (it follows the cursor, pinned, and
// is let go on release). Damped springs of PART-4 (Lobb notes).
#include "app/scene_registry.h"
#include "common.h"
#include "physics/springs/builders.h"

namespace {
using namespace pba;

constexpr Real kBeadRadius = 0.05;  // [m] drawn and picking radius
constexpr Real kPinHeight = 3.0;    // [m] both pins; the ropes are 2 m long

class RopeScene final : public app::Scene {
 public:
  RopeScene() {
    params_.integer("segments", &rope_.segments, 2, 200, "", "Springs per rope. Typical 20.").needsReset();
    params_.real("stiffness", &rope_.stiffness, 10.0, 1e5, "N/m", "Spring constant of each rope segment. Typical 2000.")
        .logarithmic()
        .needsReset();
    params_.real("damping", &rope_.damping, 0.0, 20.0, "N·s/m",
                 "Damping along each spring (resists stretching speed, not swinging). Typical 2.")
        .needsReset();
    params_.real("drag", &drag_, 0.0, 2.0, "N·s/m", "Linear air drag on every particle. Typical 0.02.");
    params_.real("gravity", &gravity_, 0.0, 30.0, "m/s²", "Gravitational acceleration. Earth 9.81.");
    lab::addIntegratorParam(params_, &kind_, " Explicit methods need h < 2/ω of the stiffest spring.");
  }

  std::string description() const override {
    return "A rope and a heavier chain swing from their pinned ends: drag a particle with the mouse and let go.";
  }
  Real defaultDt() const override { return 1.0 / 1000.0; }

  void reset() override {
    system_ = particles::ParticleSystem{};
    // Both start horizontal, 0.6 m apart, pinned at opposite ends: they swing down in opposite
    // directions and hang 2 m apart, so the picture (and the camera's framing of the start) is the
    // 2.4 m × 3 m × 0.6 m box they sweep, not the whole floor.
    rope_.start = Vec3(-1.0, kPinHeight, 0.3);
    rope_.end = Vec3(1.0, kPinHeight, 0.3);
    (void)springs::appendRope(rope_, system_);
    springs::RopeDesc chain = rope_;
    chain.start = Vec3(1.0, kPinHeight, -0.3);
    chain.end = Vec3(-1.0, kPinHeight, -0.3);
    chain.mass = 4.0 * rope_.mass;
    chain.stiffness = 4.0 * rope_.stiffness;
    chain.bending = true;
    chainFirst_ = springs::appendRope(chain, system_).value();
    for (std::size_t i = chainFirst_; i < system_.particles.size(); ++i) system_.particles.color[i] = colors::kDark;
    system_.syncMasses();
    integrator_.reset();
    system_.setTime(0.0);
    applyForces();
    initialEnergy_ = system_.energy();
    dragged_ = -1;
  }

  void step(Real dt) override {
    applyForces();
    integrator_.setKind(kind_);
    rate_.start();
    integrator_.step(system_, dt);
    particles::collideWithObstacles(system_.particles, ground_, kBeadRadius);
    rate_.stop(system_.particles.size());
  }

  void draw(DebugDraw& d) const override {
    lab::drawGroundSquare(d, 1.2);
    for (const springs::Spring& s : system_.springs) {
      if (s.j != s.i + 1) continue;  // skip bending springs
      // Shaded capsules rather than hairlines: the rope reads as a rope on a projector.
      d.capsule(system_.particles.position[s.i], system_.particles.position[s.j], 0.4 * kBeadRadius,
                s.i >= chainFirst_ ? colors::kDark : colors::kOrange);
    }
    for (std::size_t i = 0; i < system_.particles.size(); ++i) {
      const bool pinned = system_.particles.inverseMass[i] == 0.0;
      d.sphere(system_.particles.position[i], pinned ? 1.6 * kBeadRadius : kBeadRadius,
               static_cast<int>(i) == dragged_ ? colors::kYellow : (pinned ? colors::kRed : system_.particles.color[i]));
    }
  }

  nlohmann::json metrics() const override {
    nlohmann::json j = lab::baseMetrics(kind_, system_.particles.size(), system_.energy(), initialEnergy_, rate_);
    j["max_stretch"] = springs::maxRelativeStretch(system_.springs, system_.particles.position);
    return j;
  }
  std::optional<std::string> nonFiniteState() const override { return particles::describeNonFinite(system_.particles); }
  std::optional<Real> energy() const override { return system_.energy(); }
  std::vector<std::string> defaultPlots() const override { return {"energy", "max_stretch"}; }
  std::vector<app::Preset> presets() const override {
    return {{"slack", {{"stiffness", 200.0}}}, {"stiff", {{"stiffness", 20000.0}}},
            {"undamped", {{"damping", 0.0}, {"drag", 0.0}}}, {"implicit", {{"integrator", "implicit-euler"}}}};
  }
  std::optional<app::PickHit> pick(const app::Ray& ray) const override {
    return lab::pickParticle(ray, system_.particles, 2.0 * kBeadRadius);
  }
  void drag(int handle, const Vec3& target) override {
    const auto i = static_cast<std::size_t>(handle);
    if (dragged_ != handle) {
      dragged_ = handle;
      savedInverseMass_ = system_.particles.inverseMass[i];
      system_.particles.inverseMass[i] = 0.0;  // kinematic while held
      system_.syncMasses();
    }
    system_.particles.position[i] = target;
    system_.particles.velocity[i] = Vec3(0.0);
  }
  void release(int handle) override {
    if (handle != dragged_) return;
    system_.particles.inverseMass[static_cast<std::size_t>(handle)] = savedInverseMass_;
    system_.syncMasses();
    dragged_ = -1;
  }

 private:
  void applyForces() {
    system_.forces.gravity = Vec3(0.0, -gravity_, 0.0);
    system_.forces.drag.linear = drag_;
  }

  springs::RopeDesc rope_;
  Real drag_ = 0.02, gravity_ = kStandardGravity;
  ode::IntegratorKind kind_ = ode::IntegratorKind::SymplecticEuler;
  ode::Integrator integrator_;
  particles::ParticleSystem system_;
  particles::Obstacles ground_{{particles::PlaneObstacle{}}, {}, {}, {}};
  std::size_t chainFirst_ = 0;
  int dragged_ = -1;
  Real savedInverseMass_ = 0.0, initialEnergy_ = 0.0;
  lab::UpdateRate rate_;
};

}  // namespace

PBA_REGISTER_SCENE("Mass-spring", "rope", RopeScene);
