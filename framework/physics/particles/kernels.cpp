#include "physics/particles/kernels.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

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

namespace {
// The obstacles as the fountain kernel tests them, precomputed once per step.
struct PlaneTest {
  Vec3 normal;
  Real offset;  // n·p + particle radius: contact when n·x − offset < slop
};
struct SphereTest {
  Vec3 center;
  Real surface;  // sphere radius + particle radius
  Real reach2;   // (surface + slop)²: nothing to do when |x − c|² ≥ reach2
};
constexpr std::size_t kMaxFusedObstacles = 16;  // per kind; more are ignored (the fountain has 1 + 3)
constexpr std::size_t kBlock = 256;             // particles per block: a block's x and v stay in L1
}  // namespace

FountainStepStats stepFountain(Particles& p, const FusedFountainDesc& d, Real h) {
  const Real keep = 1.0 - h * d.dragRate;
  const Vec3 dv = h * (d.gravity + d.dragRate * d.wind);
  const Vec3 g = d.gravity;
  const Real swirl = h * d.vortexStrength, core2 = d.vortexCore * d.vortexCore;
  const Real cx = d.vortexCenter.x, cz = d.vortexCenter.z;
  const ContactMaterial material = d.material;
  PlaneTest planes[kMaxFusedObstacles];
  SphereTest spheres[kMaxFusedObstacles];
  const std::size_t nPlanes = std::min(d.planes.size(), kMaxFusedObstacles);
  const std::size_t nSpheres = std::min(d.spheres.size(), kMaxFusedObstacles);
  for (std::size_t k = 0; k < nPlanes; ++k) {
    planes[k] = {d.planes[k].normal, glm::dot(d.planes[k].normal, d.planes[k].point) + d.radius};
  }
  for (std::size_t k = 0; k < nSpheres; ++k) {
    const Real surface = d.spheres[k].radius + d.radius, reach = surface + kContactSlop;
    spheres[k] = {d.spheres[k].center, surface, reach * reach};
  }
  // One obstacle pass for one particle, in the order of collideWithObstacles (planes, then spheres).
  auto resolveContacts = [&](Vec3& x, Vec3& v) {
    std::size_t n = 0;
    for (std::size_t k = 0; k < nPlanes; ++k) {
      n += contact(x, v, planes[k].normal, glm::dot(planes[k].normal, x) - planes[k].offset, material);
    }
    for (std::size_t k = 0; k < nSpheres; ++k) {
      const Vec3 r = x - spheres[k].center;
      const Real l2 = glm::dot(r, r);
      if (l2 >= spheres[k].reach2 || l2 <= 0.0) continue;  // far: no square root
      const Real l = std::sqrt(l2);
      n += contact(x, v, r / l, l - spheres[k].surface, material);
    }
    return n;
  };

  const std::size_t count = p.size();
  Vec3* __restrict xs = p.position.data();
  Vec3* __restrict vs = p.velocity.data();
  Real* __restrict ages = p.age.data();
  Real* __restrict lifetimes = p.lifetime.data();
  Real* __restrict inverseMasses = p.inverseMass.data();
  Color* __restrict colors = p.color.data();
  std::size_t kept = 0, contacts = 0;
  Real speed2 = 0.0, height = 0.0;
  std::uint32_t touching[kBlock];  // survivors of the block that reach an obstacle (offsets from its start)
  for (std::size_t begin = 0; begin < count; begin += kBlock) {
    const std::size_t end = std::min(count, begin + kBlock), first = kept;
    std::size_t nTouching = 0;
    // Pass 1, free of data-dependent branches: ageing and removal, motion, and a flag for the particles
    // within reach of an obstacle. Exact: a particle that reaches none is left alone by every contact
    // test, so only the flagged ones need pass 2.
    for (std::size_t i = begin; i < end; ++i) {
      const Real age = ages[i] + h;
      if (age >= lifetimes[i]) [[unlikely]] continue;  // expired: not kept
      Vec3 xi = xs[i];
      const Real rx = xi.x - cx, rz = xi.z - cz;
      const Real s = swirl / (rx * rx + rz * rz + core2);  // ŷ × (rx, 0, rz) = (rz, 0, −rx)
      const Vec3 vi = keep * vs[i] + dv + Vec3(s * rz, 0.0, -s * rx);
      xi += h * vi;
      bool touches = false;
      for (std::size_t k = 0; k < nPlanes; ++k) {
        touches |= glm::dot(planes[k].normal, xi) - planes[k].offset < kContactSlop;
      }
      for (std::size_t k = 0; k < nSpheres; ++k) {
        const Vec3 r = xi - spheres[k].center;
        touches |= glm::dot(r, r) < spheres[k].reach2;
      }
      touching[nTouching] = static_cast<std::uint32_t>(kept - first);
      nTouching += touches;
      // Stable compaction: after the first removal every survivor slides down by the removals so far.
      xs[kept] = xi;
      vs[kept] = vi;
      ages[kept] = age;
      if (kept != i) {
        lifetimes[kept] = lifetimes[i];
        inverseMasses[kept] = inverseMasses[i];
        colors[kept] = colors[i];
      }
      ++kept;
    }
    // Pass 2: the contact model for the flagged particles, while the block is in cache.
    for (std::size_t n = 0; n < nTouching; ++n) {
      contacts += resolveContacts(xs[first + touching[n]], vs[first + touching[n]]);
    }
    // Pass 3: the energy sums. A NaN or ±∞ anywhere in x or v makes them non-finite (0·∞ is NaN
    // too), so they are also the guard's finiteness test.
    for (std::size_t i = first; i < kept; ++i) {
      speed2 += glm::dot(vs[i], vs[i]);
      height += glm::dot(g, xs[i]);
    }
  }
  p.truncate(kept);
  FountainStepStats stats;
  stats.contacts = contacts;
  stats.expired = count - kept;
  stats.nonFinite = !(std::isfinite(speed2) && std::isfinite(height));
  stats.kineticPerMass = 0.5 * speed2;
  stats.potentialPerMass = -height;
  return stats;
}

}  // namespace pba::particles
