#pragma once
// Time integration of one rigid body: semi-implicit (symplectic) Euler, velocities first, then poses
// with the new velocities (Catto, "Numerical Methods", GDC 2015; Baraff & Witkin 2001).
#include "physics/rigid/settings.h"
#include "physics/rigid/solver_body.h"

namespace pba::rigid {

// The orientation's own update over a step is the exercise RIGID-2 (exercises.h: integrateOrientation).

/// One backward-Euler Newton step of Euler's equation in the body frame (Catto GDC 2015):
///   f(ω₂) = I(ω₂ − ω₁) + h ω₂ × Iω₂ = 0,  J = I + h([ω₁]× I − [Iω₁]×),  ω₂ = ω₁ − J⁻¹ f(ω₁).
/// Returns the new world angular velocity; `inertiaBody` is I in body axes.
Vec3 gyroscopicImplicitStep(const Quat& q, const Mat3& inertiaBody, const Vec3& omega, Real h);

/// The free rotation over h by the implicit midpoint rule on L̇_b = L_b × I⁻¹L_b (body frame), with the
/// orientation moved by the Cayley rotation of h ω_mid: L_b' = Cᵀ L_b and q' = q c, so the world
/// angular momentum R_b L_b is unchanged and the energy ½ L_b·I⁻¹L_b is kept up to the fixed-point
/// tolerance. Updates q and ω (world) in place.
void midpointFreeRotation(Quat& q, Vec3& omega, const Mat3& inertiaBody, const Mat3& inverseInertiaBody, Real h);

}  // namespace pba::rigid
