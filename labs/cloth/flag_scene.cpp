// Cloth lab, scene "flag": a flag on a pole in gusty wind. Every triangle feels aerodynamic drag and lift
// (CLOTH-3) from its velocity relative to the wind; gusts travel downwind as a wave.
#include <cmath>

#include "cloth_scene.h"

namespace pba::lab {

using namespace pba::cloth;
namespace {

constexpr Real kPoleX = -0.75, kPoleTop = 2.4, kPoleRadius = 0.03;  // [m]

class FlagScene final : public ClothScene {
 public:
  FlagScene() {
    params_.real("wind", &windSpeed_, 0.0, 30.0, "m/s", "Mean wind along +x. A breeze 3, a strong wind 10.");
    params_.real("gust", &gust_, 0.0, 15.0, "m/s", "Amplitude of the gusts that travel downwind. Typical 3.");
    params_.real("drag_coefficient", &env_.dragCoefficient, 0.0, 3.0, "", "C_D of a flat plate facing the flow ≈ 1.2.");
    params_.real("lift_coefficient", &env_.liftCoefficient, 0.0, 3.0, "", "C_L of the lift model. Typical 0.5.");
    declareDisplayParams();
    clothColor_ = colors::kBlue;
    bendCompliance_ = 300.0;
  }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 1.5, 0.0), 4.2, 0.35, 0.2};
  }
  std::string description() const override {
    return "A flag on a pole in gusty wind: drag and lift on every triangle (CLOTH-3) make it flutter.";
  }

 protected:
  Result<Cloth> build() override {
    const Real width = 1.5, height = 1.0;  // [m]
    grid_ = hangingGrid(resolution_, std::max(2, resolution_ * 2 / 3), width, height,
                        Vec3(kPoleX + 0.5 * width, kPoleTop - 0.5 * height, 0.0), GridPins::None);
    material_.massPerArea = 0.15;
    Result<Cloth> c = buildClothGrid(grid_, material_);
    if (!c) return c;
    for (int j = 0; j < grid_.resolutionY; ++j) {  // the hoist: the column at the pole
      const auto i = static_cast<std::uint32_t>(j * grid_.resolutionX);
      pin(c.value(), i, c.value().position[i]);
    }
    colliders_.push_back(Collider::plane());
    return c;
  }
  void beforeStep(Real, Real t) override {
    // The wind veers slowly by ±20° about +x: a flag aligned with a steady wind is edge-on and still.
    const Real veer = degToRad(20.0) * std::sin(2.0 * kPi * 0.25 * t);
    env_.aerodynamics = true;
    env_.wind.base = windSpeed_ * Vec3(std::cos(veer), 0.0, std::sin(veer));
    env_.wind.gust = gust_;
    env_.wind.frequency = 0.7;
    env_.wind.wavelength = 4.0;
  }
  void drawExtras(DebugDraw& d) const override {
    d.capsule(Vec3(kPoleX, 0.0, 0.0), Vec3(kPoleX, kPoleTop + 0.05, 0.0), kPoleRadius, colors::kDark);
    d.arrow(Vec3(-1.6, 2.7, 0.0), Vec3(-1.6 + 0.06 * windSpeed_, 2.7, 0.0), colors::kTeal);
  }

  Real driveSpeed() const override { return windSpeed_ + gust_; }

 private:
  Real windSpeed_ = 8.0, gust_ = 3.0;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Cloth", "flag", pba::lab::FlagScene);
