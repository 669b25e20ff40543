#include "physics/ragdoll/kernels.h"

#include <cmath>

namespace pba::ragdoll {

bool projectAlongGradient(std::vector<Vec3>& x, const std::vector<Real>& w, std::span<const Term> terms, const Vec3& n,
                          Real c) {
  Real denominator = 0.0;
  for (const Term& t : terms) denominator += w[t.particle] * t.coefficient * t.coefficient;
  if (!(denominator > 1e-300)) return false;
  const Real s = c / denominator;
  for (const Term& t : terms) x[t.particle] -= (s * w[t.particle] * t.coefficient) * n;
  return true;
}

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
  const Vec3 q = p - f.origin;
  const Vec3 along = glm::dot(q, f.axis) * f.axis;
  const Real radius = glm::length(q - along);
  return f.origin + along + radius * (std::cos(target) * f.zero + std::sin(target) * glm::cross(f.axis, f.zero));
}

Real angleFromAxis(const Vec3& apex, const Vec3& axis, const Vec3& p) {
  const Vec3 d = p - apex;
  return std::atan2(glm::length(glm::cross(axis, d)), glm::dot(axis, d));
}

Vec3 anyPerpendicular(const Vec3& n) {
  return glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0)));
}

Vec3 atAngleFromAxis(const Vec3& apex, const Vec3& axis, const Vec3& p, Real target) {
  const Vec3 d = p - apex;
  const Real length = glm::length(d);
  const Vec3 radial = d - glm::dot(d, axis) * axis;
  const Real r = glm::length(radial);
  const Vec3 t = r > 1e-12 * length ? radial / r : anyPerpendicular(axis);
  return apex + length * (std::cos(target) * axis + std::sin(target) * t);
}

}  // namespace pba::ragdoll
