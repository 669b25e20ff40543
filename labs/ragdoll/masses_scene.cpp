// Ragdoll lab, scene "masses": the paper's test 4.
#include "app/runner/scene_registry.h"
#include "physics/ragdoll/builders.h"
#include "ragdoll_scene.h"

namespace pba::lab {
namespace {

class MassesScene final : public lab::RagdollScene {
 public:
  std::string description() const override {
    return "Test 4: a box 8 times larger and heavier slides into a small one: the big one dominates and neither sinks "
           "into the floor.";
  }

 protected:
  ragdoll::RagdollDesc build() const override { return ragdoll::buildMassesTest(); }
};

}  // namespace

PBA_REGISTER_SCENE("Ragdolls", "masses", MassesScene);

}  // namespace pba::lab
