// Ragdoll lab, scene "pile": several paper humans dropped onto stairs (fixed boxes), both methods.
#include "app/runner/scene_registry.h"
#include "physics/ragdoll/builders.h"
#include "ragdoll_scene.h"

namespace pba::lab {
namespace {

class PileScene final : public lab::RagdollScene {
 public:
  PileScene() {
    params_.integer("humans", &count_, 1, 20, "", "Humans dropped in a column onto the stairs. Typical 4.")
        .needsReset();
  }
  std::string description() const override {
    return "Humans dropped onto stairs tumble over each other and the steps (bone-bone contacts with a broad phase).";
  }
  bool heavy() const override { return true; }  // a stress scene: humans in contact with one another

 protected:
  ragdoll::RagdollDesc build() const override { return ragdoll::buildPile(count_, static_cast<unsigned>(seed())); }
  Real halfSeparation(const ragdoll::RagdollDesc& /*desc*/) const override { return 2.2; }

 private:
  int count_ = 4;
};

}  // namespace

PBA_REGISTER_SCENE("Ragdolls", "pile", PileScene);

}  // namespace pba::lab
