#include "physics/particles/kernels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "physics/core/lanes.h"
#include "physics/particles/fountain_contacts.h"

namespace pba::particles {

void stepGravityDragPlane(std::span<Vec3> x, std::span<Vec3> v, const FusedStepDesc& d, Real h) {
  const Vec3 n = d.ground.normal;
  const Real offset = glm::dot(n, d.ground.point) + d.radius;  // contact when n·x < offset
  const Vec3 halfKick = 0.5 * h * d.gravity;
  const Real keep = 1.0 - 0.5 * h * d.dragRate;  // each half kick (kernels.h)
  const ContactStep contactStep{d.gravity, h};
  const std::size_t count = x.size();
  Vec3* __restrict xs = x.data();
  Vec3* __restrict vs = v.data();
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 half = keep * vs[i] + halfKick;
    Vec3 xi = xs[i] + h * half;
    Vec3 vi = keep * half + halfKick;
    const Real phi = glm::dot(n, xi) - offset;
    if (phi < kContactSlop) [[unlikely]] {
      resolveContact(xi, vi, n, phi, d.material, contactStep);
    }
    xs[i] = xi;
    vs[i] = vi;
  }
}

namespace {
constexpr std::size_t kBlock = 256;  // particles per block: a block's x and v stay in L1

/// A table of n precomputed obstacle tests: on the stack for the usual few, on the heap beyond that (no
/// cap on the number of obstacles, and no allocation for scenes like the fountain's 1 + 3).
template <typename T>
class ObstacleTable {
 public:
  explicit ObstacleTable(std::size_t n) : items_(n <= kInline ? std::span<T>(local_.data(), n) : heapOf(n)) {}
  std::span<T> items() const { return items_; }

 private:
  static constexpr std::size_t kInline = 16;
  std::span<T> heapOf(std::size_t n) {
    heap_.resize(n);
    return heap_;
  }
  std::array<T, kInline> local_{};
  std::vector<T> heap_;
  std::span<T> items_;
};

// The reach tests of the motion pass with every constant already in both lanes, so that the pass loads
// them as they are instead of broadcasting each one for every pair of particles.
struct PlaneLanes {
  Pair nx, ny, nz, offset;
};
struct SphereLanes {
  Pair cx, cy, cz, reach2;
};

// The swirl's velocity change over half a step, (h/2) S (ŷ × r⊥)/(|r⊥|² + r_c²) with ŷ × (rx, 0, rz) =
// (rz, 0, −rx); halfSwirl = (h/2) S. For two particles at once (core/lanes.h): one divpd for both.
struct SwirlKick {
  Pair x, z;  // the y part is zero
};
inline SwirlKick swirlKick(const PairVec3& x, Real cx, Real cz, Real halfSwirl, Real core2) {
  const Pair rx = x.x - cx, rz = x.z - cz;
  const Pair s = halfSwirl / (rx * rx + rz * rz + core2);
  return {s * rz, -s * rx};
}
/// keep·v + halfKick + swirl, the half kick of kernels.h, component by component as glm computes it.
inline PairVec3 halfKickPair(const PairVec3& v, Real keep, const Vec3& halfKick, const SwirlKick& swirl) {
  return {keep * v.x + halfKick.x + swirl.x, keep * v.y + halfKick.y + 0.0, keep * v.z + halfKick.z + swirl.z};
}
}  // namespace

