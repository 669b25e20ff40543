// Ragdoll lab, scene "boxes": the paper's test 1.
#include "app/runner/scene_registry.h"
#include "physics/ragdoll/builders.h"
#include "ragdoll_scene.h"

namespace pba::lab {
namespace {

class BoxesScene final : public lab::RagdollScene {
 public:
  std::string description() const override {
    return "Test 1: two boxes thrown at each other collide, fall and slide to a stop by friction (particle blue left, "
           "constraint purple right).";
  }

 protected:
  ragdoll::RagdollDesc build() const override { return ragdoll::buildBoxesTest(); }
};

}  // namespace

PBA_REGISTER_SCENE("Ragdolls", "boxes", BoxesScene);

}  // namespace pba::lab
