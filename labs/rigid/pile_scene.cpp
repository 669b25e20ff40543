// Rigid lab, scene "pile": about a thousand spheres, capsules, boxes and convex hulls rain onto the
// ground and settle into a pile; islands go to sleep (grey) as they come to rest.
#include "app/runner/scene_registry.h"
#include "world_scene.h"

namespace pba::lab {
namespace {

class PileScene final : public lab::WorldScene {
 public:
  PileScene() {
    params_
        .integer("bodies", &count_, 10, 4000, "",
                 "Number of bodies (per eight: a sphere, a capsule, three boxes, three hulls). Typical 1000.")
        .needsReset();
  }
  std::string description() const override {
    return "A thousand mixed shapes (spheres, capsules, boxes, hulls) fall and pile up; resting islands sleep (grey).";
  }
  bool heavy() const override { return true; }  // a stress scene: a thousand bodies in contact

 protected:
  void build(rigid::World& w) override {
    rigid::addGround(w);
    rigid::buildPile(w, count_, static_cast<unsigned>(seed()));
  }
  std::vector<app::Preset> presets() const override {
    return {{"small", {{"bodies", 100}}}, {"sap", {{"broad_phase", "sap"}}}, {"no sleeping", {{"sleeping", false}}}};
  }
  std::vector<std::string> defaultPlots() const override { return {"kinetic_energy_J", "sleeping"}; }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 2.0, 0.0), 16.0, 0.6, 0.45};
  }

 private:
  int count_ = 1000;
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "pile", PileScene);

}  // namespace pba::lab