FountainStepStats stepFountain(Particles& p, const FusedFountainDesc& d, Real h) {
  const Real keep = 1.0 - 0.5 * h * d.dragRate;                       // each half kick (kernels.h)
  const Vec3 halfKick = 0.5 * h * (d.gravity + d.dragRate * d.wind);  // (h/2) G
  const Vec3 g = d.gravity;
  const Real halfSwirl = 0.5 * h * d.vortexStrength, core2 = d.vortexCore * d.vortexCore;
  const Real cx = d.vortexCenter.x, cz = d.vortexCenter.z;
  ObstacleTable<PlaneReach> planeTable(d.planes.size());
  ObstacleTable<SphereReach> sphereTable(d.spheres.size());
  const std::span<PlaneReach> planes = planeTable.items();
  const std::span<SphereReach> spheres = sphereTable.items();
  for (std::size_t k = 0; k < planes.size(); ++k) {
    planes[k] = {d.planes[k].normal, glm::dot(d.planes[k].normal, d.planes[k].point) + d.radius};
  }
  for (std::size_t k = 0; k < spheres.size(); ++k) {
    const Real surface = d.spheres[k].radius + d.radius, reach = surface + kContactSlop;
    spheres[k] = {d.spheres[k].center, surface, reach * reach};
  }
  const FountainObstacles obstacles{planes, spheres, d.material, ContactStep{d.gravity, h}};
  ObstacleTable<PlaneLanes> planeLaneTable(planes.size());
  ObstacleTable<SphereLanes> sphereLaneTable(spheres.size());
  const std::span<PlaneLanes> planeLanes = planeLaneTable.items();
  const std::span<SphereLanes> sphereLanes = sphereLaneTable.items();
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const PlaneReach& plane = planes[k];
    planeLanes[k] = {splat(plane.normal.x), splat(plane.normal.y), splat(plane.normal.z), splat(plane.offset)};
  }
  for (std::size_t k = 0; k < spheres.size(); ++k) {
    const SphereReach& sphere = spheres[k];
    sphereLanes[k] = {splat(sphere.center.x), splat(sphere.center.y), splat(sphere.center.z), splat(sphere.reach2)};
  }
  std::size_t contacts = 0, held = 0;
  const std::size_t count = p.size();
  Vec3* __restrict xs = p.position.data();
  Vec3* __restrict vs = p.velocity.data();
  Real* __restrict ages = p.age.data();
  Real* __restrict lifetimes = p.lifetime.data();
  Real* __restrict inverseMasses = p.inverseMass.data();
  Color* __restrict colors = p.color.data();
  std::size_t kept = 0;
  Real speed2 = 0.0, height = 0.0;  // the odd particles out of the lanes below
  Pair speed2Lanes = splat(0.0), heightLanes = splat(0.0);
  std::uint32_t touching[kBlock];  // survivors of the block that reach an obstacle (offsets from its start)
  for (std::size_t begin = 0; begin < count; begin += kBlock) {
    const std::size_t end = std::min(count, begin + kBlock), first = kept;
    std::size_t nTouching = 0;
    // Pass 1: ageing and removal, motion, and a flag for the particles within reach of an obstacle, with
    // no branch on the particles' data but the (almost always taken) survival tests. Exact: a particle
    // that reaches none is left alone by every contact test, so only the flagged ones need pass 2.
    // Two particles per iteration (core/lanes.h: the swirl's two divisions are one divpd each), each lane
    // with the scalar expressions' operations in their order, so the results are those of one particle
    // at a time, bit for bit; an odd block's last particle fills both lanes and only lane 0 is kept.
    for (std::size_t i = begin; i < end; i += 2) {
      const std::size_t j = std::min(i + 1, end - 1);
      const Pair age = Pair{ages[i], ages[j]} + h;
      const PairVec3 x0 = gatherPair(xs, i, j), v0 = gatherPair(vs, i, j);
      const PairVec3 half = halfKickPair(v0, keep, halfKick, swirlKick(x0, cx, cz, halfSwirl, core2));
      const PairVec3 x{x0.x + h * half.x, x0.y + h * half.y, x0.z + h * half.z};
      const PairVec3 v = halfKickPair(half, keep, halfKick, swirlKick(x, cx, cz, halfSwirl, core2));
      PairMask reach{0, 0};
      for (const PlaneLanes& plane : planeLanes) {
        const Pair phi = plane.nx * x.x + plane.ny * x.y + plane.nz * x.z - plane.offset;
        reach |= phi < kContactSlop;
      }
      for (const SphereLanes& sphere : sphereLanes) {
        const Pair rx = x.x - sphere.cx, ry = x.y - sphere.cy, rz = x.z - sphere.cz;
        reach |= rx * rx + ry * ry + rz * rz < sphere.reach2;
      }
      // Stable compaction: after the first removal every survivor slides down by the removals so far.
      auto keepLane = [&](int l, std::size_t from) {
        touching[nTouching] = static_cast<std::uint32_t>(kept - first);
        nTouching += reach[l] != 0;
        xs[kept] = lane(x, l);
        vs[kept] = lane(v, l);
        ages[kept] = age[l];
        if (kept != from) {
          lifetimes[kept] = lifetimes[from];
          inverseMasses[kept] = inverseMasses[from];
          colors[kept] = colors[from];
        }
        ++kept;
      };
      if (!(age[0] >= lifetimes[i])) [[likely]]
        keepLane(0, i);
      if (j != i && !(age[1] >= lifetimes[j])) [[likely]]
        keepLane(1, j);
    }
    // Pass 2: the contact model for the flagged particles, while the block is in cache (PART-5's fast path,
    // fountain_contacts.h).
    const FountainContactCounts blockContacts = resolveFountainContactsFast(
        std::span<Vec3>(xs + first, kept - first), std::span<Vec3>(vs + first, kept - first),
        std::span<const std::uint32_t>(touching, nTouching), obstacles);
    contacts += blockContacts.contacts;
    held += blockContacts.heldBySafetyNet;
    // Pass 3: the energy sums. A NaN or ±∞ anywhere in x or v makes them non-finite (0·∞ is NaN
    // too), so they are also the guard's finiteness test. Two particles per iteration into two partial
    // sums each (lanes), so that the sums are no chain of one addition per particle.
    std::size_t i = first;
    for (; i + 1 < kept; i += 2) {
      const PairVec3 v = gatherPair(vs, i, i + 1), x = gatherPair(xs, i, i + 1);
      speed2Lanes = speed2Lanes + (v.x * v.x + v.y * v.y + v.z * v.z);
      heightLanes = heightLanes + (g.x * x.x + g.y * x.y + g.z * x.z);
    }
    if (i < kept) {
      speed2 += glm::dot(vs[i], vs[i]);
      height += glm::dot(g, xs[i]);
    }
  }
  p.truncate(kept);
  speed2 += speed2Lanes[0] + speed2Lanes[1];
  height += heightLanes[0] + heightLanes[1];
  FountainStepStats stats;
  stats.contacts = contacts;
  stats.heldBySafetyNet = held;
  stats.expired = count - kept;
  stats.nonFinite = !(std::isfinite(speed2) && std::isfinite(height));
  stats.kineticPerMass = 0.5 * speed2;
  stats.potentialPerMass = -height;
  return stats;
}

}  // namespace pba::particles
