// Hello lab, scene "spring": a ball hanging from a damped spring (Lobb notes, damped spring force).
// Drag the ball with the left mouse button, let go and watch the oscillation decay. The force is HELLO-3,
// the frame HELLO-4's stable substeps of symplectic Euler, the plotted energy HELLO-5.
#include <cmath>
#include <cstdio>

#include "app/runner/scene_registry.h"
#include "physics/core/basis.h"
#include "physics/hello/ball.h"

namespace pba::lab {
namespace {

constexpr int kCoilTurns = 12;                // turns drawn for the spring's helix
constexpr Real kCoilRadius = 0.12;            // [m]
constexpr Real kBallRadius = 0.22;            // [m] visual and picking radius
constexpr Vec3 kInitialPull{0.8, -0.4, 0.0};  // [m] offset from equilibrium at reset: a visible swing

class SpringScene final : public app::Scene {
 public:
  SpringScene() {
    params_.real("mass", &desc_.mass, 0.05, 20.0, "kg", "Mass of the ball. Typical 1 kg.").logarithmic();
    params_.real("stiffness", &desc_.stiffness, 1.0, 500.0, "N/m", "Spring constant k. Typical 40 N/m.").logarithmic();
    params_.real("rest_length", &desc_.restLength, 0.2, 3.0, "m", "Length of the unloaded spring L. Typical 1.5 m.");
    params_.real("damping", &desc_.damping, 0.0, 10.0, "N·s/m",
                 "Damping along the spring: resists the rate of change of its length. Typical 0.6.");
    params_.real("drag", &desc_.drag, 0.0, 5.0, "N·s/m", "Linear air drag on the ball. Typical 0.05.");
    params_.real("gravity", &desc_.gravity, 0.0, 30.0, "m/s²", "Gravitational acceleration. Earth 9.81.");
  }

  std::string description() const override {
    return "A ball on a damped spring: drag it away and release; damping makes the swing decay to the equilibrium.";
  }
  Real defaultDt() const override { return 1.0 / 240.0; }
  void reset() override {
    state_ = hello::springEquilibrium(desc_);
    state_.position += kInitialPull;
    dragging_ = false;
  }
  void step(Real dt) override {
    if (dragging_) return;
    state_ = hello::stepSpringBall(desc_, state_, dt,
                                   [this](const hello::BallState& s) { return hello::springBallForce(desc_, s); });
  }
  void draw(DebugDraw& d) const override {
    d.box(desc_.anchor + Vec3(0, 0.06, 0), Vec3(0.3, 0.06, 0.3), Quat(1, 0, 0, 0), colors::kGrey);
    drawCoil(d);
    const Color ball = dragging_ ? colors::kYellow : colors::kPurple;
    d.sphere(state_.position, kBallRadius, ball);
    d.arrow(state_.position, state_.position + 0.2 * state_.velocity, colors::kBlue);
    const hello::BallState rest = hello::springEquilibrium(desc_);
    d.point(rest.position, 8.0f, colors::kGreen);
    char label[64];
    std::snprintf(label, sizeof label, "extension %.2f m", hello::springExtension(desc_, state_));
    d.text(state_.position + Vec3(kBallRadius * 1.4, 0, 0), label, colors::kDark);
  }
  nlohmann::json metrics() const override {
    return {{"extension_m", hello::springExtension(desc_, state_)},
            {"speed_m_s", glm::length(state_.velocity)},
            {"energy_J", hello::springEnergy(desc_, state_)}};
  }
  std::optional<std::string> nonFiniteState() const override { return hello::nonFiniteState(state_); }
  std::optional<Real> energy() const override { return hello::springEnergy(desc_, state_); }
  std::vector<std::string> defaultPlots() const override { return {"extension_m", "energy_J"}; }
  std::vector<app::Preset> presets() const override {
    return {{"soft", {{"stiffness", 15.0}, {"damping", 0.3}}},
            {"stiff", {{"stiffness", 200.0}, {"damping", 1.0}}},
            {"undamped", {{"damping", 0.0}, {"drag", 0.0}}},
            {"heavy damping", {{"damping", 8.0}}}};
  }
  std::optional<app::PickHit> pick(const app::Ray& ray) const override {
    return app::pickSphere(ray, state_.position, kBallRadius, 0);
  }
  std::vector<app::DragHandle> dragHandles() const override { return {{0, state_.position}}; }
  void drag(int, const Vec3& target) override {
    dragging_ = true;
    state_.position = target;
    state_.velocity = Vec3(0.0);
  }
  void release(int) override { dragging_ = false; }

 private:
  void drawCoil(DebugDraw& d) const {
    // A helix from the anchor to the ball, so stretching and compression are visible.
    const Vec3 axis = state_.position - desc_.anchor;
    const Real length = glm::length(axis);
    if (length < 1e-9) return;
    const Vec3 n = axis / length;
    const Basis around = orthonormalBasis(n);
    const Vec3 u = around.tangent, v = around.bitangent;
    constexpr int kSegments = kCoilTurns * 16;
    Vec3 previous = desc_.anchor;
    for (int i = 1; i <= kSegments; ++i) {
      const Real s = static_cast<Real>(i) / kSegments;
      const Real angle = 2.0 * kPi * kCoilTurns * s;
      // Taper the coil to a point at both ends.
      const Real r = kCoilRadius * std::min(1.0, std::min(s, 1.0 - s) * 10.0);
      const Vec3 p = desc_.anchor + s * axis + r * (std::cos(angle) * u + std::sin(angle) * v);
      d.line(previous, p, colors::kDark);
      previous = p;
    }
  }

  hello::SpringDesc desc_;
  hello::BallState state_;
  bool dragging_ = false;
};

}  // namespace

PBA_REGISTER_SCENE("Basics", "spring", SpringScene);

}  // namespace pba::lab
