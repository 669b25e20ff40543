// Particles lab, scene "pendulum": the CMU asst4 pendulum joint — symplectic Euler, damping by
// exp(−a h), a centre-of-mass offset, and a pivot that swings back and forth (secondary motion: the
// pendulum lags and overshoots the moving pivot). The integrator is choosable like in the other
// scenes: symplectic-euler (default) is asst4's own step; any other method steps ode::PendulumSystem,
// where the damping is the torque −a I ω.
// The body is given by its centre of mass relative to the pivot, y = C − c (com_x, com_y); the code
// derives L = |y| and ψ = atan2(y_x, −y_y) from it (asst4). The pivot is scripted (a horizontal sine,
// analytic acceleration) until the mouse grabs it; from then on it follows the mouse (smoothed by a
// critically damped spring) and the reaction term uses its actual acceleration, the central second
// difference of its positions over the steps (ode::pivotAccelerationFromPositions).
#include <cmath>

#include "app/runner/scene_registry.h"
#include "common.h"
#include "physics/ode/pendulum.h"

namespace pba::lab {
namespace {

class PendulumScene final : public app::Scene {
 public:
  PendulumScene() {
    params_.real("mass", &desc_.mass, 0.1, 10.0, "kg", "Mass of the swinging body. Typical 1 kg.");
    params_.real("com_x", &desc_.comOffset.x, -2.0, 2.0, "m",
                 "Centre of mass C relative to the pivot c at θ = 0, x part. Non-zero tilts the body: ψ = "
                 "atan2(x, −y) is computed from (C − c). Typical 0.");
    params_.real("com_y", &desc_.comOffset.y, -3.0, -0.2, "m",
                 "Centre of mass relative to the pivot at θ = 0, y part (below the pivot). L = |C − c|. Typical "
                 "−1.5 m.");
    params_.real("damping", &desc_.damping, 0.0, 5.0, "1/s", "a in ω ← ω·exp(−a h). Typical 0.1.");
    params_.real("pivot_amplitude", &amplitude_, 0.0, 2.0, "m",
                 "Horizontal swing of the scripted pivot (drag the pivot box with the mouse to move it by hand "
                 "until reset). Typical 0.5 m.");
    params_.real("pivot_frequency", &frequency_, 0.0, 3.0, "Hz", "Frequency of the pivot's swing. Typical 0.3 Hz.");
    params_.real("gravity", &desc_.gravity, 0.0, 30.0, "m/s²", "Gravitational acceleration. Earth 9.81.");
    params_.angle("initial_angle", &initialAngle_, -170.0, 170.0, "θ at reset.").needsReset();
    lab::addIntegratorParam(params_, &kind_,
                            " Default symplectic-euler: asst4's step, damping as the exact factor exp(−a h); the "
                            "others integrate the damping torque −a I ω like any force.");
  }

  std::string description() const override {
    return "A pendulum hanging from a moving pivot (CMU asst4): it lags, swings up and settles as damping "
           "removes energy. Drag the pivot (dark box) to swing it by hand.";
  }
  Real defaultDt() const override { return 1.0 / 240.0; }

