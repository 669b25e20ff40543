#pragma once
// Ray casts against every shape (Ericson, Real-Time Collision Detection §5.3). A ray is origin + t·d with
// |d| = 1 and t ∈ [0, maxT]; a hit reports the first surface point where the ray enters the solid.
// A ray that starts inside a solid convex shape reports no hit (Box2D's convention: it cannot enter).
// Planes are solid below (local y < 0); triangles and meshes are hit from either side.
#include <optional>

#include "physics/collision/ray.h"
#include "physics/collision/shapes.h"

namespace pba::collision {

struct RayHit {
  Real t = 0.0;       ///< distance along the ray [m]
  Vec3 point{0.0};    ///< world hit point [m]
  Vec3 normal{0.0};   ///< unit outward surface normal at the hit (world), against the ray
  int triangle = -1;  ///< mesh triangle index, else −1
};

/// First hit of `ray` (world) with `shape` at `pose`, within maxT [m].
std::optional<RayHit> rayCast(const Shape& shape, const Transform& pose, const Ray& ray, Real maxT);

/// Local-frame kernels (ray in the shape's frame, unit direction).
std::optional<RayHit> rayCastSphere(Real radius, const Ray& ray, Real maxT);
std::optional<RayHit> rayCastCapsule(Real halfHeight, Real radius, const Ray& ray, Real maxT);
std::optional<RayHit> rayCastBox(const Vec3& halfExtents, const Ray& ray, Real maxT);
std::optional<RayHit> rayCastHull(const ConvexHull& hull, const Ray& ray, Real maxT);
std::optional<RayHit> rayCastPlane(const Ray& ray, Real maxT);
std::optional<RayHit> rayCastTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Ray& ray, Real maxT);
std::optional<RayHit> rayCastMesh(const TriangleMesh& mesh, const Ray& ray, Real maxT);

}  // namespace pba::collision
