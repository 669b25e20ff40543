// Cloth lab, scene "tablecloth": a square cloth falls onto a table (a box) and settles with friction; its
// corners hang down over the edges.
#include "cloth_scene.h"

namespace pba::lab {

using namespace pba::cloth;
namespace {

constexpr Real kTableTop = 0.75;                     // [m]
constexpr Vec3 kTableHalf{0.45, 0.025, 0.45};        // [m] the top
constexpr Real kLegHalf = 0.5 * (kTableTop - 0.05);  // [m]

class TableclothScene final : public ClothScene {
 public:
  TableclothScene() {
    declareDisplayParams();
    clothColor_ = Color{0.80f, 0.12f, 0.16f, 1.0f};
    friction_ = 0.6;
  }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 0.55, 0.0), 3.2, 0.6, 0.5};
  }
  std::string description() const override {
    return "A tablecloth falls onto a table (a box, CLOTH-7): friction holds it on the top, the corners fold over the "
           "edges.";
  }

 protected:
  Result<Cloth> build() override {
    colliders_ = {Collider::box(Vec3(0.0, kTableTop - kTableHalf.y, 0.0), Quat(1.0, 0.0, 0.0, 0.0), kTableHalf),
                  Collider::plane()};
    // A little off-centre: it settles asymmetrically.
    grid_ = squareGrid(1.5, Vec3(0.05, kTableTop + 0.25, 0.03), GridPins::None);
    return buildClothGrid(grid_, material_);
  }
  void drawExtras(DebugDraw& d) const override {
    for (Real sx : {-1.0, 1.0}) {
      for (Real sz : {-1.0, 1.0}) {
        d.box(Vec3(sx * (kTableHalf.x - 0.05), kLegHalf, sz * (kTableHalf.z - 0.05)), Vec3(0.03, kLegHalf, 0.03),
              Quat(1.0, 0.0, 0.0, 0.0), Color{0.45f, 0.30f, 0.18f, 1.0f});
      }
    }
  }
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Cloth", "tablecloth", pba::lab::TableclothScene);
