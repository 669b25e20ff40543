// Ragdoll lab, scene "hinge-chain": the paper's test 3.
#include "app/runner/scene_registry.h"
#include "physics/ragdoll/builders.h"
#include "ragdoll_scene.h"

namespace pba::lab {
namespace {

class HingeChainScene final : public lab::RagdollScene {
 public:
  std::string description() const override {
    return "Test 3: the chain of test 2 on hinges; presets 1-3 compare 2, 5 and 20 relaxation iterations (the particle "
           "chain stretches with few).";
  }

 protected:
  ragdoll::RagdollDesc build() const override { return ragdoll::buildChainTest(ragdoll::JointKind::Hinge); }
};

}  // namespace

PBA_REGISTER_SCENE("Ragdolls", "hinge-chain", HingeChainScene);

}  // namespace pba::lab
