#include "physics/particles/fountain_contacts.h"

#include <cmath>

namespace pba::particles {

FountainContactCounts resolveFountainContactsScalar(std::span<Vec3> x, std::span<Vec3> v,
                                                    std::span<const std::uint32_t> flagged,
                                                    const FountainObstacles& o) {
  FountainContactCounts counts;
  auto count = [&](const ContactResult& r) {
    counts.contacts += r.kind != ContactKind::None;
    counts.heldBySafetyNet += r.heldBySafetyNet;
  };
  for (const std::uint32_t k : flagged) {
    Vec3& xk = x[k];
    Vec3& vk = v[k];
    for (const PlaneReach& plane : o.planes) {
      count(resolveContact(xk, vk, plane.normal, glm::dot(plane.normal, xk) - plane.offset, o.material, o.step));
    }
    for (const SphereReach& sphere : o.spheres) {
      const Vec3 r = xk - sphere.center;
      const Real l2 = glm::dot(r, r);
      if (l2 >= sphere.reach2 || l2 <= 0.0) continue;  // far: no square root
      const Real l = std::sqrt(l2);
      count(resolveContact(xk, vk, r / l, l - sphere.surface, o.material, o.step));
    }
  }
  return counts;
}

}  // namespace pba::particles
