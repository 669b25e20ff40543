#pragma once
// The coupled n-link pendulum (CMU asst4's "double/n-pendulums, full compound-pendulum equations"
// extension): n point masses m_k on massless rigid rods of lengths L_k, the first rod hanging from a
// pivot that the character moves. Unlike PendulumChain (pendulum.h), where each link is driven by its
// parent and never acts back on it, every rod here carries a tension that pulls on both of its ends:
// a swinging lower bob drags the upper one, the energy of the whole chain is one quantity.
//
// Formulation: constrained particles (Hairer, Lubich & Wanner, "Geometric Numerical Integration",
// §VII.1.4, RATTLE). Constraints g_k(x) = |x_k − x_{k−1}|² − L_k² = 0, with x_0 = p(t) the pivot; the
// tensions are their Lagrange multipliers: m_k ẍ_k = m_k g − Σ_j λ_j ∇_k g_j. One step of length h:
//   v½ = v + h/2 g − h/2 M⁻¹ Gᵀλ,  x' = x + h v½,  with λ such that g(x') = 0         (SHAKE)
//   v' = v½ + h/2 g − h/2 M⁻¹ G'ᵀμ, with μ such that ġ(x', v') = 0, i.e. the rods do not stretch
// Both multiplier sets are found by Gauss-Seidel over the rods (a rod's correction moves its two ends
// along the rod, by their inverse masses; the pivot has inverse mass 0) to round-off. RATTLE is
// symplectic and second order: undamped with a fixed pivot the energy Σ ½ m|v|² − m g·x oscillates at
// O(h²) without drift. Limiting cases: one link is the simple pendulum; two equal links swing in the
// normal modes ω² = (g/L)(2 ∓ √2) at small angles, with amplitude ratios θ₂/θ₁ = ±√2.
// Damping (ours, as asst4's pendulum joints): the velocities relative to the pivot shrink by exp(−c h).
#include <vector>

#include "physics/core/result.h"
#include "physics/core/types.h"

namespace pba::animation {

struct CoupledPendulum {
  std::vector<Real> masses;      ///< [kg] m_k > 0, bob k at the end of rod k (typical 0.05 for a ponytail)
  std::vector<Real> lengths;     ///< [m] L_k > 0 (typical 0.1)
  Real damping = 0.0;            ///< [1/s] c ≥ 0
  std::vector<Vec3> positions;   ///< [m] world x_k of the bobs
  std::vector<Vec3> velocities;  ///< [m/s] world
  Vec3 pivot{0.0};               ///< [m] world x_0 at the last step
  Vec3 pivotVelocity{0.0};       ///< [m/s]

  int size() const { return static_cast<int>(masses.size()); }
  /// Checks sizes, masses and lengths > 0, damping ≥ 0; the message names the field.
  Status validate() const;
  /// Hangs every rod from `at` along the unit `direction`, at rest.
  void rest(const Vec3& at, const Vec3& direction);
  /// One RATTLE step of h [s] to the pivot's new position [m] and velocity [m/s]; gravity [m/s²].
  void step(const Vec3& newPivot, const Vec3& newPivotVelocity, const Vec3& gravity, Real h);
  /// [J] Σ ½ m_k |v_k − v_pivot|² − m_k g·(x_k − x_pivot): the energy in the pivot's frame (for a fixed
  /// pivot, the mechanical energy with zero potential at the pivot's height).
  Real energy(const Vec3& gravity) const;
  /// [m] Largest | |x_k − x_{k−1}| − L_k | over the rods.
  Real constraintError() const;
};

}  // namespace pba::animation
