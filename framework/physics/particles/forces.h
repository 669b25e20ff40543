#pragma once
// Global force fields on particles (Lobb notes, "mass-spring system": gravity, wind, possibly
// time-varying; "Damping": particle–air drag). Each field's derivation sits beside its formula.
#include <span>
#include <vector>

#include "physics/core/result.h"
#include "physics/core/types.h"

namespace pba::particles {

/// Air drag relative to the local wind velocity w: F = −c₁ u − c₂ |u| u, u = v − w.
/// Linear (Stokes, slow or small particles) and quadratic (Newton, fast or large) terms.
struct DragDesc {
  Real linear = 0.0;     ///< c₁ [N·s/m] ≥ 0; typical 0.01–1 for a 0.1 kg particle
  Real quadratic = 0.0;  ///< c₂ [N·s²/m²] ≥ 0; ½ ρ C_d A ≈ 0.6 · 0.47 · π r² for a sphere in air
};

/// A time-varying wind field w(x, t) = base + gust · sin(2π f t − 2π (x·d̂)/λ) d̂, d̂ = base/|base|:
/// gusts travel downwind as a wave. Acts through drag only (no drag ⇒ no wind force).
struct WindDesc {
  Vec3 base{0.0};         ///< [m/s] mean wind; typical 0–10
  Real gust = 0.0;        ///< [m/s] amplitude of the gusts
  Real frequency = 0.5;   ///< [Hz] of the gusts
  Real wavelength = 8.0;  ///< [m] spatial period of the gusts
};
Vec3 windVelocity(const WindDesc& wind, const Vec3& x, Real t);

/// Point attractor, softened inverse square (Plummer): a = S (c − x) / (|c − x|² + ε²)^{3/2}.
/// Potential per unit mass −S/√(|c − x|² + ε²). S < 0 repels.
struct AttractorDesc {
  Vec3 center{0.0};     ///< [m]
  Real strength = 1.0;  ///< S [m³/s²] (like G·M)
  Real softening = 0.2; ///< ε [m] > 0: keeps the force finite at the centre
};

/// Vortex about a line through `center` along `axis`: a swirl acceleration tangential to circles
/// around the axis, a = S (â × r⊥) / (|r⊥|² + r_c²), r⊥ the offset from the axis (Rankine-like core).
struct VortexDesc {
  Vec3 center{0.0};         ///< [m] a point of the axis
  Vec3 axis{0.0, 1.0, 0.0}; ///< unit
  Real strength = 2.0;      ///< S [m²/s²]
  Real coreRadius = 0.5;    ///< r_c [m] > 0
};

struct ForceDesc {
  Vec3 gravity{0.0, -kStandardGravity, 0.0};  ///< [m/s²]
  DragDesc drag;
  WindDesc wind;
  std::vector<AttractorDesc> attractors;
  std::vector<VortexDesc> vortices;
};

/// Adds the fields' forces [N] to f (pinned particles, inverse mass 0, receive none).
void accumulateFieldForces(const ForceDesc& desc, Real t, std::span<const Vec3> x, std::span<const Vec3> v,
                           std::span<const Real> inverseMass, std::span<Vec3> f);
/// Adds (∂f/∂v) dv of the drag to df (the part implicit Euler needs; gravity and the fields of
/// position have no v-dependence, and their small ∂f/∂x is left explicit).
///   linear: −c₁ dv;  quadratic: −c₂ (|u| dv + u (u·dv)/|u|).
void accumulateDragDifferential(const ForceDesc& desc, Real t, std::span<const Vec3> x, std::span<const Vec3> v,
                                std::span<const Real> inverseMass, std::span<const Vec3> dv, std::span<Vec3> df);
/// Adds the drag's diagonal Jacobian blocks ∂f_i/∂v_i to dfdv (implicit Euler's preconditioner).
void accumulateDragJacobianDiagonal(const ForceDesc& desc, Real t, std::span<const Vec3> x, std::span<const Vec3> v,
                                    std::span<const Real> inverseMass, std::span<Mat3> dfdv);
/// Checks every field (finite; drag coefficients ≥ 0, "negative damping" is refused; positive softening, core
/// radius and wavelength; unit vortex axes); the message names the field ("forces.drag.linear: …").
Status validate(const ForceDesc& desc);
/// Potential energy of gravity and attractors [J] (drag, wind and vortex are not conservative).
Real fieldPotentialEnergy(const ForceDesc& desc, std::span<const Vec3> x, std::span<const Real> inverseMass);

}  // namespace pba::particles
