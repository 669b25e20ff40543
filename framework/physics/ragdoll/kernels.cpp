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

Real sixVolume(const std::array<Vec3, 4>& x) { return glm::dot(x[1] - x[0], glm::cross(x[2] - x[0], x[3] - x[0])); }

bool keepMinimumVolume(std::array<Vec3, 4>& x, const std::array<Real, 4>& w, Real restSixVolume, Real share) {
  const Real sign = restSixVolume < 0.0 ? -1.0 : 1.0;
  const Real c = sign * sixVolume(x) - share * std::abs(restSixVolume);
  if (!(c < 0.0)) return false;
  const Vec3 e1 = x[1] - x[0], e2 = x[2] - x[0], e3 = x[3] - x[0];
  std::array<Vec3, 4> g{Vec3(0.0), glm::cross(e2, e3), glm::cross(e3, e1), glm::cross(e1, e2)};
  g[0] = -(g[1] + g[2] + g[3]);
  Real norm = 0.0;
  for (int k = 0; k < 4; ++k) norm += w[k] * glm::dot(g[k], g[k]);
  if (!(norm > 0.0)) return false;
  const Real s = -c / norm;
  for (int k = 0; k < 4; ++k) x[k] += s * w[k] * sign * g[k];
  return true;
}

}  // namespace pba::ragdoll
