#pragma once
// Narrow phase: contact manifolds between pairs of shapes (Ericson ch. 4–5; Catto, "Contact
// Manifolds", GDC 2007; Gregorius, "The Separating Axis Test between Convex Polyhedra", GDC 2013, and
// "Robust Contact Creation for Physics Simulations", GDC 2015). Every function takes shape A first and
// returns normals from A to B; a pair farther apart than `margin` (the speculative distance) gives an
// empty manifold (count 0).
//
// Which test serves which pair:
//   sphere–sphere, sphere–capsule, capsule–capsule   closest points of the cores in closed form
//   sphere–box                                       closest point on the box (inside: nearest face)
//   box–box                                          separating axes (3 + 3 faces, 9 edge pairs) and
//                                                    reference-face clipping, up to 4 points
//   hull–hull, box–hull                              separating axes over faces and the edge pairs that
//                                                    form Minkowski faces, and clipping
//   any other convex pair (capsule–box, …–hull, …–triangle)
//                                                    GJK distance / EPA depth, then clipping of the
//                                                    supporting features when they are faces or segments
//   anything–plane                                   the core's vertices below the plane, up to 4
//   anything–mesh                                    the convex pair test per triangle near the shape
#include <vector>

#include "physics/collision/manifold.h"
#include "physics/collision/shapes.h"

namespace pba::collision {

/// A polytope in world coordinates: the separating axis test's copy of a hull, moved once per query.
struct WorldHull {
  std::vector<Vec3> vertices, normals;  // [m], unit
  std::vector<Real> offsets;            // [m] each face plane's n·x
  Vec3 centroid{0.0};                   // [m] mean of the vertices
};

/// The narrow phase's scratch memory: buffers a query fills and forgets, kept by the caller so that a
/// warm caller allocates nothing (the rigid world owns one, as Box2D's step context owns its arena and
/// Jolt's update takes a TempAllocator). Queries with different scratch may run at once on different
/// threads; the contents mean nothing between calls.
struct NarrowPhaseScratch {
  std::vector<ManifoldPoint> candidates;  // collideConvexPlane: the core vertices within the margin
  WorldHull hullA, hullB;                 // collidePolytopes: both hulls in world coordinates
};

Manifold collideSpheres(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin);
Manifold collideSphereCapsule(const Shape& sphere, const Transform& ps, const Shape& capsule, const Transform& pc,
                              Real margin);
Manifold collideCapsules(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin);
Manifold collideSphereBox(const Shape& sphere, const Transform& ps, const Shape& box, const Transform& pb, Real margin);
Manifold collideBoxes(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin);
/// Any two polytopes (boxes or hulls) by the separating axis test.
Manifold collidePolytopes(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin,
                          NarrowPhaseScratch& scratch);
/// The general convex pair: GJK/EPA for the normal and depth, then feature clipping.
Manifold collideConvex(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin);
/// A convex shape against a plane (the plane is B).
Manifold collideConvexPlane(const Shape& convex, const Transform& pc, const Transform& planePose, Real margin,
                            NarrowPhaseScratch& scratch);
/// A convex shape against the triangles of a mesh (the mesh is B); one manifold per touching triangle,
/// its key the triangle index.
void collideConvexMesh(const Shape& convex, const Transform& pc, const Shape& mesh, const Transform& pm, Real margin,
                       std::vector<Manifold>& out);

/// Dispatches on the kinds (swapping and flipping as needed) and appends the non-empty manifolds.
/// Plane–plane, plane–mesh and mesh–mesh give nothing (static only).
void collide(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin,
             std::vector<Manifold>& out, NarrowPhaseScratch& scratch);

}  // namespace pba::collision
