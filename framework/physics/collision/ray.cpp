#include "physics/collision/ray.h"

#include <cmath>

namespace pba {

std::optional<Real> intersectRaySphere(const Ray& ray, const Vec3& center, Real radius) {
  const Vec3 oc = ray.origin - center;
  const Real b = glm::dot(ray.direction, oc);
  const Real c0 = glm::dot(oc, oc) - radius * radius;
  const Real discriminant = b * b - c0;
  if (discriminant < 0.0) return std::nullopt;
  const Real root = std::sqrt(discriminant);
  const Real tNear = -b - root;
  if (tNear >= 0.0) return tNear;
  const Real tFar = -b + root;  // origin inside the sphere
  if (tFar >= 0.0) return tFar;
  return std::nullopt;
}

std::optional<Real> intersectRayPlane(const Ray& ray, const Vec3& point, const Vec3& normal) {
  const Real denominator = glm::dot(normal, ray.direction);
  if (std::abs(denominator) < 1e-12) return std::nullopt;
  const Real t = glm::dot(normal, point - ray.origin) / denominator;
  if (t < 0.0) return std::nullopt;
  return t;
}

}  // namespace pba
