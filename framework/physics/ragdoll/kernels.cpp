#include "physics/ragdoll/kernels.h"

#include <cmath>

namespace pba::ragdoll {

Real hingeAngle(const HingeFrame& f, const Vec3& p) {
  const Vec3 q = p - f.origin;
  return std::atan2(glm::dot(q, glm::cross(f.axis, f.zero)), glm::dot(q, f.zero));
}

Real unwrapAround(Real a, Real lower, Real upper) {
  const Real mid = 0.5 * (lower + upper);
  Real d = std::remainder(a - mid, 2.0 * kPi);  // in [−π, π]
  return mid + d;
}

Vec3 atHingeAngle(const HingeFrame& f, const Vec3& p, Real target) {
  // Turn p about the axis by the missing angle (a rotation keeps its height and distance from the axis).
  return f.origin + glm::angleAxis(target - hingeAngle(f, p), f.axis) * (p - f.origin);
}

Real angleFromAxis(const Vec3& apex, const Vec3& axis, const Vec3& p) {
  const Vec3 d = p - apex;
  return std::atan2(glm::length(glm::cross(axis, d)), glm::dot(axis, d));
}

Vec3 anyPerpendicular(const Vec3& n) {
  // The coordinate axis least aligned with n, minus its part along n.
  const Vec3 a = glm::abs(n);
  const Vec3 e = a.x <= a.y && a.x <= a.z ? Vec3(1.0, 0.0, 0.0)
                 : a.y <= a.z             ? Vec3(0.0, 1.0, 0.0)
                                          : Vec3(0.0, 0.0, 1.0);
  return glm::normalize(e - glm::dot(e, n) * n);
}

Vec3 atAngleFromAxis(const Vec3& apex, const Vec3& axis, const Vec3& p, Real target) {
  // Turn p − apex about axis × (p − apex), which changes its angle from the axis and nothing else.
  const Vec3 d = p - apex;
  const Vec3 normal = glm::cross(axis, d);
  const Real size = glm::length(normal);
  const Vec3 turn = size > 1e-12 * glm::length(d) ? normal / size : anyPerpendicular(axis);
  return apex + glm::angleAxis(target - angleFromAxis(apex, axis, p), turn) * d;
}

}  // namespace pba::ragdoll
