// Cloth lab, scene "drape": a cloth dropped on a sphere, a box or a capsule (--set collider=...), with
// friction and the cloth's thickness; it drapes over a sphere and slides off a box's edges. The cloth may
// be any triangle mesh Assimp loads (--set mesh=FILE), welded and scaled to the drop size.
#include "cloth_scene.h"
#include "mesh_import.h"

namespace pba::lab {

using namespace pba::cloth;
namespace {

enum class DrapeCollider { Sphere, Box, Capsule };
constexpr auto kDrapeColliderNames = enumNames<DrapeCollider>(
    {{DrapeCollider::Sphere, "sphere"}, {DrapeCollider::Box, "box"}, {DrapeCollider::Capsule, "capsule"}});
constexpr Real kDropHeight = 1.3;  // [m] of the cloth's centre at the start
constexpr Real kSize = 1.2;        // [m] side of the cloth

class DrapeScene final : public ClothScene {
 public:
  DrapeScene() {
    params_.choiceEnum("collider", &shape_, kDrapeColliderNames, "What the cloth falls on.").needsReset();
    params_.text("mesh", &meshFile_,
                 "A triangle mesh file (any format Assimp reads) to drop instead of the square grid; empty: the grid.");
    params_.needsReset();
    declareDisplayParams();
    clothColor_ = colors::kPurple;
    friction_ = 0.3;
  }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 0.55, 0.0), 2.8, 0.6, 0.45};
  }
  std::string description() const override {
    return "A cloth falls on a sphere, box or capsule (collider parameter): drapes with friction, never inside it.";
  }
  Status validate() override {
    if (meshFile_.empty()) return Status::success();
    const Result<TriangleMesh> m = loadClothMesh(meshFile_, kSize, Vec3(0.0, kDropHeight, 0.0));
    return m ? Status::success() : Status(Error{m.error()});
  }

 protected:
  Result<Cloth> build() override {
    Collider c;
    switch (shape_) {
      case DrapeCollider::Sphere:
        c = Collider::sphere(Vec3(0.0, 0.6, 0.0), 0.35);
        break;
      case DrapeCollider::Box:
        // Tilted about z, off-centre: the cloth slides off its upper face.
        c = Collider::box(Vec3(0.15, 0.45, 0.0), glm::angleAxis(0.35, Vec3(0.0, 0.0, 1.0)), Vec3(0.35, 0.3, 0.35));
        break;
      case DrapeCollider::Capsule:
        c = Collider::capsule(Vec3(0.0, 0.6, 0.0), glm::angleAxis(0.5 * kPi, Vec3(1.0, 0.0, 0.0)), 0.4, 0.15);
        break;
    }
    colliders_ = {c, Collider::plane()};
    if (!meshFile_.empty()) {
      const Result<TriangleMesh> m = loadClothMesh(meshFile_, kSize, Vec3(0.0, kDropHeight, 0.0));
      if (!m) return Error{m.error()};
      return buildCloth(m.value(), material_);
    }
    grid_ = squareGrid(kSize, Vec3(0.0, kDropHeight, 0.0), GridPins::None);
    return buildClothGrid(grid_, material_);
  }

 private:
  DrapeCollider shape_ = DrapeCollider::Sphere;
  std::string meshFile_;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Cloth", "drape", pba::lab::DrapeScene);
