// Rigid lab, scene "cradle": Newton's cradle. Steel balls hang on rigid distance joints; the first is
// lifted and released. With restitution 1 the momentum passes along the row; below 1 the swing decays.
#include <cmath>

#include "app/runner/scene_registry.h"
#include "world_scene.h"

namespace pba::lab {
namespace {

class CradleScene final : public lab::WorldScene {
 public:
  CradleScene() : WorldScene(false) {
    // One event per impact (see buildCradle): 480 Hz steps without substeps and a 1 mm speculative
    // distance, below the 4 mm gap between the balls.
    settings_.restitutionThreshold = 0.01;
    settings_.substeps = 1;
    settings_.speculativeDistance = 0.001;
    settings_.sleeping = false;
    params_.integer("balls", &count_, 2, 12, "", "Number of balls. Typical 5.").needsReset();
    params_.real("restitution", &restitution_, 0.0, 1.0, "", "Coefficient of restitution of the balls (1: elastic).")
        .needsReset();
    params_.angle("lift", &lift_, 5.0, 80.0, "Angle the first ball is pulled back. Typical 30°.").needsReset();
  }
  std::string description() const override {
    return "Newton's cradle: the first ball's momentum passes along the row (restitution 1) or spreads and decays "
           "(below 1).";
  }

 protected:
  void build(rigid::World& w) override {
    balls_ = rigid::buildCradle(w, count_, kRadius, 1.0, restitution_, lift_);
    restY_ = w.body(balls_.back()).position.y;
    rise_ = 0.0;
  }
  void afterStep(Real) override { rise_ = std::max(rise_, world_.body(balls_.back()).position.y - restY_); }
  void extraMetrics(nlohmann::json& j) const override {
    // The highest the last ball has swung so far, and the height the first one was lifted to.
    j["last_ball_rise_m"] = rise_;
    j["first_ball_lift_m"] = 1.0 - std::cos(lift_);
    j["energy_J"] = world_.stats().kineticEnergy + world_.stats().potentialEnergy;
  }
  Real defaultDt() const override { return 1.0 / 480.0; }
  std::vector<app::Preset> presets() const override {
    return {{"elastic", {{"restitution", 1.0}}},
            {"lossy", {{"restitution", 0.8}}},
            {"two up", {{"balls", 7}, {"lift", 45.0}}}};
  }
  std::vector<std::string> defaultPlots() const override { return {"energy_J", "last_ball_rise_m"}; }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 1.0, 0.0), 3.5, 0.0, 0.15};
  }

 private:
  static constexpr Real kRadius = 0.1;  // [m]
  int count_ = 5;
  Real restitution_ = 1.0, lift_ = degToRad(30.0);
  std::vector<int> balls_;
  Real restY_ = 0.0, rise_ = 0.0;
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "cradle", CradleScene);

}  // namespace pba::lab
