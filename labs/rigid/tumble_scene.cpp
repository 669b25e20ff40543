// Rigid lab, scene "tumble": the course's assessment. A cuboid is dropped corner-first onto the ground;
// its corners are tested against the plane and each contact gets the single collision impulse with
// restitution and a Coulomb friction impulse (the exercises RIGID-1 to RIGID-4, physics/rigid/tumble.h).
#include <cmath>

#include <glm/gtx/quaternion.hpp>
#include "app/scene_registry.h"

#include "physics/rigid/tumble.h"

namespace {
using namespace pba;

class TumbleScene final : public app::Scene {
 public:
  TumbleScene() {
    params_.real("gravity", &gravity_, 0.0, 30.0, "m/s²", "Gravitational acceleration (downwards). Earth 9.81.");
    params_.real("restitution", &settings_.restitution, 0.0, 1.0, "",
                 "Coefficient of restitution e of the impacts (RIGID-3). Typical 0.4.");
    params_.real("friction", &settings_.friction, 0.0, 2.0, "",
                 "Coulomb friction μ against the ground (RIGID-4). Typical 0.5.");
    params_.real("height", &height_, 0.5, 5.0, "m", "Drop height of the centre of mass.").needsReset();
    params_.real("mass", &box_.mass, 0.1, 100.0, "kg", "Mass of the box.").needsReset();
    params_.real("spin", &spin_, 0.0, 20.0, "rad/s", "Initial spin about a tilted axis.").needsReset();
    params_.integer("sweeps", &settings_.sweeps, 1, 50, "", "Passes over the corner contacts per step. Typical 8.");
  }

  std::string description() const override {
    return "A box falls corner-first: each corner below the ground gets the course's collision impulse with "
           "restitution "
           "and a friction impulse ≤ μj (exercises RIGID-1 to RIGID-4).";
  }

  void reset() override {
    box_.halfExtents = Vec3(0.4, 0.2, 0.3);
    box_.position = Vec3(0.0, height_, 0.0);
    // Corner first: the body diagonal (1, 1, 1) turned to point straight down, then a little off.
    const Vec3 diagonal = glm::normalize(box_.halfExtents);
    box_.orientation = glm::angleAxis(0.15, Vec3(0, 0, 1)) * glm::rotation(diagonal, -kUp);
    box_.velocity = Vec3(0.3, 0.0, 0.0);
    box_.angularVelocity = spin_ * glm::normalize(Vec3(0.2, 1.0, 0.4));
    contacts_.clear();
    maxPenetration_ = 0.0;
  }

  void step(Real dt) override {
    settings_.gravity = Vec3(0.0, -gravity_, 0.0);
    rigid::tumbleStep(box_, settings_, dt, contacts_);
    for (const rigid::TumbleContact& c : contacts_) maxPenetration_ = std::max(maxPenetration_, c.depth);
  }

  void draw(DebugDraw& d) const override {
    d.box(box_.position, box_.halfExtents, box_.orientation, colors::kOrange);
    for (const rigid::TumbleContact& c : contacts_) {
      d.point(c.point, 8.0f, colors::kRed);
      d.arrow(c.point, c.point + 0.2 * kUp, colors::kYellow);
      if (c.normalImpulse > 0.0) d.arrow(c.point, c.point + 0.3 * c.normalImpulse * kUp, colors::kOrange);
      if (glm::length(c.frictionImpulse) > 0.0) d.arrow(c.point, c.point + 0.3 * c.frictionImpulse, colors::kBlue);
    }
    d.frame(box_.position, box_.orientation, 0.3);
  }

  nlohmann::json metrics() const override {
    const Mat3 inertia = rigid::boxInertiaTensor(box_.mass, box_.halfExtents, box_.orientation);
    const Vec3 l = inertia * box_.angularVelocity;
    Real impulse = 0.0;
    for (const rigid::TumbleContact& c : contacts_) impulse += c.normalImpulse;
    return {{"bodies", 1},
            {"contacts", contacts_.size()},
            {"kinetic_energy_J",
             0.5 * box_.mass * glm::dot(box_.velocity, box_.velocity) + 0.5 * glm::dot(box_.angularVelocity, l)},
            {"energy_J", rigid::tumbleEnergy(box_, settings_)},
            {"momentum", box_.mass * glm::length(box_.velocity)},
            {"angular_momentum", glm::length(glm::cross(box_.position, box_.mass * box_.velocity) + l)},
            {"max_penetration_m", maxPenetration_},
            {"max_joint_error_m", 0.0},
            {"sleeping", 0},
            {"solver_iterations", settings_.sweeps},
            {"normal_impulse_Ns", impulse},
            {"height_m", box_.position.y}};
  }

  std::optional<std::string> nonFiniteState() const override {
    if (!isFinite(box_.position)) return std::string("box position is not finite");
    if (!isFinite(box_.velocity) || !isFinite(box_.angularVelocity)) return std::string("box velocity is not finite");
    return std::nullopt;
  }
  std::optional<Real> energy() const override { return rigid::tumbleEnergy(box_, settings_); }
  Real defaultDt() const override { return 1.0 / 240.0; }
  std::vector<std::string> defaultPlots() const override { return {"energy_J", "contacts"}; }
  std::vector<app::Preset> presets() const override {
    return {{"bouncy", {{"restitution", 0.8}, {"friction", 0.3}}},
            {"clay", {{"restitution", 0.0}, {"friction", 0.8}}},
            {"ice", {{"restitution", 0.3}, {"friction", 0.02}}},
            {"spinning drop", {{"spin", 8.0}, {"height", 3.0}}}};
  }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 0.1, 0.0), 3.6, 0.6, 0.4};
  }

 private:
  rigid::TumbleBox box_;
  rigid::TumbleSettings settings_;
  std::vector<rigid::TumbleContact> contacts_;
  Real gravity_ = kStandardGravity, height_ = 1.5, spin_ = 2.0, maxPenetration_ = 0.0;
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "tumble", TumbleScene);
