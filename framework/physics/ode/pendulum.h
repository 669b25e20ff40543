#pragma once
// A pendulum joint for secondary motion (CMU asst4, "Pendulum joints"): a rigid body swinging in the
// xy plane about a pivot that may itself move.
//
//   θ̈ = −[ m ⟨a_p, y⊥⟩ + m g L sin(θ + ψ) ] / I,    L = |C − c|, I = I_cm + m L² (about the pivot)
// θ is the joint angle; y = C − c the centre-of-mass offset from the pivot c, given at θ = 0 as the
// body's geometry (PendulumDesc::comOffset); ψ = atan2(y_x, −y_y) its angle from the downward vertical
// (CMU asst4: "ψ = angle of y with the vertical (atan2)"; asst4 writes sin(θ − ψ) with its own sign
// convention); a_p the pivot's actual acceleration and y⊥ the unit-free perpendicular (y rotated by
// +90°). Departure from asst4: it writes ⟨a, y⊥⟩/L² for the pivot term, which is the point-mass case
// I = m L² of our m⟨a, y⊥⟩/I.
// The pivot's acceleration: analytic when the pivot is scripted (a spline's or a sine's second
// derivative), or the central second difference of its positions over the steps when it is moved by
// hand (pivotAccelerationFromPositions).
// Damping a [1/s] adds ω̇ = −a ω, whose exact solution over a step h is the factor exp(−a h).
//
// Two ways to step it:
//  - stepPendulum(): asst4's own step, symplectic Euler (energy-stable, no temporaries) with the
//    damping applied as the exact factor between kick and drift:
//      ω ← (ω + h θ̈) exp(−a h);  θ ← θ + h ω.
//  - PendulumSystem: the same joint as an ode::SecondOrderSystem (q = θ, v = ω, M = I about the pivot),
//    so that any ode::Integrator steps it; there the damping is a torque −a I ω like any other force
//    and each method integrates the decay exp(−a t) to its own order.
// The pendulum scene uses the first for symplectic-euler (its default, as asst4 prescribes) and the
// second for every other integrator.
#include <functional>

#include "physics/core/result.h"
#include "physics/core/types.h"
#include "physics/ode/ode_system.h"

namespace pba::ode {

struct PendulumDesc {
  Real mass = 1.0;                  ///< [kg] > 0
  Vec3 comOffset{0.0, -1.0, 0.0};   ///< y = C − c [m] at θ = 0 (xy; z ignored), |y| > 0: straight down by default
  Real inertiaCm = 0.02;            ///< I_cm [kg·m²] ≥ 0 about the centre of mass
  Real damping = 0.1;               ///< a [1/s] ≥ 0
  Real gravity = kStandardGravity;  ///< [m/s²]
};
Status validate(const PendulumDesc& desc);

struct PendulumState {
  Real angle = 0.0;            ///< θ [rad]
  Real angularVelocity = 0.0;  ///< ω [rad/s]
};

/// L = |C − c| [m], the pivot to centre of mass distance.
Real comDistance(const PendulumDesc& d);
/// ψ = atan2(y_x, −y_y) [rad]: the angle of y = C − c from the downward vertical (0 = straight below).
Real comOffsetAngle(const PendulumDesc& d);
/// The pivot's acceleration at time t from its positions at t − h, t and t + h [m/s²]: the central
/// second difference (x₊ − 2x + x₋)/h², error A ω⁴ h²/12 for a sine of amplitude A, exact for constant
/// acceleration. For a pivot moved by hand, whose next position is known before the step.
Vec3 pivotAccelerationFromPositions(const Vec3& previous, const Vec3& current, const Vec3& next, Real h);
/// Moment of inertia about the pivot, I = I_cm + m L² [kg·m²].
Real pivotInertia(const PendulumDesc& d);
/// θ̈ for a pivot accelerating at pivotAcceleration [m/s²] (xy components used).
Real angularAcceleration(const PendulumDesc& d, const PendulumState& s, const Vec3& pivotAcceleration);
/// One symplectic Euler step with the exact damping factor between kick and drift (CMU asst4).
PendulumState stepPendulum(const PendulumDesc& d, const PendulumState& s, const Vec3& pivotAcceleration, Real h);
/// Centre of mass relative to the pivot [m].
Vec3 centerOfMassOffset(const PendulumDesc& d, Real angle);
/// Energy in the pivot frame (kinetic about the pivot + gravity, zero at the lowest point) [J].
Real pendulumEnergy(const PendulumDesc& d, const PendulumState& s);

/// The pendulum joint for any ode::Integrator (one coordinate): force = I θ̈(θ, a_p(t)) − a I ω [N·m],
/// inverse mass 1/I. The pivot's acceleration is a function of the system's time.
class PendulumSystem final : public OwnedStateSystem {
 public:
  using PivotAcceleration = std::function<Vec3(Real t)>;  ///< [m/s²] at time t [s]
  explicit PendulumSystem(const PendulumDesc& desc = {}, PivotAcceleration pivotAcceleration = {});

  const PendulumDesc& desc() const { return desc_; }
  /// Changes the body (mass, length, damping, … may change between steps).
  void setDesc(const PendulumDesc& desc);
  void setPivotAcceleration(PivotAcceleration a) { pivotAcceleration_ = std::move(a); }
  PendulumState pendulumState() const { return {positions()[0], velocities()[0]}; }
  void setPendulumState(const PendulumState& s);

  void force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const override;

 private:
  PendulumDesc desc_;
  PivotAcceleration pivotAcceleration_;
};

}  // namespace pba::ode
