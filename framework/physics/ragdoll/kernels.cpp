#include "physics/ragdoll/kernels.h"

#include <cmath>

namespace pba::ragdoll {

Vec3 anyPerpendicular(const Vec3& n) {
  // The coordinate axis least aligned with n, minus its part along n.
  const Vec3 a = glm::abs(n);
  const Vec3 e = a.x <= a.y && a.x <= a.z ? Vec3(1.0, 0.0, 0.0)
                 : a.y <= a.z             ? Vec3(0.0, 1.0, 0.0)
                                          : Vec3(0.0, 0.0, 1.0);
  return glm::normalize(e - glm::dot(e, n) * n);
}

}  // namespace pba::ragdoll
