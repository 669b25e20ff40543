// Cloth lab, scene "hanging" (the default): a square 32 × 32 cloth pinned at two corners falls from the
// horizontal and swings. Switch the solver live; drag any particle with the left mouse button.
#include "cloth_scene.h"

namespace pba::lab {

using namespace pba::cloth;
namespace {

class HangingScene final : public ClothScene {
 public:
  HangingScene() { declareDisplayParams(); }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 1.15, 0.0), 2.8, 0.5, 0.25};
  }
  std::string description() const override {
    return "A square cloth pinned at two corners falls and swings: switch solvers live (1–8) and compare the "
           "stretch near the pins.";
  }

 protected:
  Result<Cloth> build() override {
    grid_ = squareGrid(1.0, Vec3(0.0, 1.6, 0.0), GridPins::TopCorners);
    colliders_.push_back(Collider::plane());  // the floor
    return buildClothGrid(grid_, material_);
  }
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Cloth", "hanging", pba::lab::HangingScene);