  void reset() override {
    state_ = ode::PendulumState{initialAngle_, 0.0};
    time_ = 0.0;
    initialEnergy_ = ode::pendulumEnergy(desc_, state_);
    integrator_.reset();
    byHand_ = false;
    pivot_ = previousPivot_ = target_ = scriptedPivot(0.0);
    pivotVelocity_ = pivotAcceleration_ = Vec3(0.0);
  }
  void step(Real dt) override {
    rate_.start();
    // The pivot's position at the end of the step and its acceleration at the start (time_).
    Vec3 next, acceleration;
    if (byHand_) {
      // Follow the mouse target with a critically damped spring (ω = kFollow), semi-implicit Euler; the
      // reaction term sees the second difference of the positions the pivot actually takes.
      pivotVelocity_ += dt * (kFollow * kFollow * (target_ - pivot_) - 2.0 * kFollow * pivotVelocity_);
      next = pivot_ + dt * pivotVelocity_;
      acceleration = ode::pivotAccelerationFromPositions(previousPivot_, pivot_, next, dt);
    } else {
      next = scriptedPivot(time_ + dt);
      acceleration = scriptedAcceleration(time_);
    }
    pivotAcceleration_ = acceleration;
    if (kind_ == ode::IntegratorKind::SymplecticEuler) {
      state_ = ode::stepPendulum(desc_, state_, acceleration, dt);
    } else {
      // system_ calls back into this object: bound at each step, so a copy of the scene (rewind) steps
      // with its own pivot.
      system_.setPivotAcceleration([this](Real) { return pivotAcceleration_; });
      system_.setDesc(desc_);
      system_.setPendulumState(state_);  // unchanged values: Verlet keeps its history
      system_.setTime(time_);
      integrator_.setKind(kind_);
      integrator_.step(system_, dt);
      state_ = system_.pendulumState();
    }
    time_ += dt - integrator_.lastShortfall();  // the state's time (adaptive may fall short of dt)
    previousPivot_ = pivot_;
    pivot_ = next;
    rate_.stop(1);
  }
  void draw(DebugDraw& d) const override {
    const Vec3 p = pivot_;
    if (!byHand_) {
      d.line(Vec3(-amplitude_, kPivotHeight, 0) - Vec3(0.3, 0, 0), Vec3(amplitude_, kPivotHeight, 0) + Vec3(0.3, 0, 0),
             colors::kGrey);
    }
    d.box(p, Vec3(0.08), Quat(1, 0, 0, 0), colors::kDark);
    const Vec3 com = p + ode::centerOfMassOffset(desc_, state_.angle);
    // The body: a bar along θ from the pivot (its own axis) and a bob at the centre of mass.
    const Vec3 axis = ode::comDistance(desc_) * Vec3(std::sin(state_.angle), -std::cos(state_.angle), 0.0);
    d.capsule(p, p + axis, 0.03, colors::kOrange);
    d.line(p + axis, com, colors::kOrange);
    d.sphere(com, 0.12 * std::cbrt(desc_.mass), colors::kBlue);
    d.arc(p, Vec3(0, 0, 1), Vec3(0, -1, 0), state_.angle, 0.35, colors::kRed);
  }
  nlohmann::json metrics() const override {
    nlohmann::json j = lab::baseMetrics(kind_, 1, ode::pendulumEnergy(desc_, state_), initialEnergy_, rate_);
    j["angle_rad"] = state_.angle;
    j["angular_velocity_rad_s"] = state_.angularVelocity;
    j["psi_rad"] = ode::comOffsetAngle(desc_);
    j["pivot_x_m"] = pivot_.x;
    j["pivot_acceleration"] = glm::length(pivotAcceleration_);
    return j;
  }
  std::optional<std::string> nonFiniteState() const override {
    if (!std::isfinite(state_.angle) || !std::isfinite(state_.angularVelocity)) return "pendulum angle is not finite";
    return std::nullopt;
  }
  std::vector<std::string> defaultPlots() const override { return {"angle_rad", "energy"}; }
  std::optional<app::PickHit> pick(const app::Ray& ray) const override { return app::pickSphere(ray, pivot_, 0.15, 0); }
  std::vector<app::DragHandle> dragHandles() const override { return {{0, pivot_}}; }
  /// A drag while paused: the pivot held by hand stands where the mouse put it (time does not run, so
  /// it does not follow through the spring of step()).
  void refresh() override {
    if (!byHand_) return;
    pivot_ = previousPivot_ = target_;
    pivotVelocity_ = Vec3(0.0);
  }
  void drag(int, const Vec3& target) override {
    if (!byHand_) {
      // Take over from the script with the pivot's current position and velocity (no jump, no kick).
      const Real w = 2.0 * kPi * frequency_;
      pivotVelocity_ = Vec3(amplitude_ * w * std::cos(w * time_), 0.0, 0.0);
      byHand_ = true;
    }
    target_ = Vec3(target.x, target.y, 0.0);  // the pendulum swings in the xy plane
  }
  std::vector<app::Preset> presets() const override {
    return {{"still pivot", {{"pivot_amplitude", 0.0}, {"initial_angle", 60.0}}},
            {"resonance", {{"pivot_frequency", 0.41}, {"pivot_amplitude", 0.2}, {"damping", 0.05}}},
            {"tilted body", {{"com_x", 0.75}, {"com_y", -1.3}}},
            {"no damping", {{"damping", 0.0}}},
            {"euler gains energy", {{"integrator", "euler"}, {"damping", 0.0}, {"pivot_amplitude", 0.0}}}};
  }

 private:
  static constexpr Real kPivotHeight = 3.0;  // [m]
  static constexpr Real kFollow = 12.0;      // [rad/s] how fast a dragged pivot follows the mouse
  Vec3 scriptedPivot(Real t) const {
    return Vec3(amplitude_ * std::sin(2.0 * kPi * frequency_ * t), kPivotHeight, 0.0);
  }
  // Second derivative of scriptedPivot(): x = A sin ωt ⇒ ẍ = −A ω² sin ωt [m/s²].
  Vec3 scriptedAcceleration(Real t) const {
    const Real w = 2.0 * kPi * frequency_;
    return Vec3(-amplitude_ * w * w * std::sin(w * t), 0.0, 0.0);
  }

  ode::PendulumDesc desc_{1.0, Vec3(0.0, -1.5, 0.0), 0.02, 0.1, kStandardGravity};
  ode::PendulumState state_;
  ode::IntegratorKind kind_ = ode::IntegratorKind::SymplecticEuler;
  ode::Integrator integrator_;
  // The pivot's acceleration over a step is held at its value at the step's start (time_).
  ode::PendulumSystem system_{desc_};
  Vec3 pivot_{0.0, kPivotHeight, 0.0}, previousPivot_{0.0, kPivotHeight, 0.0}, pivotVelocity_{0.0};
  Vec3 target_{0.0, kPivotHeight, 0.0}, pivotAcceleration_{0.0};
  bool byHand_ = false;
  Real amplitude_ = 0.5, frequency_ = 0.3, initialAngle_ = degToRad(30.0), time_ = 0.0, initialEnergy_ = 0.0;
  lab::UpdateRate rate_;
};

}  // namespace

PBA_REGISTER_SCENE("ODE", "pendulum", PendulumScene);

}  // namespace pba::lab
