#include "physics/rigid/integrate.h"

#include <cmath>

#include "physics/rigid/skew.h"

namespace pba::rigid {

Vec3 gyroscopicImplicitStep(const Quat& q, const Mat3& inertia, const Vec3& omega, Real h) {
  const Vec3 wb = glm::conjugate(q) * omega;
  const Vec3 iw = inertia * wb;
  const Vec3 f = h * glm::cross(wb, iw);
  const Mat3 jacobian = inertia + h * (skewTimes(wb, inertia) - skew(iw));
  const Vec3 wb2 = wb - glm::inverse(jacobian) * f;
  return q * wb2;
}

void midpointFreeRotation(Quat& q, Vec3& omega, const Mat3& inertia, const Mat3& inverseInertia, Real h) {
  const Vec3 lb = inertia * (glm::conjugate(q) * omega);
  const Real scale = glm::length(lb);
  if (scale == 0.0) return;
  // Fixed point for L' = L + h L_mid × I⁻¹ L_mid; a contraction with factor ~h|ω|/2.
  Vec3 l1 = lb;
  for (int k = 0; k < 50; ++k) {
    const Vec3 mid = 0.5 * (lb + l1);
    const Vec3 next = lb + h * glm::cross(mid, inverseInertia * mid);
    const Real change = glm::length(next - l1);
    l1 = next;
    if (change <= 1e-16 * scale) break;
  }
  const Vec3 wMid = inverseInertia * (0.5 * (lb + l1));
  const Quat c = glm::normalize(Quat(1.0, 0.5 * h * wMid.x, 0.5 * h * wMid.y, 0.5 * h * wMid.z));
  const Vec3 lbNext = glm::conjugate(c) * lb;  // Cᵀ L_b exactly, so R' L_b' = R L_b
  q = glm::normalize(q * c);
  omega = q * (inverseInertia * lbNext);
}

}  // namespace pba::rigid
