#pragma once
// Building blocks shared by the joint types (internal).
#include <algorithm>
#include <cmath>

#include "physics/rigid/joint.h"
#include "physics/rigid/skew.h"

namespace pba::rigid::detail {

inline Vec3 anchorA(const Joint& j, const SolverBody& A) { return A.c + A.q * j.localA; }
inline Vec3 anchorB(const Joint& j, const SolverBody& B) { return B.c + B.q * j.localB; }

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
  // An inactive limit (its impulse stays 0, as a speculative one mostly does) would add zeros to both
  // angular velocities: the same bits (only an exact zero may differ in sign), so it is left out.
  if (impulse == 0.0) return;
  applyAngularImpulse(A, sign * impulse * u, -1.0);
  applyAngularImpulse(B, sign * impulse * u, 1.0);
}

}  // namespace pba::rigid::detail
