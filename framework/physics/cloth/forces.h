#pragma once
// Forces on a cloth: the springs of the mass-spring model with their analytic Jacobian, gravity, air drag,
// and wind with per-triangle aerodynamic drag and lift.
//
// Springs (Provot 1995; damping along the spring, Baraff & Witkin 1998 §4.5). For a spring i–j with
// r = x_j − x_i, l = |r|, n = r/l, rest length L, stiffness k, damping k_d:
//   f_i = [k (l − L) + k_d n·(v_j − v_i)] n,   f_j = −f_i.
// Jacobian (B&W §5.2 structure):
//   ∂f_i/∂x_j = K_s = k [ n nᵀ + (1 − L/l)(I − n nᵀ) ],   ∂f_i/∂x_i = −K_s,
//   ∂f_i/∂v_j = D_s = k_d n nᵀ,                          ∂f_i/∂v_i = −D_s,
// dropping the damping term's dependence on x (B&W drop it too; it vanishes at rest). The lateral factor
// (1 − L/l) is negative under compression and makes K_s indefinite, so the implicit system could lose
// positive definiteness; it is clamped at 0 (Choi & Ko 2002 §4: compressed springs keep only their axial
// stiffness). Named departure: `clampCompressedLateral` in SpringJacobianSettings, on by default.
#include <array>
#include <span>
#include <vector>

#include "physics/cloth/cloth.h"
#include "physics/particles/forces.h"

namespace pba::cloth {

/// What acts on the cloth from outside. Wind acts through the aerodynamic model only.
struct ClothEnvironment {
  Vec3 gravity{0.0, -kStandardGravity, 0.0};  ///< [m/s²]
  Real massDamping = 0.0;      ///< c [1/s]: force −c m v on every particle (Rayleigh's mass term); typical 0–1
  bool aerodynamics = false;   ///< per-triangle drag and lift (CLOTH-3) relative to the wind
  particles::WindDesc wind;    ///< [m/s] wind field with travelling gusts (particles/forces.h)
  Real airDensity = 1.2;       ///< ρ [kg/m³] air at 20 °C
  Real dragCoefficient = 1.0;  ///< C_D of a flat plate facing the flow ≈ 1.1–1.3
  Real liftCoefficient = 0.5;  ///< C_L of the lift model below
};

/// Stiffness [N/m] of the springs of each LinkKind, indexed by the kind.
std::array<Real, kLinkKinds> springStiffness(const ClothMaterial& m);
/// XPBD compliance [m/N] of the distance constraints of each LinkKind (Bend: the distance bending links).
std::array<Real, kLinkKinds> constraintCompliance(const ClothMaterial& m);

/// Adds the springs' forces [N] to f, each through PART-4 (springs::dampedSpringForce). With `withDamping`
/// false only the elastic part (the spring damping passed as 0).
void accumulateSpringForces(std::span<const Link> springs, const ClothMaterial& m, std::span<const Vec3> x,
                            std::span<const Vec3> v, bool withDamping, std::span<Vec3> f);
/// Σ ½ k (l − L)² over the springs [J].
Real springEnergy(std::span<const Link> springs, const ClothMaterial& m, std::span<const Vec3> x);

/// The Jacobian of one spring, in the factored form the implicit solver multiplies with:
///   K_s y = lateral y + (stiffness − lateral) n (n·y),   D_s y = damping n (n·y).
struct SpringJacobian {
  std::uint32_t i = 0, j = 0;
  Vec3 direction{0.0};   ///< n (0 for a spring of zero length: then the blocks are 0)
  Real stiffness = 0.0;  ///< k [N/m]
  Real lateral = 0.0;    ///< k (1 − L/l), clamped at 0 under compression [N/m]
  Real damping = 0.0;    ///< k_d [N·s/m]
};
struct SpringJacobianSettings {
  bool clampCompressedLateral = true;  ///< Choi & Ko 2002; false = the exact Jacobian (may be indefinite)
};
/// One SpringJacobian per spring at positions x (out is resized).
void springJacobians(std::span<const Link> springs, const ClothMaterial& m, std::span<const Vec3> x,
                     const SpringJacobianSettings& settings, std::vector<SpringJacobian>& out);
/// K_s = ∂f_i/∂x_j and D_s = ∂f_i/∂v_j as matrices (tests assemble dense systems from them).
Mat3 stiffnessBlock(const SpringJacobian& s);
Mat3 dampingBlock(const SpringJacobian& s);

// ***** CLOTH-3: the aerodynamic force on one triangle (drag and lift of a flat plate) *****
// Inputs: the triangle's vertices x0, x1, x2 [m], their velocities v0, v1, v2 [m/s], the wind velocity w
// [m/s] at the triangle, the air density ρ [kg/m³], the drag and lift coefficients C_D, C_L. Output: the
// force on the whole triangle [N] (the caller gives a third to each vertex).
// (1) The flow the triangle sees: its own mean velocity relative to the wind. No flow, no force.
// (2) The triangle's area and unit normal from its edges; cloth is two-sided, so turn the normal to face
//     the flow.
// (3) The air pushes with the dynamic pressure of the flow on the area the triangle presents to it (its
//     projection across the flow). Drag acts against the flow; lift is perpendicular to the flow, in
//     the plane of the flow and the normal, and vanishes when the plate faces the flow or lies along it.
//     Work out both with their coefficients.
// Check: face-on flow gives full drag and no lift; edge-on flow gives nothing; at 45° drag and lift
// follow the projected area; flipping the triangle's winding changes nothing; adding the same velocity
// to the triangle and the wind changes nothing.
// *****
Vec3 triangleAerodynamicForce(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& v0, const Vec3& v1,
                              const Vec3& v2, const Vec3& wind, Real airDensity, Real dragCoefficient,
                              Real liftCoefficient);

/// Adds gravity, mass damping and (when on) the aerodynamic forces at time t [s] to f, for free particles.
void accumulateExternalForces(const Cloth& cloth, const ClothEnvironment& env, Real t, std::span<const Vec3> x,
                              std::span<const Vec3> v, std::span<Vec3> f);

/// Kinetic energy Σ ½ m |v|² [J] of the free particles.
Real kineticEnergy(const Cloth& cloth);
/// Gravitational potential −Σ m g·x [J] of the free particles (0 at the origin).
Real gravityEnergy(const Cloth& cloth, const Vec3& gravity);

}  // namespace pba::cloth
