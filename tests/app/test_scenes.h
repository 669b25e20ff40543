#pragma once
// Small scenes for the runner's tests: a constant-velocity point whose state is a closed form of
// the step count, and a scene that produces NaN on demand (for the instability guard).
#include <cmath>
#include <limits>

#include "app/runner/scene.h"
#include "app/runner/scene_runner.h"

namespace pba::app::testing {

/// x(t) = v t along x; every step adds v·dt, so x after n steps is exactly n·v·dt (up to rounding).
class ConstantVelocityScene final : public Scene {
 public:
  ConstantVelocityScene() {
    params_.real("speed", &speed, 0.0, 10.0, "m/s", "Speed of the point.");
    params_.integer("count", &count, 1, 100, "", "An integer parameter.").needsReset();
    params_.flag("visible", &visible, "A flag parameter.");
    params_.choice("mode", &mode, {"first", "second", "third"}, "A choice parameter.");
    params_.angle("heading", &heading, -180.0, 180.0, "An angle parameter (radians inside, degrees outside).");
    params_.text("label", &label, "A text parameter.");
  }
  std::string description() const override { return "A point moving at constant speed."; }
  Status validate() override {
    if (label == "invalid") return Error{"label: 'invalid' is not a valid label"};
    return Status::success();
  }
  void reset() override {
    x = 0.0;
    stepsTaken = 0;
  }
  void step(Real dt) override {
    x += speed * dt;
    ++stepsTaken;
    if (poison) x = std::numeric_limits<Real>::quiet_NaN();
  }
  void draw(DebugDraw& d) const override { d.sphere(Vec3(x, 0.5, 0.0), 0.1, colors::kBlue); }
  nlohmann::json metrics() const override { return {{"x_m", x}, {"steps", stepsTaken}}; }
  std::optional<std::string> nonFiniteState() const override {
    if (!std::isfinite(x)) return "point position is not finite";
    return std::nullopt;
  }
  std::optional<Real> energy() const override { return 0.5 * speed * speed + energyBoost; }
  std::optional<Real> energyGainBound(Real reference) const override {
    return driven ? std::nullopt : Scene::energyGainBound(reference);
  }
  std::optional<std::string> divergedState() const override {
    return diverged ? std::optional<std::string>("the test solver diverged") : std::nullopt;
  }
  std::vector<Preset> presets() const override { return {{"fast", {{"speed", 5.0}}}, {"broken", {{"speed", 99.0}}}}; }

  Real speed = 1.0;
  int count = 3;
  bool visible = true;
  int mode = 0;
  Real heading = 0.0;
  std::string label = "none";
  Real x = 0.0;
  int stepsTaken = 0;
  bool poison = false;
  Real energyBoost = 0.0;
  bool driven = false;    ///< states no energy gain bound (only the runaway factor applies)
  bool diverged = false;  ///< the solver says it diverged, with a finite state
};

/// The runner's scene as the constant-velocity scene it was given.
inline ConstantVelocityScene& constantVelocitySceneOf(SceneRunner& r) {
  return static_cast<ConstantVelocityScene&>(r.scene());
}

}  // namespace pba::app::testing
