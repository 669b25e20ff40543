#include "physics/collision/point_query.h"

#include <cassert>
#include <cmath>
#include <limits>

#include "physics/collision/closest_points.h"

#include "physics/exercises/not_implemented.h"

namespace pba::collision {

SurfacePoint boxSurface([[maybe_unused]] const Vec3& halfExtents, [[maybe_unused]] const Vec3& p) {
  // BEGIN SOLUTION
  const Vec3 a = glm::abs(p) - halfExtents;  // per-axis distance outside the slab
  SurfacePoint s;
  if (a.x > 0.0 || a.y > 0.0 || a.z > 0.0) {  // outside: distance to the closest point of the box
    const Vec3 outside = glm::max(a, Vec3(0.0));
    s.distance = glm::length(outside);
    s.normal = outside * glm::sign(p) / s.distance;
    return s;
  }
  int axis = 0;  // inside: leave through the nearest face
  if (a.y > a[axis]) axis = 1;
  if (a.z > a[axis]) axis = 2;
  s.normal = Vec3(0.0);
  s.normal[axis] = p[axis] >= 0.0 ? 1.0 : -1.0;
  s.distance = a[axis];
  return s;
  // END SOLUTION
  // STUB: return exercises::notImplemented("CLOTH-7", SurfacePoint{std::numeric_limits<Real>::infinity(), Vec3(0.0, 1.0, 0.0)}, halfExtents, p);
}

SurfacePoint hullSurface(const ConvexHull& hull, const Vec3& p) {
  SurfacePoint inside{-std::numeric_limits<Real>::infinity(), Vec3(0.0, 1.0, 0.0)};
  Real best = std::numeric_limits<Real>::infinity();  // [m²] squared distance to the closest outside point
  Vec3 closest(0.0), closestFace(0.0, 1.0, 0.0);
  for (const HullFace& f : hull.faces) {
    const Real height = glm::dot(f.normal, p) - f.offset;
    if (height <= 0.0) {
      if (height > inside.distance) inside = {height, f.normal};
      continue;
    }
    // Above this face's plane: its polygon's closest point, the projection when that lands inside it.
    const Vec3 q = p - height * f.normal;
    bool within = true;
    const std::size_t n = f.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& a = hull.vertices[f.vertices[k]];
      const Vec3& b = hull.vertices[f.vertices[(k + 1) % n]];
      if (glm::dot(glm::cross(b - a, q - a), f.normal) >= 0.0) continue;  // inside this edge's half-plane
      within = false;
      const Vec3 c = closestPointOnSegment(p, a, b);
      if (const Real d2 = glm::dot(p - c, p - c); d2 < best) best = d2, closest = c, closestFace = f.normal;
    }
    if (within && height * height < best) best = height * height, closest = q, closestFace = f.normal;
  }
  if (!std::isfinite(best)) return inside;  // below every face plane: inside
  const Real d = std::sqrt(best);
  return {d, d > 0.0 ? (p - closest) / d : closestFace};
}

SurfacePoint hullSurfacePoint(const PosedShape& s, const Vec3& x) {
  if (s.shape->kind != ShapeKind::Hull) {
    assert(false && "surfacePoint: no point query for meshes (checkPointQueryShape)");
    return {std::numeric_limits<Real>::infinity(), Vec3(0.0, 1.0, 0.0)};
  }
  SurfacePoint h = hullSurface(*s.shape->hull, s.pose.applyInverse(x));
  h.normal = s.pose.rotate(h.normal);
  return h;
}

PosedShape posed(const Shape& shape, const Transform& pose) {
  PosedShape s;
  s.shape = &shape;
  s.pose = {pose.position, glm::normalize(pose.rotation)};
  s.axis = s.pose.rotate(Vec3(0.0, 1.0, 0.0));
  return s;
}

SurfacePoint surfacePoint(const Shape& shape, const Transform& pose, const Vec3& x) {
  return surfacePoint(posed(shape, pose), x);
}

Status checkPointQueryShape(const Shape& shape, const std::string& field) {
  if (shape.kind == ShapeKind::Mesh)
    return Error{field + ": a mesh has no point query (it has no inside); use a plane, sphere, capsule, box or hull"};
  return Status::success();
}

// Start-up probe: tells the lab whether CLOTH-7 is still a stub.
PBA_EXERCISE_PROBE(boxSurface(Vec3(0.5), Vec3(0.0, 1.0, 0.0)));

}  // namespace pba::collision
