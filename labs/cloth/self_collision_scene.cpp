// Cloth lab, scene "self-collision": Ten Minute Physics #15's ribbon — 30 × 200 particles 1 cm apart, 10
// substeps — stands on its short edge, falls and folds onto itself on the floor. Self-collision (dense
// spatial hash, particles kept a thickness apart) lets no layer pass through another: the metric
// self_intersections_max counts, over the whole run, pairs closer than half the thickness.
#include <random>

#include "cloth_scene.h"

namespace pba::lab {

using namespace pba::cloth;
namespace {

constexpr Real kSpacing = 0.01;  // [m] TMP #15

class SelfCollisionScene final : public ClothScene {
 public:
  SelfCollisionScene() {
    declareDisplayParams();
    resolution_ = 30;
    settings_.selfCollision = true;
    settings_.selfFriction = 0.1;
    settings_.substeps = 10;
    // Four sweeps a substep, the floor between them (the last three over the pairs in contact): with TMP's
    // one, the weight of the pile pressed its lowest layers within half a thickness now and then (1–3
    // pairs in seeds 1–5).
    settings_.selfCollisionSweeps = 4;
    thickness_ = kSpacing;
    // TMP's bending: distance links across the inner edges, soft (TMP's compliance 1 with 1 kg particles is
    // softer still; with 20 mg particles 100 m/N bends as readily).
    settings_.bending = BendingModel::Distance;
    bendLinkCompliance_ = 100.0;
    friction_ = 0.5;
    countIntersections_ = true;
    clothColor_ = Color{0.20f, 0.45f, 0.80f, 1.0f};
  }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.1, 0.3, 0.0), 1.6, 0.6, 0.6};
  }
  std::string description() const override {
    return "TMP #15's 30 × 200 ribbon falls and folds onto itself: self-collision keeps every layer apart.";
  }
  // A benchmark: TMP #15's ribbon, 6,000 particles and 10 substeps, timed against its own goal
  // (docs/performance-cloth.md), not the 2 ms budget of the teaching scenes.
  bool heavy() const override { return true; }

 protected:
  Result<Cloth> build() override {
    const int nx = resolution_, ny = resolution_ * 20 / 3;  // 30 × 200
    const Real height = kSpacing * (ny - 1);
    grid_ = hangingGrid(nx, ny, kSpacing * (nx - 1), height, Vec3(0.0, 0.05 + 0.5 * height, 0.0), GridPins::None);
    colliders_.push_back(Collider::plane());
    Result<Cloth> c = buildClothGrid(grid_, material_);
    if (!c) return c;
    // TMP's jitter: a tiny random offset out of the plane breaks the symmetry of the fall (seeded).
    std::mt19937_64 rng(seed());
    std::uniform_real_distribution<Real> jitter(-0.001 * kSpacing, 0.001 * kSpacing);
    for (Vec3& x : c.value().position) x.z += jitter(rng);
    return c;
  }
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Cloth", "self-collision", pba::lab::SelfCollisionScene);
