#pragma once
// Point queries: how far a world point lies from a shape's surface (negative inside) and the outward unit
// normal at the closest surface point, for planes, spheres, capsules, boxes and hulls at a pose (Ericson,
// Real-Time Collision Detection §5.1: the closest point of a segment §5.1.2 and of a box §5.1.3). The
// cloth's colliders (cloth/colliders.h) are shapes at poses and ask these queries for every particle.
//
// Per kind, with the pose applied (local frames as in shapes.h):
//  - plane (local y = 0, normal +y): the distance is n·(x − c), the normal n = q ŷ, the same everywhere;
//  - sphere: |x − c| − r along (x − c)/|x − c|;
//  - capsule: the sphere of radius r about the closest point of its axis segment, c + clamp((x − c)·a,
//    −h, h) a with a = q ŷ (exact: the capsule is the set of points within r of that segment);
//  - box: CLOTH-7 in the box's frame, the point rotated in with the conjugate rotation and the normal
//    rotated back out.
//  - hull: hullSurface in the hull's frame, rotated in and out as the box.
// A point at a sphere's centre or on a capsule's axis has no direction; it gets +y (the centre is as deep
// as it gets, so any direction leads out at once). Triangle meshes have no point query (no inside):
// checkPointQueryShape says so where a description names one.
#include <algorithm>
#include <string>

#include "physics/collision/shapes.h"
#include "physics/collision/transform.h"
#include "physics/core/result.h"

namespace pba::collision {

/// The signed distance of a point to a surface [m] (negative inside) and the outward unit normal at the
/// surface point closest to it.
struct SurfacePoint {
  Real distance = 0.0;
  Vec3 normal{0.0, 1.0, 0.0};
};

// ***** CLOTH-7: signed distance and normal of a box (Müller et al. 2007 §3.5: collision constraints) *****
// The box is centred at the origin of its own frame, its faces perpendicular to the axes, halfExtents
// [m] from the centre (all > 0). p [m] is the particle in that frame (the caller rotates in and out).
// Return the signed distance of p to the box's surface [m] (negative inside) and the outward unit normal
// at the closest surface point, both in the box frame.
// (1) Per axis, work out how far p lies outside the slab between the two faces of that axis (negative
//     when it lies between them).
// (2) Outside the box (outside at least one slab): the closest point clamps p into the box; the distance
//     and the normal come from the part of p that clamping removes (a face, an edge or a corner is the
//     closest feature depending on how many slabs p is outside), with the normal's signs those of p.
// (3) Inside: the particle leaves through the nearest face; the distance is the least negative of the
//     three slab values and the normal is that face's axis, pointing to the side p is on (+ at 0).
// Check: a point above the top face by d has distance d and normal +y; one beyond an edge or corner lies
// at the Euclidean distance to it, with a unit normal along the offset; the centre is at minus the
// smallest half extent; |normal| = 1 everywhere.
// *****
SurfacePoint boxSurface(const Vec3& halfExtents, const Vec3& p);

/// The same for a convex hull, p in the hull's frame. Inside (below every face plane) the nearest face
/// plane is the nearest surface: the distance is the largest of n·p − offset, along that face's normal.
/// Outside, the closest surface point lies on a face whose plane p is above: per such face, p projected
/// onto the plane if that lands inside the polygon, else the closest point of its edges (Ericson §5.1.2);
/// the normal points from the closest of them to p.
SurfacePoint hullSurface(const ConvexHull& hull, const Vec3& p);

/// A shape at a pose, made ready for many point queries: the rotation normalised once (a pose built from
/// rounded angles still gives unit normals) and its local y axis in world coordinates (a plane's normal,
/// a capsule's axis). Refers to `shape`, which must outlive it.
struct PosedShape {
  const Shape* shape = nullptr;
  Transform pose;
  Vec3 axis{0.0, 1.0, 0.0};  ///< the pose's local y axis, world frame (unit)
};
PosedShape posed(const Shape& shape, const Transform& pose);

/// The closest point of a posed capsule's axis segment to the world point x.
inline Vec3 capsuleAxisPoint(const PosedShape& capsule, const Vec3& x) {
  const Vec3& c = capsule.pose.position;
  const Real h = capsule.shape->halfHeight;
  return c + std::clamp(glm::dot(x - c, capsule.axis), -h, h) * capsule.axis;
}

/// [m] A point this close to a ball's centre (or a capsule's axis) has no direction out of it.
inline constexpr Real kNoDirectionDistance = 1e-12;

/// The signed distance of x to the ball of `radius` about `center` and its outward normal (+y at the centre).
inline SurfacePoint ballSurface(const Vec3& center, Real radius, const Vec3& x) {
  const Vec3 r = x - center;
  const Real l = glm::length(r);
  return {l - radius, l > kNoDirectionDistance ? r / l : Vec3(0.0, 1.0, 0.0)};
}

/// surfacePoint's hull case, out of line (the inline cases stay small); a mesh: +∞ (an assert in debug builds).
SurfacePoint hullSurfacePoint(const PosedShape& hull, const Vec3& x);

/// The signed distance of the world point x to the surface of a posed plane, sphere, capsule, box or hull and
/// the outward normal there (world frame). Meshes: not answered (+∞, an assert in debug builds).
/// Inline: the cloth's collider passes ask it for every particle near a collider.
inline SurfacePoint surfacePoint(const PosedShape& s, const Vec3& x) {
  switch (s.shape->kind) {
    case ShapeKind::Plane:
      return {glm::dot(s.axis, x - s.pose.position), s.axis};
    case ShapeKind::Sphere:
      return ballSurface(s.pose.position, s.shape->radius, x);
    case ShapeKind::Capsule:
      return ballSurface(capsuleAxisPoint(s, x), s.shape->radius, x);
    case ShapeKind::Box: {
      SurfacePoint b = boxSurface(s.shape->halfExtents, s.pose.applyInverse(x));
      b.normal = s.pose.rotate(b.normal);
      return b;
    }
    case ShapeKind::Hull:
    case ShapeKind::Mesh:
      break;
  }
  return hullSurfacePoint(s, x);
}
/// The same for a shape at a pose, prepared for this one query.
SurfacePoint surfacePoint(const Shape& shape, const Transform& pose, const Vec3& x);

/// Success when `shape` has a point query (plane, sphere, capsule, box, hull); else (a mesh, open, with no
/// inside) an error naming `field`.
Status checkPointQueryShape(const Shape& shape, const std::string& field);

}  // namespace pba::collision
