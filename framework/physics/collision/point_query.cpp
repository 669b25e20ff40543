#include "physics/collision/point_query.h"

#include <limits>

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
  if (shape.kind == ShapeKind::Hull || shape.kind == ShapeKind::Mesh)
    return Error{field + ": a " + shapeKindName(shape.kind) +
                 " has no point query; use a plane, sphere, capsule or box"};
  return Status::success();
}

// Start-up probe: tells the lab whether CLOTH-7 is still a stub.
PBA_EXERCISE_PROBE(boxSurface(Vec3(0.5), Vec3(0.0, 1.0, 0.0)));

}  // namespace pba::collision
