// Hello lab, scene "drop": a ball dropped on the ground with restitution and air drag.
// Exercises HELLO-1 (explicit Euler step) and HELLO-2 (ground bounce) run here; the ground contact is the
// particles lab's contact model (hello::groundContact), so slow impacts are resting contact, not bounces.
#include <cmath>
#include <cstdio>

#include "app/runner/scene_registry.h"
#include "physics/hello/ball.h"

namespace pba::lab {
namespace {

class DropScene final : public app::Scene {
 public:
  DropScene() {
    params_
        .real("mass", &desc_.mass, 0.01, 100.0, "kg", "Mass of the ball. Drag slows a light ball more. Typical 1 kg.")
        .logarithmic();
    params_.real("radius", &desc_.radius, 0.05, 1.0, "m", "Radius of the ball. Typical 0.25 m.");
    params_.real("restitution", &desc_.restitution, 0.0, 1.0, "",
                 "Share of the normal speed a bounce keeps: 0 = clay, 1 = perfectly elastic. Typical 0.8.");
    params_.real("drag", &desc_.drag, 0.0, 5.0, "N·s/m", "Linear air drag coefficient c in F = -c v. Typical 0.1.");
    params_.real("gravity", &desc_.gravity, 0.0, 30.0, "m/s²", "Gravitational acceleration. Earth 9.81, Moon 1.62.");
    params_.real("drop_height", &desc_.dropHeight, 0.0, 10.0, "m", "Initial height of the ball's lowest point.")
        .needsReset();
    params_.real("resting_speed", &desc_.restingSpeed, 0.0, 2.0, "m/s",
                 "Impacts slower than this plus g·dt are resting contact: no bounce, and not counted. "
                 "Typical 0.1 m/s (the particles lab's default).");
  }

  std::string description() const override {
    return "A ball falls and bounces, each apex about restitution² of the last, until it rests (a lively ball "
           "keeps hopping: explicit Euler gains energy in flight).";
  }
  void reset() override {
    state_ = hello::initialState(desc_);
    bounces_ = 0;
    maxHeightSinceBounce_ = hello::heightAboveGround(desc_, state_);
    lastApex_ = maxHeightSinceBounce_;
  }
  void step(Real dt) override {
    if (dragging_) return;
    const hello::BounceResult r = hello::stepDrop(desc_, state_, dt);
    if (r.bounced) {  // real bounces only: resting contact is not one
      ++bounces_;
      lastApex_ = maxHeightSinceBounce_;
      maxHeightSinceBounce_ = 0.0;
    }
    state_ = r.state;
    maxHeightSinceBounce_ = std::max(maxHeightSinceBounce_, hello::heightAboveGround(desc_, state_));
  }
  void draw(DebugDraw& d) const override {
    d.sphere(state_.position, desc_.radius, colors::kOrange);
    d.arrow(state_.position, state_.position + 0.25 * state_.velocity, colors::kBlue);
    const Vec3 foot(state_.position.x, desc_.groundHeight, state_.position.z);
    d.line(foot, state_.position - Vec3(0, desc_.radius, 0), colors::kGrey);
    char label[64];
    std::snprintf(label, sizeof label, "h = %.2f m", hello::heightAboveGround(desc_, state_));
    d.text(state_.position + Vec3(desc_.radius * 1.3, desc_.radius, 0), label, colors::kDark);
    // The drop height, as a reference for the shrinking apexes.
    const Real top = desc_.groundHeight + desc_.dropHeight;
    d.line(Vec3(-1.0, top, 0.0), Vec3(1.0, top, 0.0), colors::kGrey);
  }
  nlohmann::json metrics() const override {
    return {{"height_m", hello::heightAboveGround(desc_, state_)},
            {"speed_m_s", glm::length(state_.velocity)},
            {"energy_J", hello::energy(desc_, state_)},
            {"bounces", bounces_},
            {"resting", glm::length(state_.velocity) == 0.0},
            {"last_apex_m", lastApex_}};
  }
  std::optional<std::string> nonFiniteState() const override { return hello::nonFiniteState(state_); }
  std::optional<Real> energy() const override { return hello::energy(desc_, state_); }
  std::vector<std::string> defaultPlots() const override { return {"height_m", "energy_J"}; }
  std::vector<app::Preset> presets() const override {
    return {{"superball", {{"restitution", 0.95}, {"drag", 0.0}, {"gravity", 9.81}}},
            {"clay", {{"restitution", 0.2}, {"drag", 0.1}, {"gravity", 9.81}}},
            {"moon", {{"restitution", 0.8}, {"drag", 0.0}, {"gravity", 1.62}}},
            {"feather", {{"restitution", 0.5}, {"drag", 3.0}, {"mass", 0.05}, {"gravity", 9.81}}}};
  }
  std::optional<app::PickHit> pick(const app::Ray& ray) const override {
    return app::pickSphere(ray, state_.position, desc_.radius, 0);
  }
  std::vector<app::DragHandle> dragHandles() const override { return {{0, state_.position}}; }
  void drag(int, const Vec3& target) override {
    dragging_ = true;
    const Real floorY = desc_.groundHeight + desc_.radius;
    state_.position = Vec3(target.x, std::max(target.y, floorY), target.z);
    state_.velocity = Vec3(0.0);
    maxHeightSinceBounce_ = hello::heightAboveGround(desc_, state_);
  }
  void release(int) override { dragging_ = false; }

 private:
  hello::BallDesc desc_;
  hello::BallState state_;
  int bounces_ = 0;
  Real maxHeightSinceBounce_ = 0.0;
  Real lastApex_ = 0.0;
  bool dragging_ = false;
};

}  // namespace

PBA_REGISTER_SCENE("Basics", "drop", DropScene);

}  // namespace pba::lab
