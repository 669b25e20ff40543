// Cloth lab, scene "curtain": the top row hangs from rings on a rail; the rings slide (moving pins), so
// the curtain opens and closes, bunching into folds.
#include <cmath>

#include "cloth_scene.h"

namespace pba::lab {

using namespace pba::cloth;
namespace {

constexpr Real kRailHeight = 2.2, kWidth = 2.0, kLeft = -1.0;  // [m]

class CurtainScene final : public ClothScene {
 public:
  CurtainScene() {
    params_.real("period", &period_, 1.0, 60.0, "s", "Time to open and close once. Typical 6.");
    params_.real("open_fraction", &openFraction_, 0.1, 1.0, "",
                 "Width of the open (bunched) curtain as a fraction of its flat width. Typical 0.25.");
    declareDisplayParams();
    clothColor_ = colors::kTeal;
    pattern_ = Pattern::Woven;
  }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 1.25, 0.0), 4.2, 0.35, 0.2};
  }
  std::string description() const override {
    return "A curtain on a rail: its top row follows the sliding rings (moving pins) and bunches into folds.";
  }

 protected:
  Result<Cloth> build() override {
    grid_ = hangingGrid(resolution_, resolution_, kWidth, 1.8, Vec3(kLeft + 0.5 * kWidth, kRailHeight - 0.9, 0.0),
                        GridPins::TopRow);
    colliders_.push_back(Collider::plane());
    return buildClothGrid(grid_, material_);
  }
  /// Width the rings span at time t [m]: full at t = 0, bunched to open_fraction at half the period.
  Real span(Real t) const {
    const Real closed = 0.5 + 0.5 * std::cos(2.0 * kPi * t / period_);
    return kWidth * (openFraction_ + (1.0 - openFraction_) * closed);
  }
  void beforeStep(Real dt, Real t) override {
    const Real w = span(t + dt);
    const int nx = resolution_;
    const Real rest = kWidth / (nx - 1), gap = w / (nx - 1);
    // Pleating tape: as the rings close up, the fabric between them folds alternately forward and back,
    // so the top row keeps its length and the pleats run down the curtain.
    const Real depth = 0.5 * std::sqrt(std::max(0.0, rest * rest - gap * gap));
    for (Pin& p : cloth_.pins) {
      if (static_cast<int>(p.particle) == dragged_ || p.particle >= static_cast<std::uint32_t>(nx)) continue;
      const Real z = (p.particle % 2 == 0 ? 1.0 : -1.0) * depth;
      p.target = Vec3(kLeft + gap * static_cast<Real>(p.particle), kRailHeight, z);
    }
  }
  void drawExtras(DebugDraw& d) const override {
    d.capsule(Vec3(kLeft - 0.1, kRailHeight + 0.02, 0.0), Vec3(kLeft + kWidth + 0.1, kRailHeight + 0.02, 0.0), 0.015,
              colors::kDark);
  }

  /// The rings' fastest speed along the rail, |d span/dt| at a quarter period.
  Real driveSpeed() const override { return kPi * kWidth * (1.0 - openFraction_) / period_; }

 private:
  Real period_ = 6.0, openFraction_ = 0.25;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Cloth", "curtain", pba::lab::CurtainScene);
