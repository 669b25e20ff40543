#pragma once
// GJK distance and EPA penetration depth between two convex cores (Gilbert, Johnson & Keerthi 1988;
// van den Bergen, "Collision Detection in Interactive 3D Environments" ch. 4; Ericson §9.5; Catto,
// "Computing Distance using GJK", GDC 2010). Shapes are cores (points, segments, boxes, hulls, triangles)
// inflated by a radius, so GJK only ever sees polytopes, where it and EPA terminate exactly.
//
// Minkowski difference convention: w = a − b with a ∈ A, b ∈ B. A and B overlap ⇔ 0 ∈ A − B. When they
// are apart, the point v of A − B closest to 0 gives the core distance |v| and the normal from A to B
// n = −v/|v|. When they overlap, EPA finds the face of A − B nearest to 0, with outward normal n and
// distance d: moving B by d·n separates them, so n again points from A to B.
#include <array>

#include "physics/collision/shapes.h"

namespace pba::collision {

/// A convex core as a small set of local points plus a radius (Box2D's b2ShapeProxy). Boxes and hulls
/// point into their hull's vertices; spheres, capsules and triangles keep their points inline.
struct ConvexProxy {
  const Vec3* external = nullptr;
  std::array<Vec3, 3> inlinePoints{};
  int count = 0;
  Real radius = 0.0;  ///< [m]
  const Vec3* points() const { return external ? external : inlinePoints.data(); }
};

/// The proxy of a convex shape (not a plane or mesh). Keep the shape alive while the proxy is used.
ConvexProxy makeProxy(const Shape& shape);
/// A triangle (local points) with a radius, for mesh queries.
ConvexProxy makeTriangleProxy(const Vec3& a, const Vec3& b, const Vec3& c, Real radius = 0.0);

struct SimplexVertex {
  Vec3 a{0.0}, b{0.0}, w{0.0};  ///< support points on A and B (world) and w = a − b
  int indexA = 0, indexB = 0;
};

struct DistanceResult {
  Vec3 pointA{0.0}, pointB{0.0};  ///< closest points on the cores (world); equal when overlapping
  Real distance = 0.0;            ///< core distance [m] (0 when the cores overlap)
  bool overlap = false;           ///< the cores intersect (distance 0)
  int iterations = 0;
  std::array<SimplexVertex, 4> simplex{};
  int simplexCount = 0;
};

/// GJK: distance between the cores of a (at poseA) and b (at poseB). Radii are not applied.
DistanceResult gjkDistance(const ConvexProxy& a, const Transform& poseA, const ConvexProxy& b, const Transform& poseB);

struct PenetrationResult {
  bool valid = false;             ///< false only if EPA failed to build a polytope (degenerate input)
  Vec3 normal{0.0};               ///< unit, from A to B
  Real depth = 0.0;               ///< of the cores [m], ≥ 0
  Vec3 pointA{0.0}, pointB{0.0};  ///< deepest points of the cores (world)
  int iterations = 0;
};

/// EPA from the terminating simplex of an overlapping gjkDistance call.
PenetrationResult epaPenetration(const ConvexProxy& a, const Transform& poseA, const ConvexProxy& b,
                                 const Transform& poseB, const DistanceResult& gjk);

/// Signed distance of the inflated shapes and the normal from A to B: GJK when the cores are apart
/// (distance − rA − rB), EPA when they overlap (−depth − rA − rB). The general narrow-phase query, also
/// the reference for the special cases in the tests.
struct SignedDistance {
  bool valid = true;
  Real separation = 0.0;  ///< [m], < 0 when penetrating
  Vec3 normal{0.0, 1.0, 0.0};
  Vec3 pointA{0.0}, pointB{0.0};  ///< on the surfaces of A and B (world)
};
SignedDistance signedDistance(const ConvexProxy& a, const Transform& poseA, const ConvexProxy& b,
                              const Transform& poseB);

}  // namespace pba::collision
