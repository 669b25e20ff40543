// Particles lab, scene "pendulum": the CMU asst4 pendulum joint — symplectic Euler, damping by
// exp(−a h), a centre-of-mass offset, and a pivot that swings back and forth (secondary motion: the
// pendulum lags and overshoots the moving pivot). The integrator is choosable like in the other
// scenes: symplectic-euler (default) is asst4's own step; any other method steps ode::PendulumSystem,
// where the damping is the torque −a I ω.
#include <cmath>

#include "app/scene_registry.h"
#include "common.h"
#include "physics/ode/pendulum.h"

namespace {
using namespace pba;

class PendulumScene final : public app::Scene {
 public:
  PendulumScene() {
    params_.real("mass", &desc_.mass, 0.1, 10.0, "kg", "Mass of the swinging body. Typical 1 kg.");
    params_.real("length", &desc_.comDistance, 0.2, 3.0, "m", "Pivot to centre of mass L. Typical 1.5 m.");
    params_.angle("com_offset", &desc_.comOffsetAngle, -90.0, 90.0,
                  "Angle ψ of the centre of mass from straight below the pivot at θ = 0: the body hangs tilted.");
    params_.real("damping", &desc_.damping, 0.0, 5.0, "1/s", "a in ω ← ω·exp(−a h). Typical 0.1.");
    params_.real("pivot_amplitude", &amplitude_, 0.0, 2.0, "m", "Horizontal swing of the pivot. Typical 0.5 m.");
    params_.real("pivot_frequency", &frequency_, 0.0, 3.0, "Hz", "Frequency of the pivot's swing. Typical 0.3 Hz.");
    params_.real("gravity", &desc_.gravity, 0.0, 30.0, "m/s²", "Gravitational acceleration. Earth 9.81.");
    params_.angle("initial_angle", &initialAngle_, -170.0, 170.0, "θ at reset.").needsReset();
    lab::addIntegratorParam(params_, &kind_,
                            " Default symplectic-euler: asst4's step, damping as the exact factor exp(−a h); the "
                            "others integrate the damping torque −a I ω like any force.");
  }

  PendulumScene(const PendulumScene&) = delete;  // system_ calls back into this object
  PendulumScene& operator=(const PendulumScene&) = delete;

  std::string description() const override {
    return "A pendulum hanging from a moving pivot (CMU asst4): it lags, swings up and settles as damping "
           "removes energy.";
  }
  Real defaultDt() const override { return 1.0 / 240.0; }

  void reset() override {
    state_ = ode::PendulumState{initialAngle_, 0.0};
    time_ = 0.0;
    initialEnergy_ = ode::pendulumEnergy(desc_, state_);
    integrator_.reset();
  }
  void step(Real dt) override {
    rate_.start();
    if (kind_ == ode::IntegratorKind::SymplecticEuler) {
      state_ = ode::stepPendulum(desc_, state_, pivotAcceleration(time_), dt);
    } else {
      system_.setDesc(desc_);
      system_.setPendulumState(state_);  // unchanged values: Verlet keeps its history
      system_.setTime(time_);
      integrator_.setKind(kind_);
      integrator_.step(system_, dt);
      state_ = system_.pendulumState();
    }
    time_ += dt;
    rate_.stop(1);
  }
  void draw(DebugDraw& d) const override {
    const Vec3 p = pivot();
    d.line(Vec3(-amplitude_, kPivotHeight, 0) - Vec3(0.3, 0, 0), Vec3(amplitude_, kPivotHeight, 0) + Vec3(0.3, 0, 0), colors::kGrey);
    d.box(p, Vec3(0.08), Quat(1, 0, 0, 0), colors::kDark);
    const Vec3 com = p + ode::centerOfMassOffset(desc_, state_.angle);
    // The body: a bar along θ from the pivot (its own axis) and a bob at the centre of mass.
    const Vec3 axis = desc_.comDistance * Vec3(std::sin(state_.angle), -std::cos(state_.angle), 0.0);
    d.capsule(p, p + axis, 0.03, colors::kOrange);
    d.line(p + axis, com, colors::kOrange);
    d.sphere(com, 0.12 * std::cbrt(desc_.mass), colors::kBlue);
    d.arc(p, Vec3(0, 0, 1), Vec3(0, -1, 0), state_.angle, 0.35, colors::kRed);
  }
  nlohmann::json metrics() const override {
    nlohmann::json j = lab::baseMetrics(kind_, 1, ode::pendulumEnergy(desc_, state_), initialEnergy_, rate_);
    j["angle_rad"] = state_.angle;
    j["angular_velocity_rad_s"] = state_.angularVelocity;
    return j;
  }
  std::optional<std::string> nonFiniteState() const override {
    if (!std::isfinite(state_.angle) || !std::isfinite(state_.angularVelocity)) return "pendulum angle is not finite";
    return std::nullopt;
  }
  std::vector<std::string> defaultPlots() const override { return {"angle_rad", "energy"}; }
  std::vector<app::Preset> presets() const override {
    return {{"still pivot", {{"pivot_amplitude", 0.0}, {"initial_angle", 60.0}}},
            {"resonance", {{"pivot_frequency", 0.41}, {"pivot_amplitude", 0.2}, {"damping", 0.05}}},
            {"tilted body", {{"com_offset", 30.0}}},
            {"no damping", {{"damping", 0.0}}},
            {"euler gains energy", {{"integrator", "euler"}, {"damping", 0.0}, {"pivot_amplitude", 0.0}}}};
  }

 private:
  static constexpr Real kPivotHeight = 3.0;  // [m]
  Vec3 pivot() const { return Vec3(amplitude_ * std::sin(2.0 * kPi * frequency_ * time_), kPivotHeight, 0.0); }
  // Second derivative of pivot(): x = A sin ωt ⇒ ẍ = −A ω² sin ωt [m/s²].
  Vec3 pivotAcceleration(Real t) const {
    const Real w = 2.0 * kPi * frequency_;
    return Vec3(-amplitude_ * w * w * std::sin(w * t), 0.0, 0.0);
  }

  ode::PendulumDesc desc_{1.0, 1.5, 0.0, 0.02, 0.1, kStandardGravity};
  ode::PendulumState state_;
  ode::IntegratorKind kind_ = ode::IntegratorKind::SymplecticEuler;
  ode::Integrator integrator_;
  ode::PendulumSystem system_{desc_, [this](Real t) { return pivotAcceleration(t); }};
  Real amplitude_ = 0.5, frequency_ = 0.3, initialAngle_ = degToRad(30.0), time_ = 0.0, initialEnergy_ = 0.0;
  lab::UpdateRate rate_;
};

}  // namespace

PBA_REGISTER_SCENE("ODE", "pendulum", PendulumScene);
