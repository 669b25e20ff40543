// Cloth lab, scene "tear": a cloth held along its border; a heavy ball descends through it and the edges
// stretched beyond the tear threshold split the mesh (or pull a particle with the mouse until it tears).
#include <algorithm>

#include "cloth_scene.h"

namespace pba::lab {

using namespace pba::cloth;
namespace {

constexpr Real kClothHeight = 1.2, kBallStart = 1.7;  // [m]

class TearScene final : public ClothScene {
 public:
  TearScene() {
    params_.real("ball_speed", &ballSpeed_, 0.0, 3.0, "m/s", "Speed of the heavy ball pushing down. Typical 0.4.");
    params_.real("ball_radius", &ballRadius_, 0.05, 0.5, "m", "Radius of the ball. Typical 0.18.").needsReset();
    declareDisplayParams();
    settings_.tearing.enabled = true;
    settings_.tearing.threshold = 0.25;
    compliance_ = 2e-4;
    clothColor_ = colors::kOrange;
    friction_ = 0.2;
  }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 0.9, 0.0), 3.0, 0.6, 0.55};
  }
  std::string description() const override {
    return "A ball pushes through a cloth held at its border until it tears; the mesh splits and stays valid.";
  }

 protected:
  Result<Cloth> build() override {
    grid_ = squareGrid(1.2, Vec3(0.0, kClothHeight, 0.0), GridPins::None);
    Result<Cloth> c = buildClothGrid(grid_, material_);
    if (!c) return c;
    const int n = resolution_;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        if (i == 0 || j == 0 || i == n - 1 || j == n - 1) {
          const auto k = static_cast<std::uint32_t>(j * n + i);
          pin(c.value(), k, c.value().position[k]);
        }
      }
    }
    colliders_ = {Collider::sphere(Vec3(0.08, kBallStart, 0.05), ballRadius_), Collider::plane()};
    return c;
  }
  void beforeStep(Real dt, Real) override {
    Collider& ball = colliders_[0];
    const Real floorStop = ballRadius_;  // it rests on the floor at the end
    Vec3& center = ball.pose.position;
    ball.velocity = center.y > floorStop ? Vec3(0.0, -ballSpeed_, 0.0) : Vec3(0.0);
    center.y = std::max(floorStop, center.y - ballSpeed_ * dt);
  }

  /// The ball is kinematic: it strains the cloth until it tears, whatever that costs, so its work has no
  /// bound below the tear itself; only the runaway factor applies.
  std::optional<Real> energyGainBound(Real) const override { return std::nullopt; }

 private:
  Real ballSpeed_ = 0.4, ballRadius_ = 0.18;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Cloth", "tear", pba::lab::TearScene);
