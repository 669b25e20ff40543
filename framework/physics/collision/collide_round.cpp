// Round pairs in closed form: the cores are points and segments, so the closest points of the cores
// (Ericson §5.1.2, §5.1.9) reduce every pair to two spheres, whose contact is COLL-1's.
#include <cmath>
#include <optional>

#include "physics/collision/closest_points.h"
#include "physics/collision/exercises.h"
#include "physics/collision/narrow_phase.h"

namespace pba::collision {
namespace {

// One contact from the closest points ca (core of A) and cb (core of B): two spheres about them, which is
// COLL-1 (collision/exercises.h), asked with A's radius grown by the speculative margin so that it reports
// every pair within the margin; its depth and midpoint are then moved back to the real surfaces.
Manifold fromCorePoints(const Vec3& ca, Real ra, const Vec3& cb, Real rb, Real margin, std::uint32_t id) {
  Manifold m;
  const std::optional<SphereContact> c = sphereSphereContact(ca, ra + margin, cb, rb);
  if (!c) return m;
  m.normal = c->normal;
  m.separation = margin - c->depth;
  m.add(c->point - 0.5 * margin * c->normal, m.separation, id);
  return m;
}

struct Segment {
  Vec3 p, q;
};
Segment coreSegment(const Shape& capsule, const Transform& pose) {
  const Vec3 axis = pose.rotate(Vec3(0.0, capsule.halfHeight, 0.0));
  return {pose.position - axis, pose.position + axis};
}

}  // namespace

Manifold collideSpheres(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin) {
  return fromCorePoints(pa.position, a.radius, pb.position, b.radius, margin, 0);
}

Manifold collideSphereCapsule(const Shape& sphere, const Transform& ps, const Shape& capsule, const Transform& pc,
                              Real margin) {
  const Segment s = coreSegment(capsule, pc);
  const Vec3 onSegment = closestPointOnSegment(ps.position, s.p, s.q);
  return fromCorePoints(ps.position, sphere.radius, onSegment, capsule.radius, margin, 0);
}

Manifold collideCapsules(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin) {
  const Segment sa = coreSegment(a, pa), sb = coreSegment(b, pb);
  const SegmentPair c = closestPointsSegments(sa.p, sa.q, sb.p, sb.q);
  Manifold m = fromCorePoints(c.onFirst, a.radius, c.onSecond, b.radius, margin, 0);
  if (m.count == 0) return m;
  // Nearly parallel capsules lying side by side: two points at the ends of the overlap of B's segment
  // projected onto A's, so that a capsule resting on another does not rock on one point.
  const Vec3 da = sa.q - sa.p, db = sb.q - sb.p;
  const Real la = glm::length(da), lb = glm::length(db);
  const Real sinAngle = glm::length(glm::cross(da, db)) / (la * lb);
  if (sinAngle > 0.05) return m;
  const Vec3 ua = da / la;
  Real t0 = glm::dot(sb.p - sa.p, ua), t1 = glm::dot(sb.q - sa.p, ua);
  if (t0 > t1) std::swap(t0, t1);
  t0 = std::max(t0, 0.0);
  t1 = std::min(t1, la);
  if (t1 - t0 < 0.01 * la) return m;
  Manifold two;
  two.normal = m.normal;
  two.separation = m.separation;
  std::uint32_t id = 1;
  for (Real t : {t0, t1}) {
    const Vec3 onA = sa.p + t * ua;
    const Vec3 onB = closestPointOnSegment(onA, sb.p, sb.q);
    const Real s = glm::dot(onB - onA, m.normal) - a.radius - b.radius;
    if (s <= margin) two.add(0.5 * (onA + a.radius * m.normal + onB - b.radius * m.normal), s, id);
    ++id;
  }
  return two.count ? two : m;
}

Manifold collideSphereBox(const Shape& sphere, const Transform& ps, const Shape& box, const Transform& pb,
                          Real margin) {
  // In the box frame: clamp the centre to the box. Outside: the clamped point is the closest one.
  // Inside: the nearest face gives the normal and the (negative) distance.
  const Vec3 c = pb.applyInverse(ps.position);
  const Vec3& h = box.halfExtents;
  const Vec3 q = closestPointOnBox(c, h);
  Manifold m;
  const Vec3 d = c - q;
  const Real dd = glm::dot(d, d);
  Vec3 normalLocal;  // from the box toward the sphere
  Real distance;
  Vec3 onBox = q;
  if (dd > 1e-24) {
    distance = std::sqrt(dd);
    normalLocal = d / distance;
  } else {
    int axis = 0;
    Real best = h.x - std::abs(c.x);
    for (int k = 1; k < 3; ++k)
      if (h[k] - std::abs(c[k]) < best) best = h[k] - std::abs(c[k]), axis = k;
    normalLocal = Vec3(0.0);
    normalLocal[axis] = c[axis] >= 0.0 ? 1.0 : -1.0;
    distance = -best;
    onBox = c;
    onBox[axis] = normalLocal[axis] * h[axis];
  }
  m.separation = distance - sphere.radius;
  if (m.separation > margin) return m;
  m.normal = -pb.rotate(normalLocal);  // from the sphere (A) toward the box (B)
  const Vec3 surfaceBox = pb.apply(onBox);
  const Vec3 surfaceSphere = ps.position + sphere.radius * m.normal;
  m.add(0.5 * (surfaceBox + surfaceSphere), m.separation, 0);
  return m;
}

}  // namespace pba::collision
