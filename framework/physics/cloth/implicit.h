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
#include "physics/cloth/implicit_fast_path.h"
#include "physics/cloth/pcg.h"

namespace pba::cloth {

// ***** CLOTH-5: the matrix–vector product of the implicit system (Baraff & Witkin 1998, eq. 16) *****
// Compute out = A y for the backward Euler system A = M − h ∂f/∂v − h² ∂f/∂x of the cloth's springs and
// Rayleigh mass damping (force −c m v), with step h [s], without ever building A: the conjugate gradient
// only needs products. y and out hold one Vec3 per particle.
// (1) The mass and mass-damping terms act on each particle alone: work out what the −h ∂f/∂v of the
//     damping force adds to the mass there.
// (2) Each spring couples its two ends through its stiffness and damping blocks (SpringJacobian in
//     forces.h gives them in factored form, to be applied to a vector, never multiplied out). From the
//     signs of ∂f_i/∂x_j and ∂f_i/∂x_i, work out what the spring adds to particle i and to particle j,
//     and which power of h multiplies each block.
// (3) Pins and contacts are not your concern: the solver filters the result.
// Check: A is symmetric (yᵀ A z = zᵀ A y for random y, z); with h = 0 the product is M y; a uniform y
// (every particle the same vector) sees no spring term; EqualsTheSystemMatrixBuiltFromCentralDifferences.
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
  /// Also constrain particles that would reach a collider within the step (implicit.cpp, buildFilter); our
  /// addition to B&W, whose contacts start at the surface. false: only touching particles.
  bool speculativeContacts = true;
  /// A contact whose friction stopped it sticks at the next step, fixed to the collider inside the solve,
  /// until its tangential impulse leaves the friction cone (implicit.cpp, contactFriction). false: friction
  /// only after the solve, so the springs never see a particle hold (stiff cloth then jitters on colliders).
  bool staticFriction = true;
  /// The conjugate gradient's first guess of v₁: v₀ + h a, with a the velocity change per second of the
  /// last step (an extrapolation of the motion; ours); false: v₀. Only the start of the iteration changes,
  /// not the system nor the stopping test (relative to the right-hand side), but the iterate at which the
  /// test stops differs, and with it the strain (docs/performance-cloth.md, "Implicit cloth, issue 36").
  bool extrapolatedStart = false;
  /// Step control (ClothSolver, not implicitStep): a step in which some stretch or shear spring's strain
  /// |l − L|/L grows by more than this is discarded and taken again as two steps of half the size, down to
  /// 2^-maxHalvings of the step. Baraff & Witkin's simulator controls its step size by the cloth's stretch
  /// in the same way; the measure and the threshold are ours. One Newton step linearises the springs about
  /// the start of the step, which holds only for small changes of length: stiff cloth struck by a collider
  /// can overshoot far in one step and gain energy without it. A
  /// spring that relaxes does not count (self-collision stretches springs that the next step restores),
  /// nor do bend springs, whose length changes by design when cloth folds onto itself.
  /// 0 turns it off (every step as asked, the bare method).
  Real maxStrainGrowth = 0.1;
  int maxHalvings = 6;
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
  std::vector<Real> correction;                   ///< [m/s] position alteration / h of each contact (B&W §6)
  std::vector<int> contact;                       ///< collider each particle touches this step, −1 none
  std::vector<char> sticking;                     ///< contacts friction stopped, fixed at the next step
  std::vector<Vec3> acceleration;                 ///< [m/s²] (v₁ − v₀)/h of the last step (first guess)
  PcgWorkspace pcg;
  ImplicitSystem system;  ///< the step's A, multiplied through CLOTH-5's fast path
};

/// One implicit Euler step of h [s] at time t [s]: velocities and positions of the free particles, pins
/// moved onto their targets, contacts constrained. Collider projection is the caller's (solver.h), so
/// that it comes after self-collision as in every other solver.
ImplicitStats implicitStep(Cloth& cloth, const ClothEnvironment& env, std::span<const Collider> colliders,
                           const ImplicitSettings& settings, Real h, Real t, ImplicitWorkspace& w);

}  // namespace pba::cloth
