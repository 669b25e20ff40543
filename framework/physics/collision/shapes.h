#pragma once
// Collision shapes in their local frame (Ericson, Real-Time Collision Detection ch. 4; Box2D v3 and
// Jolt keep a shape's geometry apart from the body that carries it, as here).
//
// Every convex shape is a *core* (point, segment, box or polytope) inflated by a radius: a sphere is a
// point with radius r, a capsule a segment with radius r, a box and a hull have radius 0. Distance and
// penetration queries work on the cores and add the radii (GJK on cores is exact for polytopes and
// avoids EPA on curved surfaces). Local frames: a capsule's segment runs along local y, a plane is the
// local plane y = 0 with normal +y (solid below). Planes and triangle meshes are static only.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "physics/collision/aabb.h"
#include "physics/collision/transform.h"
#include "physics/core/result.h"

namespace pba::collision {

enum class ShapeKind { Sphere, Capsule, Box, Hull, Plane, Mesh };
/// "sphere", "capsule", "box", "hull", "plane", "mesh".
const char* shapeKindName(ShapeKind kind);

/// One face of a convex hull: a convex polygon, vertices counter-clockwise seen from outside, on the
/// plane normal·x = offset (normal outward, unit).
struct HullFace {
  std::vector<int> vertices;
  Vec3 normal{0.0};
  Real offset = 0.0;  ///< [m]
};

/// An edge of a hull between the faces on its two sides (for the edge–edge axes of the separating
/// axis test: the arc between the two face normals on the Gauss map, Gregorius GDC 2013).
struct HullEdge {
  int a = 0, b = 0;          ///< vertex indices
  int faceA = 0, faceB = 0;  ///< the faces that share it
};

/// A convex polyhedron with merged coplanar faces (a box has 6 quadrilateral faces, not 12 triangles).
struct ConvexHull {
  std::vector<Vec3> vertices;  ///< [m] local frame
  std::vector<HullFace> faces;
  std::vector<HullEdge> edges;
};

/// Builds the convex hull of `points` (incremental hull, Ericson §12.4.2 / O'Rourke ch. 4), merging
/// coplanar triangles into polygons. Errors: fewer than 4 points, non-finite points, or all points
/// (nearly) coplanar. `field` names the input in messages ("pile.hull").
Result<ConvexHull> buildConvexHull(const std::vector<Vec3>& points, const std::string& field = "hull");
/// The hull of a box of half extents h centred at the origin (faces ±x, ±y, ±z in that order).
ConvexHull boxHull(const Vec3& halfExtents);
/// The same hull moved by `offset` (recentring on the centre of mass).
ConvexHull translated(const ConvexHull& hull, const Vec3& offset);

class DynamicTree;

/// A static triangle mesh with a bounding-volume tree over its triangles.
struct TriangleMesh {
  std::vector<Vec3> vertices;                           ///< [m] local frame
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< counter-clockwise seen from the front
  std::vector<Vec3> normals;                            ///< unit, one per triangle (front side)
  std::shared_ptr<const DynamicTree> tree;              ///< triangle AABBs (local frame), leaf data = triangle index
};

/// Validates and indexes a triangle mesh (indices in range, no degenerate triangle, finite vertices).
Result<TriangleMesh> buildTriangleMesh(std::vector<Vec3> vertices, std::vector<std::array<std::uint32_t, 3>> triangles,
                                       const std::string& field = "mesh");

/// A shape: geometry in its local frame. Cheap to copy (hulls and meshes are shared).
struct Shape {
  ShapeKind kind = ShapeKind::Sphere;
  Real radius = 0.0;                       ///< [m] sphere and capsule radius (0 for the others)
  Real halfHeight = 0.0;                   ///< [m] capsule: half the length of its segment along local y
  Vec3 halfExtents{0.0};                   ///< [m] box
  std::shared_ptr<const ConvexHull> hull;  ///< box (its polytope, for the general queries) and hull
  std::shared_ptr<const TriangleMesh> mesh;

  bool isConvex() const { return kind != ShapeKind::Plane && kind != ShapeKind::Mesh; }
};

/// Constructors that validate their inputs; messages name `field` ("stack.box.halfExtents: ...").
Result<Shape> makeSphere(Real radius, const std::string& field = "sphere");
Result<Shape> makeCapsule(Real halfHeight, Real radius, const std::string& field = "capsule");
Result<Shape> makeBox(const Vec3& halfExtents, const std::string& field = "box");
/// A hull shape; its vertices are used as given (see centeredHull to put the centre of mass at 0).
Result<Shape> makeHull(const std::vector<Vec3>& points, const std::string& field = "hull");
Shape makePlane();
Shape makeMesh(TriangleMesh mesh);

/// World AABB of `shape` at `pose` (exact for spheres, capsules and boxes; vertex bound for hulls).
Aabb computeAabb(const Shape& shape, const Transform& pose);
/// Largest distance of the shape's surface from its local origin [m] (0 for planes and meshes):
/// bounds the speed of a surface point, |v| + |ω| r, in conservative advancement.
Real boundingRadius(const Shape& shape);

/// Smallest distance from the origin to the surface of a convex shape [m] (sphere and capsule: the
/// radius; box: the smallest half extent; hull: the nearest face plane): how far it may move in a step
/// before it could pass through something thin.
Real minimumExtent(const Shape& shape);

/// Support point of the core in local coordinates: argmax over the core of d·x (d need not be unit).
Vec3 coreSupport(const Shape& shape, const Vec3& direction);
/// The radius added to the core: the sphere's and capsule's radius, 0 for polytopes.
inline Real coreRadius(const Shape& shape) { return shape.radius; }
/// The core's vertices in local coordinates: 1 (sphere), 2 (capsule), 8 (box), or the hull's; none for
/// planes and meshes. A view, so that a query needs no buffer: a polytope's are its hull's vertices, a
/// round core's are held inline. Not copyable (it may point into itself).
class CoreVertices {
 public:
  explicit CoreVertices(const Shape& shape);
  CoreVertices(const CoreVertices&) = delete;
  CoreVertices& operator=(const CoreVertices&) = delete;
  const Vec3* begin() const { return data_; }
  const Vec3* end() const { return data_ + size_; }
  std::size_t size() const { return size_; }
  const Vec3& operator[](std::size_t i) const { return data_[i]; }

 private:
  Vec3 round_[2]{Vec3(0.0), Vec3(0.0)};  // a sphere's centre, or a capsule's segment ends
  const Vec3* data_ = round_;
  std::size_t size_ = 0;
};

}  // namespace pba::collision
