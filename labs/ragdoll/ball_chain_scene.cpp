// Ragdoll lab, scene "ball-chain": the paper's test 2.
#include "app/runner/scene_registry.h"
#include "physics/ragdoll/builders.h"
#include "ragdoll_scene.h"

namespace pba::lab {
namespace {

class BallChainScene final : public lab::RagdollScene {
 public:
  std::string description() const override {
    return "Test 2: six boxes on ball joints hang from a fixed one, swing down from horizontal and a seventh box falls "
           "onto them.";
  }

 protected:
  ragdoll::RagdollDesc build() const override { return ragdoll::buildChainTest(ragdoll::JointKind::Ball); }
};

}  // namespace

PBA_REGISTER_SCENE("Ragdolls", "ball-chain", BallChainScene);

}  // namespace pba::lab
