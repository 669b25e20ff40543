// Ragdoll lab, scene "spider": the paper's test 7.
#include "app/runner/scene_registry.h"
#include "physics/ragdoll/builders.h"
#include "ragdoll_scene.h"

namespace pba::lab {
namespace {

class SpiderScene final : public lab::RagdollScene {
 public:
  std::string description() const override {
    return "Test 7: a four-legged spider (ball-jointed upper legs with 45 degree cones, hinged lower legs) dropped on "
           "the ground comes to rest.";
  }

 protected:
  ragdoll::RagdollDesc build() const override { return ragdoll::buildSpider(); }
};

}  // namespace

PBA_REGISTER_SCENE("Ragdolls", "spider", SpiderScene);

}  // namespace pba::lab
