// Ragdoll lab, scene "hinge-limits": the paper's test 6.
#include "app/runner/scene_registry.h"
#include "physics/ragdoll/builders.h"
#include "ragdoll_scene.h"

namespace pba::lab {
namespace {

class HingeLimitsScene final : public lab::RagdollScene {
 public:
  std::string description() const override {
    return "Test 6: four arms on hinges limited to plus or minus 0, 45, 90 and 135 degrees fall from horizontal and "
           "stop on their limits.";
  }

 protected:
  ragdoll::RagdollDesc build() const override { return ragdoll::buildLimitsTest(ragdoll::JointKind::Hinge); }
};

}  // namespace

PBA_REGISTER_SCENE("Ragdolls", "hinge-limits", HingeLimitsScene);

}  // namespace pba::lab
