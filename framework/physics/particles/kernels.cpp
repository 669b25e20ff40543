#include "physics/particles/kernels.h"

#include <cmath>

namespace pba::particles {

void stepGravityDragPlane(std::span<Vec3> x, std::span<Vec3> v, const FusedStepDesc& d, Real h) {
  const Vec3 n = d.ground.normal;
  const Real offset = glm::dot(n, d.ground.point) + d.radius;  // contact when n·x < offset
  const Vec3 dv = h * d.gravity;
  const Real keep = 1.0 - h * d.dragRate;
  const std::size_t count = x.size();
  Vec3* __restrict xs = x.data();
  Vec3* __restrict vs = v.data();
  for (std::size_t i = 0; i < count; ++i) {
    Vec3 vi = keep * vs[i] + dv;
    Vec3 xi = xs[i] + h * vi;
    const Real phi = glm::dot(n, xi) - offset;
    if (phi < kContactSlop) [[unlikely]] {
      if (phi < 0.0) xi -= phi * n;
      if (glm::dot(vi, n) < 0.0) {
        vi = contactVelocity(vi, n, d.material);
        const Real vn = glm::dot(vi, n);
        if (vn < 0.0) vi -= vn * n;
      }
    }
    xs[i] = xi;
    vs[i] = vi;
  }
}

namespace {
// collision.cpp's resolve() for one particle (projection, then PART-5's response and the safety net).
inline bool contact(Vec3& x, Vec3& v, const Vec3& n, Real phi, const ContactMaterial& m) {
  if (phi >= kContactSlop) return false;
  if (phi < 0.0) x -= phi * n;
  if (glm::dot(v, n) >= 0.0) return false;
  v = contactVelocity(v, n, m);
  const Real vn = glm::dot(v, n);
  if (vn < 0.0) v -= vn * n;
  return true;
}
}  // namespace

std::size_t stepFountain(std::span<Vec3> x, std::span<Vec3> v, const FusedFountainDesc& d, Real h) {
  const Real keep = 1.0 - h * d.dragRate;
  const Vec3 dv = h * (d.gravity + d.dragRate * d.wind);
  const Real swirl = h * d.vortexStrength, core2 = d.vortexCore * d.vortexCore;
  const Real cx = d.vortexCenter.x, cz = d.vortexCenter.z;
  const Real r2 = d.radius;
  std::size_t contacts = 0;
  const std::size_t count = x.size();
  Vec3* __restrict xs = x.data();
  Vec3* __restrict vs = v.data();
  for (std::size_t i = 0; i < count; ++i) {
    Vec3 xi = xs[i];
    const Real rx = xi.x - cx, rz = xi.z - cz;
    const Real s = swirl / (rx * rx + rz * rz + core2);  // ŷ × (rx, 0, rz) = (rz, 0, −rx)
    Vec3 vi = keep * vs[i] + dv + Vec3(s * rz, 0.0, -s * rx);
    xi += h * vi;
    for (const PlaneObstacle& p : d.planes) {
      contacts += contact(xi, vi, p.normal, glm::dot(p.normal, xi - p.point) - r2, d.material);
    }
    for (const SphereObstacle& sp : d.spheres) {
      const Vec3 r = xi - sp.center;
      const Real l2 = glm::dot(r, r), reach = sp.radius + r2 + kContactSlop;
      if (l2 >= reach * reach || l2 <= 0.0) [[likely]] continue;  // far: no square root
      const Real l = std::sqrt(l2);
      contacts += contact(xi, vi, r / l, l - sp.radius - r2, d.material);
    }
    xs[i] = xi;
    vs[i] = vi;
  }
  return contacts;
}

}  // namespace pba::particles
