#pragma once
// The part of a body the constraint solver touches, packed for the inner loops (Box2D v3's b2BodyState
// and b2BodySim): velocities, the pose being integrated, and inverse mass properties. Static and sleeping
// bodies have zero inverse mass and never move inside the solver.
#include <vector>

#include "physics/core/types.h"

namespace pba::rigid {

struct SolverBody {
  Vec3 v{0.0};  ///< [m/s]
  Vec3 w{0.0};  ///< [rad/s] world
  Vec3 c{0.0};  ///< [m] centre of mass (updated every substep)
  Quat q{1, 0, 0, 0};
  Vec3 dp{0.0};        ///< [m] displacement since the start of the step (contact separations)
  Vec3 dtheta{0.0};    ///< [rad] rotation vector Σ ω h since the start of the step
  Real invMass = 0.0;  ///< [1/kg]
  Mat3 invI{0.0};      ///< [1/(kg·m²)] world, fixed over the step
};

/// Applies the impulse P [N·s] at arm r (from the centre of mass) with sign +1 (body B) or −1 (body A).
inline void applyImpulse(SolverBody& b, const Vec3& r, const Vec3& P, Real sign) {
  b.v += sign * b.invMass * P;
  b.w += sign * (b.invI * glm::cross(r, P));
}
/// Applies the angular impulse L [N·m·s].
inline void applyAngularImpulse(SolverBody& b, const Vec3& L, Real sign) { b.w += sign * (b.invI * L); }

/// 1/(J M⁻¹ Jᵀ) of a linear row along unit u at arms rA, rB:
///   k = m_A⁻¹ + m_B⁻¹ + (r_A × u)·I_A⁻¹(r_A × u) + (r_B × u)·I_B⁻¹(r_B × u).
inline Real rowMass(const SolverBody& a, const SolverBody& b, const Vec3& rA, const Vec3& rB, const Vec3& u) {
  const Vec3 ra = glm::cross(rA, u), rb = glm::cross(rB, u);
  const Real k = a.invMass + b.invMass + glm::dot(ra, a.invI * ra) + glm::dot(rb, b.invI * rb);
  return k > 0.0 ? 1.0 / k : 0.0;
}

}  // namespace pba::rigid
