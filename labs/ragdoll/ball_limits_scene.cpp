// Ragdoll lab, scene "ball-limits": the paper's test 5.
#include "app/runner/scene_registry.h"
#include "physics/ragdoll/builders.h"
#include "ragdoll_scene.h"

namespace pba::lab {
namespace {

class BallLimitsScene final : public lab::RagdollScene {
 public:
  std::string description() const override {
    return "Test 5: four arms on ball joints with cone limits of 0, 45, 90 and 135 degrees fall from horizontal and "
           "stop on their cones.";
  }

 protected:
  ragdoll::RagdollDesc build() const override { return ragdoll::buildLimitsTest(ragdoll::JointKind::Ball); }
};

}  // namespace

PBA_REGISTER_SCENE("Ragdolls", "ball-limits", BallLimitsScene);

}  // namespace pba::lab
