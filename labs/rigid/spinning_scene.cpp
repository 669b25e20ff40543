// Rigid lab, scene "spinning": a free T-handle spun about its intermediate principal axis flips over and
// back again and again (the Dzhanibekov effect), while its energy and |L| stay constant. Only the
// gyroscopic term shows this; switch it off and the handle spins on about a fixed axis.
#include <cmath>

#include "app/runner/scene_registry.h"
#include "world_scene.h"

namespace pba::lab {
namespace {

class SpinningScene final : public lab::WorldScene {
 public:
  SpinningScene() : WorldScene(false) {
    settings_.gyroscopic = rigid::GyroscopicMode::Midpoint;
    settings_.sleeping = false;
    gravity_ = 0.0;
    params_
        .real("spin", &spin_, 0.5, 30.0, "rad/s", "Spin about the intermediate axis (along the bar). Typical 6 rad/s.")
        .needsReset();
    params_
        .real("perturbation", &perturbation_, 0.0, 1.0, "rad/s",
              "Small spin about the other axes that grows into the flip.")
        .needsReset();
  }
  std::string description() const override {
    return "A T-handle spinning about its intermediate axis flips over periodically; energy and |L| stay constant "
           "(gyroscopic term on).";
  }

 protected:
  void build(rigid::World& w) override {
    handle_ = rigid::buildTHandle(w, spin_, perturbation_);
    lastSign_ = 1;
    flips_ = 0;
    l0_ = glm::length(rigid::angularMomentum(w.body(handle_.body)));
    e0_ = rigid::kineticEnergy(w.body(handle_.body));
  }
  void afterStep(Real) override {
    // A flip: the bar's axis reverses its direction relative to L.
    const rigid::Body& b = world_.body(handle_.body);
    const Vec3 l = rigid::angularMomentum(b);
    const int sign = glm::dot(b.orientation * Vec3(1, 0, 0), l) >= 0.0 ? 1 : -1;
    if (sign != lastSign_) ++flips_, lastSign_ = sign;
  }
  void extraMetrics(nlohmann::json& j) const override {
    const rigid::Body& b = world_.body(handle_.body);
    j["flips"] = flips_;
    j["angular_momentum_drift"] = glm::length(rigid::angularMomentum(b)) / l0_ - 1.0;
    j["energy_drift"] = rigid::kineticEnergy(b) / e0_ - 1.0;
  }
  void drawExtra(DebugDraw& d) const override {
    const rigid::Body& b = world_.body(handle_.body);
    const Quat& q = b.orientation;
    d.box(b.position + q * handle_.barCenter, handle_.barHalf, q, colors::kOrange);
    d.box(b.position + q * handle_.shaftCenter, handle_.shaftHalf, q, colors::kBlue);
    const Vec3 l = rigid::angularMomentum(b);
    d.arrow(b.position, b.position + 0.8 * l / std::max(glm::length(l), 1e-12), colors::kGreen);
    d.text(b.position + 0.9 * l / std::max(glm::length(l), 1e-12), "L", colors::kGreen);
    d.arrow(b.position, b.position + 0.08 * b.angularVelocity, colors::kPurple);
  }
  std::vector<app::Preset> presets() const override {
    return {{"gyroscopic off", {{"gyroscopic", "off"}}},
            {"implicit (Catto)", {{"gyroscopic", "implicit"}}},
            {"fast", {{"spin", 15.0}}}};
  }
  std::vector<std::string> defaultPlots() const override { return {"kinetic_energy_J", "angular_momentum"}; }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 1.5, 0.0), 3.0, 0.6, 0.3};
  }

 private:
  rigid::THandle handle_;
  Real spin_ = 6.0, perturbation_ = 0.01, l0_ = 1.0, e0_ = 1.0;
  int flips_ = 0, lastSign_ = 1;
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "spinning", SpinningScene);

}  // namespace pba::lab
