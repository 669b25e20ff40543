#include <algorithm>
#include <cmath>

#include "physics/core/lanes.h"
#include "physics/exercises/not_implemented.h"  // the switch of the isolation build (student_release.sh)
#include "physics/particles/fountain_contacts.h"

namespace pba::particles {

// Fast path of PART-5 in the fountain: the scalar route pays, per contact, a call of resolveContact and
// one of contactVelocity, each with branches on the particle's data (touching or not, inward or not,
// impact or resting, sticking or sliding, the safety net); in a settled pool a third of the particles
// rest on the ground and the stick-or-slide branch is a coin toss. Here two flagged particles share the
// lanes of a Pair: each lane computes every branch of the contact model and keeps the one the scalar
// route takes (selectPair), so a mispredicted branch costs nothing and one sqrtpd or divpd serves two
// particles. The only branches left skip an obstacle that neither particle touches, or a contact that
// neither particle enters. Every lane does the IEEE operations of resolveContact and PART-5 in their
// order (no fused or reordered arithmetic), and the lanes that a branch would have skipped keep their
// bits, so the positions, velocities and counts are those of resolveFountainContactsScalar to the bit.
// A lane whose result is dropped divides by 1 instead of a zero (no spurious floating-point exception:
// the tests run with traps on).
// flatten: the lambda below inlines into the loop, as in relaxSticksFast.
[[gnu::flatten]] FountainContactCounts resolveFountainContactsFast(std::span<Vec3> x, std::span<Vec3> v,
                                                                   std::span<const std::uint32_t> flagged,
                                                                   const FountainObstacles& o) {
  // BEGIN SOLUTION
  const ContactMaterial& m = o.material;
  const Vec3 a = o.step.acceleration;
  const Real dt = o.step.dt;
  const Pair zero = splat(0.0), one = splat(1.0);
  FountainContactCounts counts;
  std::size_t lanes = 2;  // 1 for an odd last particle, which fills both lanes
  auto lanesSet = [&](PairMask mask) {
    return static_cast<std::size_t>(mask[0] != 0) + static_cast<std::size_t>(lanes == 2 && mask[1] != 0);
  };
  // resolveContact for both lanes against the surface with outward unit normal n at signed distance phi,
  // for the lanes in `touching` (φ < slop); aN = max(0, −n·a), the inward part of the acceleration.
  auto respond = [&](PairVec3& px, PairVec3& pv, const PairVec3& n, Pair phi, PairMask touching, Pair aN) {
    const PairMask below = touching & (phi < 0.0);
    const Pair depth = selectPair(below, -phi, zero);
    px = {selectPair(below, px.x + depth * n.x, px.x), selectPair(below, px.y + depth * n.y, px.y),
          selectPair(below, px.z + depth * n.z, px.z)};
    const Pair vn = pv.x * n.x + pv.y * n.y + pv.z * n.z;
    const PairMask inward = touching & (vn < 0.0);
    if (!anyLane(inward)) return;
    // Impact or resting contact: the contact-time speed, compared in squares.
    const Pair s = -vn;
    const Pair fall = s * s - 2.0 * aN * depth;
    const Pair contactSpeed2 = selectPair(fall > 0.0, fall, zero);
    const Pair threshold = m.restingSpeed + aN * dt;
    const PairMask resting = contactSpeed2 <= threshold * threshold;
    const Pair back = s - sqrtPair(contactSpeed2);
    const PairVec3 u{selectPair(resting, pv.x, pv.x + back * n.x), selectPair(resting, pv.y, pv.y + back * n.y),
                     selectPair(resting, pv.z, pv.z + back * n.z)};
    const Pair restitution = selectPair(resting, zero, splat(m.restitution));
    // The contact velocity: restitution on the normal part, Coulomb friction on the tangential part.
    const Pair un = n.x * u.x + n.y * u.y + n.z * u.z;
    const PairVec3 t{u.x - un * n.x, u.y - un * n.y, u.z - un * n.z};
    const Pair e = selectPair(-un > m.restingSpeed, restitution, zero);
    const Pair dvn = -(1.0 + e) * un;
    const Pair tangentialSpeed = sqrtPair(t.x * t.x + t.y * t.y + t.z * t.z);
    const PairMask slides = tangentialSpeed > m.staticFriction * dvn;
    // A leaving lane (un ≥ 0, dvn ≤ 0) "slides" at any speed, 0 included: it divides by 1 instead.
    const Pair kept =
        1.0 - m.kineticFriction * dvn / selectPair(slides & (tangentialSpeed > 0.0), tangentialSpeed, one);
    const Pair share = selectPair(kept > 0.0, kept, zero);
    const Pair en = e * un;
    const PairMask leaving = un >= 0.0;
    PairVec3 w{selectPair(leaving, u.x, selectPair(slides, t.x * share, zero) - en * n.x),
               selectPair(leaving, u.y, selectPair(slides, t.y * share, zero) - en * n.y),
               selectPair(leaving, u.z, selectPair(slides, t.z * share, zero) - en * n.z)};
    // The safety net: no inward speed left.
    const Pair after = w.x * n.x + w.y * n.y + w.z * n.z;
    const PairMask net = after < 0.0;
    w = {selectPair(net, w.x - after * n.x, w.x), selectPair(net, w.y - after * n.y, w.y),
         selectPair(net, w.z - after * n.z, w.z)};
    pv = {selectPair(inward, w.x, pv.x), selectPair(inward, w.y, pv.y), selectPair(inward, w.z, pv.z)};
    counts.contacts += lanesSet(inward);
    counts.heldBySafetyNet += lanesSet(inward & net & (after < -kSafetyNetSpeed));
  };

  const std::size_t count = flagged.size();
  for (std::size_t k = 0; k < count; k += 2) {
    lanes = k + 1 < count ? 2 : 1;
    const std::size_t i = flagged[k], j = flagged[k + lanes - 1];
    PairVec3 px = gatherPair(x.data(), i, j), pv = gatherPair(v.data(), i, j);
    for (const PlaneReach& plane : o.planes) {
      const Vec3 normal = plane.normal;
      const Pair phi = normal.x * px.x + normal.y * px.y + normal.z * px.z - plane.offset;
      const PairMask touching = phi < kContactSlop;
      if (!anyLane(touching)) continue;
      const Pair aN = splat(std::max(0.0, -glm::dot(a, normal)));
      respond(px, pv, {splat(normal.x), splat(normal.y), splat(normal.z)}, phi, touching, aN);
    }
    for (const SphereReach& sphere : o.spheres) {
      const PairVec3 r{px.x - sphere.center.x, px.y - sphere.center.y, px.z - sphere.center.z};
      const Pair l2 = r.x * r.x + r.y * r.y + r.z * r.z;
      const PairMask near = (l2 < sphere.reach2) & (l2 > 0.0);
      if (!anyLane(near)) continue;
      const Pair l = sqrtPair(selectPair(near, l2, one));
      const PairVec3 n{r.x / l, r.y / l, r.z / l};
      const Pair phi = l - sphere.surface;
      const Pair inwardAcceleration = -(a.x * n.x + a.y * n.y + a.z * n.z);
      respond(px, pv, n, phi, near & (phi < kContactSlop),
              selectPair(inwardAcceleration > 0.0, inwardAcceleration, zero));
    }
    x[i] = lane(px, 0);
    v[i] = lane(pv, 0);
    if (lanes == 2) {
      x[j] = lane(px, 1);
      v[j] = lane(pv, 1);
    }
  }
  return counts;
  // END SOLUTION
  // FAST PATH: PART-5 (the hand-out runs the scalar contact pass over your contactVelocity)
  // STUB: return resolveFountainContactsScalar(x, v, flagged, o);
}

}  // namespace pba::particles
