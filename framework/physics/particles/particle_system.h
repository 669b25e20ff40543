#pragma once
// A particle system as a state source for the ODE layer (Lobb notes, "Solver/state separation"):
// state = (x₁…xₙ, v₁…vₙ) ∈ ℝ⁶ⁿ, derivative = (v₁…vₙ, F₁/m₁…Fₙ/mₙ). Forces: the global fields of
// forces.h and the damped springs of springs/spring_network.h. Collisions are applied between steps
// by collision.h (they are discontinuities: the notes' "stop and back up" is replaced by projection).
#include <vector>

#include "physics/ode/ode_system.h"
#include "physics/particles/forces.h"
#include "physics/particles/particles.h"
#include "physics/springs/spring_network.h"

namespace pba::particles {

class ParticleSystem final : public ode::SecondOrderSystem {
 public:
  Particles particles;
  std::vector<springs::Spring> springs;
  ForceDesc forces;

  /// Call after adding or removing particles or changing masses: refreshes the per-coordinate
  /// inverse masses the integrators read.
  void syncMasses();

  /// Kinetic + gravitational/attractor potential + spring potential [J].
  Real energy() const;
  Vec3 momentum() const { return particles.momentum(); }

  std::size_t dofCount() const override { return 3 * particles.size(); }
  std::span<Real> positions() override { return flat(particles.position); }
  std::span<const Real> positions() const override { return flat(particles.position); }
  std::span<Real> velocities() override { return flat(particles.velocity); }
  std::span<const Real> velocities() const override { return flat(particles.velocity); }
  std::span<const Real> inverseMasses() const override { return dofInverseMass_; }
  void force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const override;
  void forceDifferential(Real t, std::span<const Real> q, std::span<const Real> v, std::span<const Real> dq,
                         std::span<const Real> dv, std::span<Real> out) override;
  /// Springs (−K_s, −K_d at both ends) and drag; gravity and the position fields add nothing (their small
  /// ∂f/∂x is left out of the differential too).
  bool forceJacobianDiagonalBlocks(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Mat3> dfdq,
                                   std::span<Mat3> dfdv) const override;
  /// Without springs the particles are uncoupled (groups of 3: fields and drag act on each particle alone),
  /// and implicit Euler solves each particle's 3 × 3 system directly.
  int uncoupledGroupSize() const override { return springs.empty() ? 3 : 0; }
  /// f, and the blocks of forceJacobianDiagonalBlocks() (∂f/∂q = 0: the position fields are left explicit).
  void uncoupledForce(Real t, std::span<const Real> q, std::span<const Real> v, std::size_t first, std::span<Real> f,
                      std::span<Real> dfdq, std::span<Real> dfdv) const override;

 private:
  std::vector<Real> dofInverseMass_;
};

}  // namespace pba::particles
