// Rigid lab, scene "dominoes": a row of dominoes, the first one tipped; each falls onto the next.
#include <cmath>

#include "app/runner/scene_registry.h"
#include "world_scene.h"

namespace pba::lab {
namespace {

class DominoesScene final : public lab::WorldScene {
 public:
  DominoesScene() {
    params_.integer("count", &count_, 2, 200, "", "Number of dominoes. Typical 24.").needsReset();
    params_
        .real("spacing", &spacing_, 0.15, 0.9, "m",
              "Distance between neighbours (a domino is 1 m tall). Typical 0.5 m.")
        .needsReset();
    params_.real("friction", &friction_, 0.0, 1.5, "", "Coulomb μ of dominoes and ground. Typical 0.6.").needsReset();
  }
  std::string description() const override {
    return "The first domino is tipped and the wave runs down the row: contacts between rotating boxes, friction at "
           "the "
           "feet.";
  }

 protected:
  void build(rigid::World& w) override {
    rigid::addGround(w, friction_);
    dominoes_ = rigid::buildDominoes(w, count_, spacing_, friction_);
  }
  void extraMetrics(nlohmann::json& j) const override {
    int fallen = 0;
    for (int b : dominoes_) fallen += (world_.body(b).orientation * kUp).y < std::cos(degToRad(45.0));
    j["fallen"] = fallen;
  }
  std::vector<app::Preset> presets() const override {
    return {
        {"close", {{"spacing", 0.3}}}, {"far", {{"spacing", 0.8}}}, {"long row", {{"count", 100}, {"spacing", 0.5}}}};
  }
  std::vector<std::string> defaultPlots() const override { return {"fallen", "kinetic_energy_J"}; }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 0.5, 0.0), 0.6 * count_ * spacing_ + 3.0, 0.5, 0.35};
  }

 private:
  int count_ = 24;
  Real spacing_ = 0.5, friction_ = 0.6;
  std::vector<int> dominoes_;
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "dominoes", DominoesScene);

}  // namespace pba::lab
