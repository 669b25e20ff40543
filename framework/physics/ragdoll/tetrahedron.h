#pragma once
// A bone of the particle ragdoll: a tetrahedron of four equal point masses whose mass, centre of mass
// and inertia tensor equal those of the box it stands for (the "proper particulating" the Ragdoll paper
// lists as future work, §6).
//
// Derivation. Point masses m_i at r_i (about the centre) have the inertia I = tr(S) 1 − S with the
// second moment S = Σ m_i r_i r_iᵀ; a solid box of mass M and half extents h has S_box = M/3 diag(h²)
// (M/12 times the squared full sides). The regular tetrahedron v ∈ {(1,1,1), (1,−1,−1), (−1,1,−1),
// (−1,−1,1)} has Σ v = 0 and Σ v vᵀ = 4·1. So masses M/4 at r_i = diag(h)/√3 · v_i give Σ m_i r_i = 0
// and S = M/4 · 4 · diag(h²)/3 = S_box: the same mass, centre and inertia for every box.
//
// A point of the bone is carried by the tetrahedron as an affine combination p = Σ c_i x_i with
// Σ c_i = 1 (its barycentric coordinates, constant while the tetrahedron stays rigid; they may be
// negative: a box corner lies outside the tetrahedron). These c_i are the paper's per-particle weights
// of §3.3 in exact form: moving the particles by c_i λ Δ with λ = 1/Σ c_j² moves p by exactly Δ.
#include <array>

#include "physics/collision/transform.h"
#include "physics/core/types.h"

namespace pba::ragdoll {

using Weights = std::array<Real, 4>;

/// The four particle positions in the box's frame [m] (see above).
std::array<Vec3, 4> tetrahedronOffsets(const Vec3& halfExtents);

/// The barycentric coordinates of `point` in the tetrahedron (x0..x3), Σ = 1. The tetrahedron must not
/// be flat.
Weights barycentric(const std::array<Vec3, 4>& x, const Vec3& point);
/// Σ c_i x_i (inline: every joint point of every relaxation pass reads it).
inline Vec3 embedded(const std::array<Vec3, 4>& x, const Weights& c) {
  return c[0] * x[0] + c[1] * x[1] + c[2] * x[2] + c[3] * x[3];
}
/// The mean of the four particles: the centre of the box fitted to them (fitFrame).
inline Vec3 centroid(const std::array<Vec3, 4>& x) { return 0.25 * (x[0] + x[1] + x[2] + x[3]); }

/// The rigid frame that best fits the tetrahedron (exercise RAG-5): centre = mean of the particles,
/// rotation = the polar factor of the deformation of the rest edges into the current ones. The box is
/// drawn and collided in this frame (paper §3.1, "Display").
collision::Transform fitFrame(const std::array<Vec3, 4>& x, const Mat3& restEdgesInverse);
/// [r_1 − r_0, r_2 − r_0, r_3 − r_0]⁻¹ of the rest offsets.
Mat3 restEdgesInverse(const std::array<Vec3, 4>& rest);

/// Inertia tensor of point masses about their centre of mass [kg·m²] (tests compare it with the box).
Mat3 pointMassInertia(const std::array<Vec3, 4>& x, const Weights& masses);

}  // namespace pba::ragdoll
