#pragma once
// Implicit Euler for the mass-spring cloth after Baraff & Witkin 1998, "Large steps in cloth simulation":
// backward Euler, one Newton step per time step, solved by the filtered PCG of §5.3 (pcg.h).
//
// Derivation (B&W §4.1, eq. 15–18). Backward Euler takes the force at the end of the step,
//   v₁ = v₀ + h M⁻¹ f(x₀ + h v₁, v₁),   x₁ = x₀ + h v₁.
// One Newton step linearises f about (x₀, v₀) with K = ∂f/∂x, D = ∂f/∂v (forces.h):
//   (M − h D − h² K) Δv = h (f₀ + h K v₀),  v₁ = v₀ + Δv.                         (B&W eq. 16, × M)
// Unknown v₁ instead of Δv: adding A v₀ to both sides with A = M − h D − h² K gives
//   A v₁ = M v₀ + h (f₀ − D v₀),
// and when the damping forces are linear in v (spring damping k_d n nᵀ(v_j − v_i), Rayleigh mass damping
// −c M v; both hold here) D v₀ is exactly the damping force, so f₀ − D v₀ is the force without damping:
//   A v₁ = M v₀ + h f_undamped(x₀, v₀).
// The aerodynamic force is left explicit (in f, not in D). Pins prescribe v₁ (the pin's velocity) and
// contacts its normal component (the collider's), through the filter S of §5.3. Limiting cases: h → 0
// recovers explicit Euler; on one undamped spring every step shrinks the energy by 1/(1 + ω²h²) at any h.
// Contacts whose constraint force pulls (adhesion) are released for the next step (B&W §5.3); Coulomb
// friction bounds the tangential velocity change by μ times the normal impulse the constraint applied.
#include <span>
#include <vector>

#include "physics/cloth/cloth.h"
#include "physics/cloth/colliders.h"
#include "physics/cloth/forces.h"
#include "physics/cloth/pcg.h"

namespace pba::cloth {

// ***** CLOTH-5: the matrix–vector product of the implicit system (Baraff & Witkin 1998, eq. 16) *****
// Compute out = A y with A = M − h ∂f/∂v − h² ∂f/∂x for the cloth's springs and mass damping, without
// building A (the conjugate gradient only ever needs products):
// (1) The mass and the Rayleigh mass damping f = −c m v (so −h ∂f/∂v = +h c M):
//     out_i = (1 + h c) m_i y_i for every particle.
// (2) Each spring s couples its ends i, j. With Δy = y_j − y_i, its stiffness block applied to Δy is
//     K_s Δy = lateral Δy + (stiffness − lateral) n (n·Δy) and its damping block D_s Δy = damping n (n·Δy)
//     (SpringJacobian in forces.h). Since ∂f_i/∂x_j = K_s and ∂f_i/∂x_i = −K_s (the same for D_s),
//     the spring's share of −h D y − h² K y is −t on particle i and +t on particle j, with
//     t = h² K_s Δy + h D_s Δy.
// (3) Pins and contacts are not your concern: the solver filters the result.
// *****
void implicitSystemProduct(std::span<const SpringJacobian> springs, std::span<const Real> mass, Real massDamping,
                           Real h, std::span<const Vec3> y, std::span<Vec3> out);

enum class Preconditioner {
  None,         ///< P = I
  BlockJacobi,  ///< the 3 × 3 diagonal blocks of A, probed from the product itself (pcg.h)
};

struct ImplicitSettings {
  PcgSettings cg;
  Preconditioner preconditioner = Preconditioner::BlockJacobi;
  SpringJacobianSettings jacobian;
  bool contactConstraints = true;  ///< contacts through the filter (B&W §5.3); else projection only
};

struct ImplicitStats {
  PcgStats cg;
  std::size_t contactConstraints = 0;  ///< particles whose normal velocity the filter prescribed
};

/// Scratch and memory of the implicit solver (reused: stepping does not allocate once sized).
struct ImplicitWorkspace {
  std::vector<SpringJacobian> jacobians;
  std::vector<Vec3> force, b, velocity, z, probeIn, probeOut;
  std::vector<ParticleFilter> filter;
  std::vector<Mat3> preconditioner;
  std::vector<std::uint32_t> colour;
  std::uint32_t colours = 0;
  std::size_t colouredSprings = ~std::size_t{0};  ///< spring count the colouring was made for
  std::vector<char> released;                     ///< contacts released for the next step (adhesion)
  PcgWorkspace pcg;
};

/// One implicit Euler step of h [s] at time t [s]: velocities and positions of the free particles, pins
/// moved onto their targets, contacts constrained. Collider projection is the caller's (solver.h), so
/// that it comes after self-collision as in every other solver.
ImplicitStats implicitStep(Cloth& cloth, const ClothEnvironment& env, std::span<const Collider> colliders,
                           const ImplicitSettings& settings, Real h, Real t, ImplicitWorkspace& w);

}  // namespace pba::cloth
