#include "physics/particles/collision.h"

#include <algorithm>
#include <cmath>

#include "physics/core/validate.h"
#include "physics/exercises/not_implemented.h"

namespace pba::particles {

SurfacePoint closestSurface(const PlaneObstacle& o, const Vec3& x) {
  return {glm::dot(o.normal, x - o.point), o.normal};
}

SurfacePoint closestSurface(const SphereObstacle& o, const Vec3& x) {
  const Vec3 d = x - o.center;
  const Real l = glm::length(d);
  if (l <= 0.0) return {-o.radius, kUp};
  return {l - o.radius, d / l};
}

SurfacePoint closestSurface(const BoxObstacle& o, const Vec3& x) {
  // In the box frame: q = |p| − e. Outside, the distance is |max(q, 0)|; inside, max(q) ≤ 0 and the
  // nearest face is the one with the largest q.
  const Vec3 p = glm::conjugate(o.orientation) * (x - o.center);
  const Vec3 q = glm::abs(p) - o.halfExtents;
  const Vec3 sign{p.x < 0.0 ? -1.0 : 1.0, p.y < 0.0 ? -1.0 : 1.0, p.z < 0.0 ? -1.0 : 1.0};
  const Vec3 outside = glm::max(q, Vec3(0.0));
  const Real outsideLength = glm::length(outside);
  Vec3 localNormal;
  Real distance;
  if (outsideLength > 0.0) {
    distance = outsideLength;
    localNormal = sign * outside / outsideLength;
  } else {
    const int axis = q.x >= q.y && q.x >= q.z ? 0 : (q.y >= q.z ? 1 : 2);
    distance = q[axis];
    localNormal = Vec3(0.0);
    localNormal[axis] = sign[axis];
  }
  return {distance, o.orientation * localNormal};
}

Vec3 contactVelocity(const Vec3& v, [[maybe_unused]] const Vec3& normal,
                     [[maybe_unused]] const ContactMaterial& material) {
  // BEGIN SOLUTION
  const Real vn = glm::dot(normal, v);
  if (vn >= 0.0) return v;
  const Vec3 vt = v - vn * normal;
  const Real e = -vn > material.restingSpeed ? material.restitution : 0.0;
  const Real dvn = -(1.0 + e) * vn;
  const Real tangentialSpeed = glm::length(vt);
  Vec3 vtNew(0.0);
  if (tangentialSpeed > material.staticFriction * dvn) {
    vtNew = vt * std::max(0.0, 1.0 - material.kineticFriction * dvn / tangentialSpeed);
  }
  return vtNew - e * vn * normal;
  // END SOLUTION
  // STUB: return exercises::notImplemented("PART-5", v);
}

namespace {
void resolve(Particles& p, std::size_t i, const SurfacePoint& s, Real radius, const ContactMaterial& m,
             const ContactStep& step, CollisionStats& stats) {
  const ContactResult r = resolveContact(p.position[i], p.velocity[i], s.normal, s.distance - radius, m, step);
  stats.deepestPenetration = std::max(stats.deepestPenetration, r.depth);
  stats.contacts += r.kind != ContactKind::None;
  stats.impacts += r.kind == ContactKind::Impact;
  stats.heldBySafetyNet += r.heldBySafetyNet;
}
}  // namespace

CollisionStats collideWithObstacles(Particles& p, const Obstacles& o, Real radius, const ContactStep& step) {
  CollisionStats stats;
  const ContactMaterial& m = o.material;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.inverseMass[i] <= 0.0) continue;
    for (const PlaneObstacle& plane : o.planes) resolve(p, i, closestSurface(plane, p.position[i]), radius, m, step, stats);
    for (const SphereObstacle& s : o.spheres) resolve(p, i, closestSurface(s, p.position[i]), radius, m, step, stats);
    for (const BoxObstacle& b : o.boxes) resolve(p, i, closestSurface(b, p.position[i]), radius, m, step, stats);
  }
  return stats;
}

Status validate(const ContactMaterial& m) {
  for (Status s : {checkRange("material.restitution", m.restitution, 0.0, 1.0),
                   checkRange("material.staticFriction", m.staticFriction, 0.0, 1e3),
                   checkRange("material.kineticFriction", m.kineticFriction, 0.0, 1e3),
                   checkRange("material.restingSpeed", m.restingSpeed, 0.0, 1e3)}) {
    if (!s) return s;
  }
  return Status::success();
}

Status validate(const Obstacles& o) {
  for (const PlaneObstacle& plane : o.planes) {
    if (Status s = checkFinite("planes.point", plane.point); !s) return s;
    if (!(isFinite(plane.normal) && std::abs(glm::length(plane.normal) - 1.0) <= 1e-9)) {
      return Error{"planes.normal: must be a unit vector"};
    }
  }
  for (const SphereObstacle& sphere : o.spheres) {
    if (Status s = checkFinite("spheres.center", sphere.center); !s) return s;
    if (Status s = checkPositive("spheres.radius", sphere.radius); !s) return s;
  }
  for (const BoxObstacle& box : o.boxes) {
    if (Status s = checkFinite("boxes.center", box.center); !s) return s;
    for (int a = 0; a < 3; ++a) {
      if (Status s = checkPositive("boxes.halfExtents", box.halfExtents[a]); !s) return s;
    }
    if (!(std::abs(glm::length(box.orientation) - 1.0) <= 1e-9)) return Error{"boxes.orientation: must be a unit quaternion"};
  }
  return validate(o.material);
}

// Start-up probe: tells the lab whether PART-5 is still a stub.
PBA_EXERCISE_PROBE(contactVelocity(Vec3(0.0, -1.0, 0.0), Vec3(0.0, 1.0, 0.0), ContactMaterial{}));

}  // namespace pba::particles
