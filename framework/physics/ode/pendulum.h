#pragma once
// A pendulum joint for secondary motion (CMU asst4, "Pendulum joints"): a rigid body swinging in the
// xy plane about a pivot that may itself move.
//
//   θ̈ = −[ m ⟨a_p, y⊥⟩ + m g L sin(θ + ψ) ] / I,    L = |C − c|, I = I_cm + m L² (about the pivot)
// θ is the joint angle, ψ the angle from the downward vertical of the centre-of-mass offset y = C − c at
// θ = 0 (atan2; the asst4 writes sin(θ − ψ) with its own sign convention), a_p the pivot's acceleration
// and y⊥ the unit-free perpendicular (y rotated by +90°). Departure from asst4: it writes ⟨a, y⊥⟩/L² for
// the pivot term, which is the point-mass case I = m L² of our m⟨a, y⊥⟩/I.
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
  Real mass = 1.0;            ///< [kg] > 0
  Real comDistance = 1.0;     ///< L [m] > 0, pivot to centre of mass
  Real comOffsetAngle = 0.0;  ///< ψ [rad], 0 = centre of mass straight below the pivot at θ = 0
  Real inertiaCm = 0.02;      ///< I_cm [kg·m²] ≥ 0 about the centre of mass
  Real damping = 0.1;         ///< a [1/s] ≥ 0
  Real gravity = kStandardGravity;  ///< [m/s²]
};
Status validate(const PendulumDesc& desc);

struct PendulumState {
  Real angle = 0.0;            ///< θ [rad]
  Real angularVelocity = 0.0;  ///< ω [rad/s]
};

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
  PendulumState pendulumState() const { return {q_[0], v_[0]}; }
  void setPendulumState(const PendulumState& s);

  void force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const override;

 private:
  PendulumDesc desc_;
  PivotAcceleration pivotAcceleration_;
};

}  // namespace pba::ode
