// Rigid lab, scene "incline": a box on a plane tilted by `angle` with friction μ. It slides when
// tan θ > μ, with a = g (sin θ − μ cos θ), and stays put otherwise; a ghost box beside it moves by the
// closed form ½ a t².
#include <cmath>

#include "app/scene_registry.h"
#include "world_scene.h"

namespace {
using namespace pba;

constexpr Real kBoxHalf = 0.25;     // [m] the sliding cube
constexpr Real kRampHalfLength = 12.0;

class InclineScene final : public lab::WorldScene {
 public:
  InclineScene() {
    params_.angle("angle", &angle_, 0.0, 60.0, "Tilt θ of the plane. It slides when tan θ > μ. Typical 30°.").needsReset();
    params_.real("friction", &friction_, 0.0, 1.5, "", "Coulomb μ of box and plane. Typical 0.3.").needsReset();
  }

  std::string description() const override {
    return "A box on a tilted plane slides with a = g(sin θ − μ cos θ) when tan θ > μ and sticks otherwise; the ghost beside "
           "it follows the closed form.";
  }

 protected:
  void build(rigid::World& w) override {
    rampRotation_ = glm::angleAxis(angle_, Vec3(0.0, 0.0, 1.0));  // downhill is −x along the ramp
    const Vec3 rampHalf(kRampHalfLength, 0.25, 1.5);
    rampCenter_ = Vec3(0.0, 4.0, 0.0);
    rigid::BodyDesc ramp;
    ramp.type = rigid::BodyType::Static;
    ramp.shape = collision::makeBox(rampHalf).value();
    ramp.position = rampCenter_;
    ramp.orientation = rampRotation_;
    ramp.friction = friction_;
    ramp.color = colors::kGrey;
    w.addBody(ramp);
    normal_ = rampRotation_ * kUp;
    downhill_ = rampRotation_ * Vec3(-1.0, 0.0, 0.0);
    start_ = rampCenter_ + (rampHalf.y + kBoxHalf) * normal_ - 0.6 * kRampHalfLength * downhill_;
    rigid::BodyDesc box;
    box.shape = collision::makeBox(Vec3(kBoxHalf)).value();
    box.position = start_;
    box.orientation = rampRotation_;
    box.friction = friction_;
    box.color = colors::kOrange;
    box.name = "slider";
    box_ = w.addBody(box).value();
    time_ = 0.0;
  }
  void afterStep(Real dt) override { time_ += dt; }

  Real expected() const {
    const Real a = gravity_ * (std::sin(angle_) - friction_ * std::cos(angle_));
    return a > 0.0 ? 0.5 * a * time_ * time_ : 0.0;
  }
  Real slide() const { return glm::dot(world_.body(box_).position - start_, downhill_); }

  void extraMetrics(nlohmann::json& j) const override {
    j["slide_distance_m"] = slide();
    j["expected_slide_distance_m"] = expected();
    j["slides"] = std::tan(angle_) > friction_;
  }
  void drawExtra(DebugDraw& d) const override {
    // The closed form, a ghost box one metre to the side.
    const Real s = std::min(expected(), 1.6 * kRampHalfLength);
    const Vec3 side(0.0, 0.0, 0.9);
    d.box(start_ + s * downhill_ + side, Vec3(kBoxHalf), rampRotation_, Color{0.2f, 0.66f, 0.29f, 0.5f});
    d.text(start_ + s * downhill_ + side + Vec3(0.0, 0.6, 0.0), "closed form", colors::kGreen);
  }
  std::vector<app::Preset> presets() const override {
    return {{"slides", {{"angle", 30.0}, {"friction", 0.3}}}, {"sticks", {{"angle", 20.0}, {"friction", 0.5}}},
            {"ice", {{"angle", 15.0}, {"friction", 0.02}}}, {"on the edge", {{"angle", 26.0}, {"friction", 0.5}}}};
  }
  std::vector<std::string> defaultPlots() const override { return {"slide_distance_m", "expected_slide_distance_m"}; }
  std::optional<app::CameraView> preferredView() const override { return app::CameraView{Vec3(0.0, 4.0, 0.0), 16.0, 0.15, 0.25}; }

 private:
  Real angle_ = degToRad(30.0), friction_ = 0.3, time_ = 0.0;
  Quat rampRotation_{1, 0, 0, 0};
  Vec3 rampCenter_{0.0}, normal_{0.0}, downhill_{0.0}, start_{0.0};
  int box_ = -1;
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "incline", InclineScene);
