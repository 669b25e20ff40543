// Rigid lab, scene "incline": a box on a plane tilted by `angle` with friction μ. It slides when
// tan θ > μ, with a = g (sin θ − μ cos θ), and stays put otherwise; a ghost box beside it moves by the
// closed form ½ a t².
#include <cmath>

#include "app/runner/scene_registry.h"
#include "world_scene.h"

namespace pba::lab {
namespace {

constexpr Real kBoxHalf = 0.25;  // [m] the sliding cube

class InclineScene final : public lab::WorldScene {
 public:
  InclineScene() {
    params_.angle("angle", &angle_, 0.0, 60.0, "Tilt θ of the plane. It slides when tan θ > μ. Typical 30°.")
        .needsReset();
    params_.real("friction", &friction_, 0.0, 1.5, "", "Coulomb μ of box and plane. Typical 0.3.").needsReset();
  }

  std::string description() const override {
    return "A box on a tilted plane slides with a = g(sin θ − μ cos θ) when tan θ > μ and sticks otherwise; the ghost "
           "beside "
           "it follows the closed form.";
  }

 protected:
  void build(rigid::World& w) override {
    incline_ = rigid::buildIncline(w, angle_, friction_, kBoxHalf);
    time_ = 0.0;
  }
  void afterStep(Real dt) override { time_ += dt; }

  Real expected() const {
    const Real a = gravity_ * (std::sin(angle_) - friction_ * std::cos(angle_));
    return a > 0.0 ? 0.5 * a * time_ * time_ : 0.0;
  }
  Real slide() const { return glm::dot(world_.body(incline_.box).position - incline_.start, incline_.downhill); }

  void extraMetrics(nlohmann::json& j) const override {
    j["slide_distance_m"] = slide();
    j["expected_slide_distance_m"] = expected();
    j["slides"] = std::tan(angle_) > friction_;
  }
  void drawExtra(DebugDraw& d) const override {
    // The closed form, a ghost box one metre to the side.
    const Real s = std::min(expected(), 20.0);
    const Vec3 side(0.0, 0.0, 0.9);
    const Vec3 at = incline_.start + s * incline_.downhill + side;
    d.box(at, Vec3(kBoxHalf), incline_.rotation, Color{0.2f, 0.66f, 0.29f, 0.5f});
    d.text(at + Vec3(0.0, 0.6, 0.0), "closed form", colors::kGreen);
  }
  std::vector<app::Preset> presets() const override {
    return {{"slides", {{"angle", 30.0}, {"friction", 0.3}}},
            {"sticks", {{"angle", 20.0}, {"friction", 0.5}}},
            {"ice", {{"angle", 15.0}, {"friction", 0.02}}},
            {"on the edge", {{"angle", 26.0}, {"friction", 0.5}}}};
  }
  std::vector<std::string> defaultPlots() const override { return {"slide_distance_m", "expected_slide_distance_m"}; }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 4.5, 0.0), 17.0, 0.35, 0.12};  // the box at the top in view at 1280×720
  }

 private:
  Real angle_ = degToRad(30.0), friction_ = 0.3, time_ = 0.0;
  rigid::Incline incline_;
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "incline", InclineScene);

}  // namespace pba::lab
