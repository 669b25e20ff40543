#pragma once
// Building blocks shared by the joint types (internal).
#include <algorithm>
#include <cmath>

#include "physics/rigid/joint.h"

namespace pba::rigid::detail {

inline Vec3 anchorA(const Joint& j, const SolverBody& A) { return A.c + A.q * j.localA; }
inline Vec3 anchorB(const Joint& j, const SolverBody& B) { return B.c + B.q * j.localB; }

/// [v]× with [v]× u = v × u.
inline Mat3 skew(const Vec3& v) { return Mat3(0.0, v.z, -v.y, -v.z, 0.0, v.x, v.y, -v.x, 0.0); }

/// [r]× M [r]×, as (skew(r) · M) · skew(r) with glm's products but without their terms that multiply by
/// the zero diagonal of [r]×: each entry is the same sum of the same nonzero products in the same order,
/// so the result has the same bits (an exact zero may differ in sign); 54 flops instead of 90.
inline Mat3 skewSandwich(const Vec3& r, const Mat3& m) {
  Mat3 t, u;  // t = [r]× m: column c of t is r × (column c of m)
  for (int c = 0; c < 3; ++c) {
    t[c][0] = -r.z * m[c][1] + r.y * m[c][2];
    t[c][1] = r.z * m[c][0] + -r.x * m[c][2];
    t[c][2] = -r.y * m[c][0] + r.x * m[c][1];
  }
  for (int i = 0; i < 3; ++i) {  // u = t [r]×, row i at a time
    u[0][i] = t[1][i] * r.z + t[2][i] * -r.y;
    u[1][i] = t[0][i] * -r.z + t[2][i] * r.x;
    u[2][i] = t[0][i] * r.y + t[1][i] * -r.x;
  }
  return u;
}

/// Effective mass of the point rows C = p_B − p_A (3 × 3):
///   K = (m_A⁻¹ + m_B⁻¹) 1 − [r_A]× I_A⁻¹ [r_A]× − [r_B]× I_B⁻¹ [r_B]×,   returns K⁻¹.
inline Mat3 pointMass(const SolverBody& A, const SolverBody& B, const Vec3& rA, const Vec3& rB) {
  const Mat3 k = Mat3(A.invMass + B.invMass) - skewSandwich(rA, A.invI) - skewSandwich(rB, B.invI);
  return std::abs(glm::determinant(k)) > 1e-300 ? glm::inverse(k) : Mat3(0.0);
}

/// Rotation of B relative to its pose at creation, expressed in A's frame:
///   δ = q_A⁻¹ q_B q_rel0⁻¹ (identity while the joint holds its initial relative pose).
inline Quat relativeRotation(const Joint& j, const SolverBody& A, const SolverBody& B) {
  Quat d = glm::conjugate(A.q) * B.q * glm::conjugate(j.relative0);
  if (d.w < 0.0) d = -d;
  return d;
}

/// Twist of δ about A's axis (swing–twist decomposition): 2 atan2(δ_v·a, δ_w) ∈ (−π, π].
inline Real twistAngle(const Joint& j, const SolverBody& A, const SolverBody& B) {
  const Quat d = relativeRotation(j, A, B);
  return 2.0 * std::atan2(glm::dot(Vec3(d.x, d.y, d.z), j.axisA), d.w);
}

/// Small-angle rotation vector of δ in world axes: the error of an angular lock, C = 2 δ_v (δ_w ≥ 0).
inline Vec3 lockError(const Joint& j, const SolverBody& A, const SolverBody& B) {
  const Quat d = relativeRotation(j, A, B);
  return A.q * (2.0 * Vec3(d.x, d.y, d.z));
}

/// One scalar row along world unit direction u acting on the angular velocities only,
/// Ċ = sign·u·(ω_B − ω_A), with a one-sided (λ ≥ 0) accumulated impulse: a joint limit. C is the
/// distance to the limit (> 0: inside, speculative).
inline void solveAngularLimit(SolverBody& A, SolverBody& B, const Vec3& u, Real sign, Real C, Real mass,
                              Real& accumulated, const Softness& soft, Real h, bool useBias) {
  Real bias = 0.0, massScale = 1.0, impulseScale = 0.0;
  if (C > 0.0)
    bias = C / h;
  else if (useBias)
    bias = soft.biasRate * C, massScale = soft.massScale, impulseScale = soft.impulseScale;
  const Real cdot = sign * glm::dot(u, B.w - A.w);
  Real impulse = -mass * massScale * (cdot + bias) - impulseScale * accumulated;
  const Real next = std::max(accumulated + impulse, 0.0);
  impulse = next - accumulated;
  accumulated = next;
  applyAngularImpulse(A, sign * impulse * u, -1.0);
  applyAngularImpulse(B, sign * impulse * u, 1.0);
}

}  // namespace pba::rigid::detail
