#pragma once
// Position-based constraint kernels (stateless, over arrays of particle data, as in Bender's
// PositionBasedDynamics library): the distance constraint of PBD/XPBD and isometric bending.
//
// XPBD (Macklin, Müller & Chentanez 2016, "XPBD: position-based simulation of compliant constrained
// dynamics"). A constraint C(x) with compliance α (inverse stiffness) has the potential U = ½ C²/α. Per
// substep of length h, with α̃ = α/h² and the multiplier λ accumulated over the iterations of that
// substep (reset to 0 at its start):
//   Δλ = (−C − α̃ λ) / (Σ_k w_k |∇_k C|² + α̃)          (eq. 18)
//   Δx_k = w_k ∇_k C Δλ                                (eq. 17)
// The converged state satisfies C + α̃ λ = 0: the constraint force λ∇C/h² balances the other forces with
// the stiffness 1/α, whatever the number of iterations or substeps. PBD (Müller et al. 2007 §3.3) is the
// same projection with α̃ = 0 and no λ, scaled by a stiffness s ∈ [0, 1]: its effective stiffness then
// depends on the iteration count and the step.
#include <array>
#include <cstdint>
#include <span>

#include "physics/cloth/cloth.h"

namespace pba::cloth {

/// The corrections of one distance-constraint projection.
struct DistanceCorrection {
  Vec3 deltaI{0.0};        ///< Δx_i [m]
  Vec3 deltaJ{0.0};        ///< Δx_j [m]
  Real deltaLambda = 0.0;  ///< Δλ [N·s²] (XPBD's multiplier increment; PBD ignores it)
};

// ***** CLOTH-2: the XPBD distance constraint update with compliance (Macklin et al. 2016, eq. 17–18) *****
// The constraint keeps two particles at their rest length L [m]: C is their distance minus L. Inputs:
// positions [m], inverse masses w_i, w_j [1/kg] (0: pinned), L, compliance α [m/N], the substep h [s] and
// the multiplier λ accumulated so far in this substep. Return the position corrections of both
// particles and the change Δλ of the multiplier.
// (1) The gradient of C with respect to each particle: a unit direction, opposite for the two. When the
//     particles coincide or both are pinned there is nothing to do: return zeros.
// (2) From Macklin et al. eq. 17–18, work out Δλ: the compliance enters scaled by the substep, and the
//     multiplier accumulated so far enters too (that is what makes XPBD independent of the iteration
//     count).
// (3) Each particle moves along its gradient by Δλ weighted by its own inverse mass.
// Check: with α = 0 one call makes the distance exactly L (PBD); a pinned particle never moves; the
// heavier particle moves less; a large compliance barely moves anything.
// *****
DistanceCorrection xpbdDistanceCorrection(const Vec3& xi, const Vec3& xj, Real wi, Real wj, Real restLength,
                                          Real compliance, Real h, Real lambda);

// ***** CLOTH-6: the isometric bending constraint of XPBD (Bergou et al. 2006 §4; Macklin et al. 2016 eq. 17–18) *****
// A stencil (cloth.h, BendingStencil) names the four particles of two triangles that share an edge and
// one weight K_k [1/m] per particle, worked out once on the flat rest shape; its constraint is the vector
// C = Σ_k K_k x_k ∈ ℝ³ [1/m · m = dimensionless], zero for the flat rest pair and for any rigid motion of
// it. Inputs: the positions x [m] (update the stencil's four in place), inverse masses w [1/kg] (0:
// pinned), the compliance α = 1/k_b [1/(N·m)], the substep h [s] and the stencil's multiplier λ ∈ ℝ³
// accumulated so far in this substep (update it in place).
// (1) Evaluate C at the current positions and write down its gradient with respect to one particle:
//     C is linear in the positions, so the gradient is constant (a multiple of the 3 × 3 identity).
// (2) Follow CLOTH-2's XPBD update (eq. 18) with that gradient, component by component: the compliance
//     scaled by the substep, the accumulated multiplier in the numerator, the weighted squared gradients
//     of all four particles in the denominator. When that denominator is zero (every particle pinned,
//     no compliance) do nothing.
// (3) Add Δλ to λ and move each particle along its own gradient by Δλ, weighted by its inverse mass.
// Check: with α = 0 one call makes C exactly zero (C is linear: no iteration needed); a pinned particle
// never moves; the mass-weighted centre Σ m_k x_k stays put (the weights sum to zero); a flat stencil
// is left alone.
// *****
void projectIsometricBending(const BendingStencil& s, std::span<Vec3> x, std::span<const Real> w, Real compliance,
                             Real h, Vec3& lambda);
/// How a Gauss–Seidel sweep treats its constraints: XPBD (compliance by kind, λ accumulated) or PBD
/// (Müller et al. 2007 §3.3: the exact projection, compliance 0, scaled by a stiffness ∈ [0, 1]).
struct SweepMode {
  bool xpbd = true;
  Real pbdStiffness = 1.0;
};
/// One sweep of CLOTH-2 over `links` in their order; lambda holds one multiplier per link.
void sweepDistanceConstraints(std::span<const Link> links, const std::array<Real, kLinkKinds>& compliance,
                              const SweepMode& mode, Real h, std::span<Vec3> x, std::span<const Real> w,
                              std::span<Real> lambda);
/// One sweep over the isometric bending stencils (compliance [1/(N·m)]); lambda: 3 reals per stencil.
void sweepIsometricBending(std::span<const BendingStencil> stencils, Real compliance, const SweepMode& mode, Real h,
                           std::span<Vec3> x, std::span<const Real> w, std::span<Vec3> lambda);

/// Bending energy ½ |C|²/α summed over the stencils [J] (0 when α = 0).
Real bendingEnergy(std::span<const BendingStencil> stencils, std::span<const Vec3> x, Real compliance);
/// ½ C²/α over the distance constraints with their kind's compliance [J] (constraints with α = 0 add 0).
Real constraintEnergy(std::span<const Link> constraints, std::span<const Vec3> x, const ClothMaterial& m);

}  // namespace pba::cloth
