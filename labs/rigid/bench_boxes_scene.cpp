// Rigid lab, scene "bench-boxes": Bullet's "3000 boxes" benchmark scene (47 layers of 8 × 8 cubes of
// half extent 1 and mass 2) collapsing onto the ground; bench/rigid_bench.cpp times it against Bullet.
#include "app/runner/scene_registry.h"
#include "world_scene.h"

namespace pba::lab {
namespace {

class BenchBoxesScene final : public lab::WorldScene {
 public:
  BenchBoxesScene() {
    settings_.sleeping = false;  // as in Bullet's benchmark, which times every body every step
    params_.integer("layers", &layers_, 1, 47, "", "Layers of 8 × 8 boxes (47: Bullet's 3000).").needsReset();
  }
  std::string description() const override {
    return "Bullet's 3000-box benchmark: 47 layers of 8 × 8 unit boxes lean, topple and pile up.";
  }
  bool heavy() const override { return true; }  // a benchmark: 3,008 bodies, every one awake

 protected:
  void build(rigid::World& w) override {
    rigid::addGround(w, 0.5);
    rigid::addAll(w, rigid::benchBoxes(layers_));
  }
  std::vector<app::Preset> presets() const override {
    return {{"ten layers", {{"layers", 10}}}, {"sap", {{"broad_phase", "sap"}}}, {"sleeping", {{"sleeping", true}}}};
  }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(-6.0, 55.0, -6.0), 200.0, 0.6, 0.2};
  }

 private:
  int layers_ = 47;
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "bench-boxes", BenchBoxesScene);

}  // namespace pba::lab
