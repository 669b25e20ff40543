// Rigid lab, scene "tumble": the course's assessment. A cuboid is dropped corner-first onto the ground;
// its corners are tested against the plane and each contact gets the single collision impulse with
// restitution and a Coulomb friction impulse (the exercises RIGID-1 to RIGID-4, physics/rigid/tumble.h).
// T throws the box again (each throw turned by the golden angle, so no two land alike); a left drag pulls
// the point the window drags (the box's centre, as in the other rigid scenes) with a damped spring, and a
// release throws the box with the velocity it has.
#include <algorithm>
#include <cmath>

#include <glm/gtx/quaternion.hpp>
#include "app/runner/scene_registry.h"

#include "physics/collision/raycast.h"
#include "physics/rigid/tumble.h"

namespace pba::lab {
namespace {

constexpr int kBoxHandle = 0;
constexpr Real kGoldenAngle = 2.399963229728653;  // [rad] π (3 − √5): successive throws spread evenly
// The mouse spring: a damped spring on the grabbed point, stiffness m ω² and damping 2 ζ m ω for the
// box's mass m, so that it pulls any mass at the same 3 Hz, critically damped in the linear part.
// Its force is bounded so that a fast cursor does not fling the box through the ground.
constexpr Real kDragHertz = 3.0;              // [Hz]
constexpr Real kDragDampingRatio = 1.0;       // [1]
constexpr Real kDragMaxAccelerations = 30.0;  // the bound: this many times g on the box's mass

PBA_REGISTER_LAB_KEY('T', "tumble", "throw the box again (a new heading each time)");

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
           "and a friction impulse ≤ μj (exercises RIGID-1 to RIGID-4). T throws it again; drag it to throw it "
           "yourself.";
  }

  void reset() override {
    throws_ = 0;
    drop();
    maxPenetration_ = 0.0;
  }

  bool keyPressed(char key) override {
    if (key != 'T') return false;
    ++throws_;
    drop();
    return true;
  }

  void step(Real dt) override {
    settings_.gravity = Vec3(0.0, -gravity_, 0.0);
    pullGrabbedPoint(dt);
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
    if (dragTarget_) d.line(grabbedPoint(), *dragTarget_, colors::kDark);
  }

  std::optional<app::PickHit> pick(const Ray& ray) const override {
    const collision::Shape shape = collision::makeBox(box_.halfExtents).value();
    const std::optional<collision::RayHit> hit =
        collision::rayCast(shape, collision::Transform{box_.position, box_.orientation}, ray, 1e4);
    if (!hit) return std::nullopt;
    return app::PickHit{kBoxHandle, hit->t, hit->point};
  }
  void drag(int handle, const Vec3& target) override {
    if (handle != kBoxHandle) return;
    if (!dragTarget_) grabLocal_ = glm::inverse(box_.orientation) * (target - box_.position);
    dragTarget_ = target;
  }
  void release(int /*handle*/) override { dragTarget_.reset(); }
  /// Paused: the grabbed point is put on the cursor at once, the box at rest.
  void refresh() override {
    if (!dragTarget_) return;
    box_.position += *dragTarget_ - grabbedPoint();
    box_.velocity = Vec3(0.0);
    box_.angularVelocity = Vec3(0.0);
  }
  std::vector<app::DragHandle> dragHandles() const override { return {{kBoxHandle, box_.position}}; }

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
  /// Drops the box corner-first from the drop height; throw n > 0 turns the heading by n golden angles.
  void drop() {
    box_.halfExtents = Vec3(0.4, 0.2, 0.3);
    box_.position = Vec3(0.0, height_, 0.0);
    // Corner first: the body diagonal (1, 1, 1) turned to point straight down, then a little off.
    const Vec3 diagonal = glm::normalize(box_.halfExtents);
    const Quat heading = glm::angleAxis(kGoldenAngle * throws_, kUp);
    box_.orientation = heading * glm::angleAxis(0.15, Vec3(0, 0, 1)) * glm::rotation(diagonal, -kUp);
    box_.velocity = heading * Vec3(0.3, 0.0, 0.0);
    box_.angularVelocity = spin_ * (heading * glm::normalize(Vec3(0.2, 1.0, 0.4)));
    contacts_.clear();
    dragTarget_.reset();
  }

  Vec3 grabbedPoint() const { return box_.position + box_.orientation * grabLocal_; }

  /// The mouse spring's impulse over dt on the grabbed point: F = m (ω² (target − p) − 2 ζ ω v_p),
  /// |F| ≤ kDragMaxAccelerations m g; Δv = F dt / m and Δω = I⁻¹ (r × F) dt with I from RIGID-1 (only
  /// the linear part while RIGID-1 is a stub and I is not invertible).
  void pullGrabbedPoint(Real dt) {
    if (!dragTarget_) return;
    const Vec3 r = box_.orientation * grabLocal_;
    const Vec3 pointVelocity = box_.velocity + glm::cross(box_.angularVelocity, r);
    const Real omega = 2.0 * kPi * kDragHertz;
    Vec3 force = box_.mass * (omega * omega * (*dragTarget_ - (box_.position + r)) -
                              2.0 * kDragDampingRatio * omega * pointVelocity);
    const Real maxForce = kDragMaxAccelerations * box_.mass * std::max(gravity_, kStandardGravity);
    if (glm::length(force) > maxForce) force *= maxForce / glm::length(force);
    box_.velocity += dt * force / box_.mass;
    const Mat3 inertia = rigid::boxInertiaTensor(box_.mass, box_.halfExtents, box_.orientation);
    const Real det = glm::determinant(inertia);
    if (std::isfinite(det) && det > 0.0) box_.angularVelocity += dt * (glm::inverse(inertia) * glm::cross(r, force));
  }

  rigid::TumbleBox box_;
  rigid::TumbleSettings settings_;
  std::vector<rigid::TumbleContact> contacts_;
  Real gravity_ = kStandardGravity, height_ = 1.5, spin_ = 2.0, maxPenetration_ = 0.0;
  int throws_ = 0;                  ///< T presses since the reset
  std::optional<Vec3> dragTarget_;  ///< [m] where the cursor pulls the grabbed point, while dragging
  Vec3 grabLocal_{0.0};             ///< [m] the grabbed point in the box's frame
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "tumble", TumbleScene);

}  // namespace pba::lab
