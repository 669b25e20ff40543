#pragma once
// What the particle ragdoll's corrections share (not exercises: see exercises.h for RAG-1..4).
//
// One projection serves every constraint (Müller et al. 2007, "Position Based Dynamics", §3.3, with
// inverse masses): a constraint C(x) whose gradient with respect to particle k is a_k n (one unit
// direction n for all, a scalar a_k each) is removed to first order by
//   Δx_k = −s w_k a_k n,   s = C / Σ_j w_j a_j².
// Limiting cases: all w = 0 (fixed) → nothing moves; one free particle → it takes all of C/a_k.
// A stick is C = |x_b − x_a| − L with a = (−1, +1) along n = (x_b − x_a)/|·|; a joint point or a contact
// point embedded with barycentric weights c_i has a_i = c_i (one side, plus) and −c_i (the other).
//
// The sticks, limits, contacts and embedded points (joints, limits, the mouse) are the exercises RAG-1..4
// and RAG-6 (exercises.h), which the solver calls.

#include <array>

#include "physics/core/types.h"

namespace pba::ragdoll {

/// A hinge of the particle ragdoll seen from bone A: the axis through `origin`, and the direction of
/// angle 0 (unit, ⟂ axis). Angles about the axis by the right-hand rule.
struct HingeFrame {
  Vec3 origin{0.0};          ///< [m] a point of the axis
  Vec3 axis{1.0, 0.0, 0.0};  ///< unit
  Vec3 zero{0.0, 1.0, 0.0};  ///< unit, ⟂ axis
};

/// A unit vector ⟂ n.
Vec3 anyPerpendicular(const Vec3& n);

/// Six times the signed volume of the tetrahedron x0..x3: (x1 − x0) · ((x2 − x0) × (x3 − x0)) [m³].
Real sixVolume(const std::array<Vec3, 4>& x);

/// Keeps a bone's tetrahedron from turning flat or inside out (not in the Ragdoll paper: its six sticks
/// only hold edge lengths, and the mirror image of a tetrahedron has the same edges, so a thin bone struck
/// hard can flip and stay flipped, its box then drawn and collided in a wrong frame). The unilateral
/// constraint, with D = sixVolume(x) and D₀ its rest value (σ = sign D₀),
///   C(x) = σ D − share·|D₀| ≥ 0,
/// has the gradients ∇₁D = (x2 − x0) × (x3 − x0), ∇₂D = (x3 − x0) × (x1 − x0), ∇₃D = (x1 − x0) × (x2 − x0),
/// ∇₀D = −(∇₁D + ∇₂D + ∇₃D), and when violated is projected as Müller et al. 2007 §3.3 do (above, but with
/// one gradient per particle): Δx_k = −C w_k σ∇_kD / Σ_j w_j |∇_jD|². Limiting cases: C ≥ 0 → nothing moves
/// (a bone within its normal shape is untouched); all w = 0 → nothing moves. Equal weights move the
/// centroid by Σ∇_k = 0: momentum is kept. Returns whether it moved anything.
bool keepMinimumVolume(std::array<Vec3, 4>& x, const std::array<Real, 4>& w, Real restSixVolume, Real share);

}  // namespace pba::ragdoll
