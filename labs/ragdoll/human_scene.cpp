// Ragdoll lab, scene "human" (the default): the paper's test 8, its 16-bone human (§5, table of part
// sizes, mass ∝ volume, its joints and limits), dropped with both methods side by side.
#include "app/runner/scene_registry.h"
#include "physics/ragdoll/builders.h"
#include "ragdoll_scene.h"

namespace pba::lab {
namespace {

class HumanScene final : public lab::RagdollScene {
 public:
  HumanScene() {
    declareStartParams(height_, tilt_);
    params_.angle("turn", &turn_, -180.0, 180.0, "Turn of the figure about the vertical at the start. Typical 0°.")
        .needsReset();
    params_
        .real("mass", &mass_, 10.0, 200.0, "kg",
              "Total mass, shared by the bones in proportion to their volume. Typical 75 kg.")
        .needsReset();
    params_
        .flag("limits", &limits_,
              "The paper's hinge and cone limits (off: free joints; the figure folds through itself).")
        .needsReset();
  }
  std::string description() const override {
    return "Test 8: the paper's 16-bone human dropped on the ground; both methods come to rest within their joint "
           "limits (orange).";
  }

 protected:
  ragdoll::RagdollDesc build() const override {
    ragdoll::HumanDesc h;
    h.position = Vec3(0.0, height_, 0.0);
    h.orientation = glm::angleAxis(turn_, kUp) * glm::angleAxis(tilt_, Vec3(1.0, 0.0, 0.0));
    h.totalMass = mass_;
    h.limits = limits_;
    return ragdoll::buildHumanRagdoll(h);
  }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 0.0, 0.3), 7.5, 0.0, 0.8};
  }

 private:
  Real height_ = 0.6, tilt_ = degToRad(80.0), turn_ = 0.0, mass_ = 75.0;
  bool limits_ = true;
};

}  // namespace

PBA_REGISTER_SCENE("Ragdolls", "human", HumanScene);

}  // namespace pba::lab
