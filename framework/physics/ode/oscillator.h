#pragma once
// Two small systems with closed-form solutions, used by the oscillator and orbit scenes, the integrator
// tests and the benchmarks.
//
// Harmonic oscillator (Lobb notes, "ODE view": ẍ = −(k/m) x = −c x): n independent coordinates, each
//   x(t) = x₀ cos ωt + (v₀/ω) sin ωt,  v(t) = −x₀ ω sin ωt + v₀ cos ωt,  ω = √(k/m),
//   E = m v²/2 + k x²/2 (constant); phase-space orbits are ellipses.
// Kepler orbit: a planet of mass m around a fixed sun, f = −G M m r/|r|³;
//   E = m|v|²/2 − G M m/|r| and L = m r × v are conserved.
#include <vector>

#include "physics/core/types.h"
#include "physics/ode/ode_system.h"

namespace pba::ode {

struct OscillatorDesc {
  Real mass = 1.0;       ///< [kg] > 0
  Real stiffness = 1.0;  ///< [N/m] > 0 (ω = 1 rad/s with the defaults: Lobb's example)
  Real x0 = 1.0;         ///< [m] initial displacement
  Real v0 = 0.0;         ///< [m/s] initial velocity
  int copies = 1;        ///< independent identical coordinates (benchmarks use many)
};

class HarmonicOscillator final : public OwnedStateSystem {
 public:
  explicit HarmonicOscillator(const OscillatorDesc& desc = {});

  Real omega() const;  ///< [rad/s]
  const OscillatorDesc& desc() const { return desc_; }
  /// Exact x(t), v(t) of coordinate 0.
  Real exactPosition(Real t) const;
  Real exactVelocity(Real t) const;
  /// Energy of coordinate i [J].
  Real energy(std::size_t i = 0) const;

  void force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const override;
  /// (−k q_i) M⁻¹_i in one pass: the same numbers as force() then the scaling.
  void acceleration(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const override;
  void forceDifferential(Real t, std::span<const Real> q, std::span<const Real> v, std::span<const Real> dq,
                         std::span<const Real> dv, std::span<Real> out) override;
  /// The copies are independent: f_i = −k q_i, ∂f_i/∂q_i = −k, ∂f_i/∂v_i = 0.
  int uncoupledGroupSize() const override { return 1; }
  void uncoupledForce(Real t, std::span<const Real> q, std::span<const Real> v, std::size_t first, std::span<Real> f,
                      std::span<Real> dfdq, std::span<Real> dfdv) const override;

 private:
  OscillatorDesc desc_;
};

struct OrbitDesc {
  Real gm = 1.0;                  ///< [m³/s²] G·M of the sun (scaled units: a 1 m orbit has period 2π s)
  Real planetMass = 1.0;          ///< [kg]
  Vec3 position{1.0, 0.0, 0.0};   ///< [m] initial, relative to the sun at the origin
  Vec3 velocity{0.0, 0.0, -1.2};  ///< [m/s] initial (1.0 would be circular; 1.2 gives e ≈ 0.44)
};

class KeplerOrbit final : public OwnedStateSystem {
 public:
  explicit KeplerOrbit(const OrbitDesc& desc = {});
  const OrbitDesc& desc() const { return desc_; }
  Vec3 position() const { return {positions()[0], positions()[1], positions()[2]}; }
  Vec3 velocity() const { return {velocities()[0], velocities()[1], velocities()[2]}; }
  Real energy() const;           ///< [J]
  Vec3 angularMomentum() const;  ///< [kg·m²/s]
  /// Period from Kepler's third law, T = 2π √(a³/GM), a from the energy [s].
  Real period() const;

  void force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const override;

 private:
  OrbitDesc desc_;
};

}  // namespace pba::ode
