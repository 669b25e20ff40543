#include "physics/collision/shapes.h"

#include "physics/core/enum_names.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/collision/dynamic_tree.h"
#include "physics/core/validate.h"

namespace pba::collision {

namespace {
constexpr auto kShapeKindNames = enumNames<ShapeKind>({{ShapeKind::Sphere, "sphere"},
                                                       {ShapeKind::Capsule, "capsule"},
                                                       {ShapeKind::Box, "box"},
                                                       {ShapeKind::Hull, "hull"},
                                                       {ShapeKind::Plane, "plane"},
                                                       {ShapeKind::Mesh, "mesh"}});
}  // namespace

const char* shapeKindName(ShapeKind kind) { return kShapeKindNames.name(kind).data(); }

Result<Shape> makeSphere(Real radius, const std::string& field) {
  if (Status s = checkPositive(field + ".radius", radius); !s) return Error{s.error()};
  Shape shape;
  shape.kind = ShapeKind::Sphere;
  shape.radius = radius;
  return shape;
}

Result<Shape> makeCapsule(Real halfHeight, Real radius, const std::string& field) {
  if (Status s = checkPositive(field + ".radius", radius); !s) return Error{s.error()};
  if (Status s = checkPositive(field + ".halfHeight", halfHeight); !s) return Error{s.error()};
  Shape shape;
  shape.kind = ShapeKind::Capsule;
  shape.radius = radius;
  shape.halfHeight = halfHeight;
  return shape;
}

Result<Shape> makeBox(const Vec3& halfExtents, const std::string& field) {
  for (int k = 0; k < 3; ++k) {
    static const char* axis[] = {"x", "y", "z"};
    if (Status s = checkPositive(field + ".halfExtents." + axis[k], halfExtents[k]); !s) return Error{s.error()};
  }
  Shape shape;
  shape.kind = ShapeKind::Box;
  shape.halfExtents = halfExtents;
  shape.hull = std::make_shared<const ConvexHull>(boxHull(halfExtents));
  return shape;
}

Result<Shape> makeHull(const std::vector<Vec3>& points, const std::string& field) {
  Result<ConvexHull> hull = buildConvexHull(points, field);
  if (!hull) return Error{hull.error()};
  Shape shape;
  shape.kind = ShapeKind::Hull;
  shape.hull = std::make_shared<const ConvexHull>(std::move(hull).value());
  return shape;
}

Shape makePlane() {
  Shape shape;
  shape.kind = ShapeKind::Plane;
  return shape;
}

Shape makeMesh(TriangleMesh mesh) {
  Shape shape;
  shape.kind = ShapeKind::Mesh;
  shape.mesh = std::make_shared<const TriangleMesh>(std::move(mesh));
  return shape;
}

Result<TriangleMesh> buildTriangleMesh(std::vector<Vec3> vertices, std::vector<std::array<std::uint32_t, 3>> triangles,
                                       const std::string& field) {
  if (triangles.empty()) return Error{field + ".triangles: must not be empty"};
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (!isFinite(vertices[i])) return Error{field + ".vertices[" + std::to_string(i) + "]: must be finite"};
  TriangleMesh mesh;
  auto tree = std::make_shared<DynamicTree>(0.0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    for (std::uint32_t v : tri)
      if (v >= vertices.size())
        return Error{field + ".triangles[" + std::to_string(t) + "]: index " + std::to_string(v) + " out of range"};
    const Vec3 n = glm::cross(vertices[tri[1]] - vertices[tri[0]], vertices[tri[2]] - vertices[tri[0]]);
    const Real twiceArea = glm::length(n);
    if (!(twiceArea > 1e-14)) return Error{field + ".triangles[" + std::to_string(t) + "]: degenerate (zero area)"};
    mesh.normals.push_back(n / twiceArea);
    Aabb box;
    for (std::uint32_t v : tri) box.grow(vertices[v]);
    tree->createProxy(box, static_cast<int>(t));
  }
  mesh.vertices = std::move(vertices);
  mesh.triangles = std::move(triangles);
  mesh.tree = std::move(tree);
  return mesh;
}

Vec3 coreSupport(const Shape& shape, const Vec3& d) {
  switch (shape.kind) {
    case ShapeKind::Sphere:
      return Vec3(0.0);
    case ShapeKind::Capsule:
      return Vec3(0.0, d.y >= 0.0 ? shape.halfHeight : -shape.halfHeight, 0.0);
    case ShapeKind::Box: {
      const Vec3& h = shape.halfExtents;
      return {d.x >= 0.0 ? h.x : -h.x, d.y >= 0.0 ? h.y : -h.y, d.z >= 0.0 ? h.z : -h.z};
    }
    case ShapeKind::Hull: {
      const std::vector<Vec3>& v = shape.hull->vertices;
      std::size_t best = 0;
      Real bestDot = glm::dot(v[0], d);
      for (std::size_t i = 1; i < v.size(); ++i) {
        const Real dd = glm::dot(v[i], d);
        if (dd > bestDot) bestDot = dd, best = i;
      }
      return v[best];
    }
    case ShapeKind::Plane:
    case ShapeKind::Mesh:
      break;
  }
  return Vec3(0.0);
}

CoreVertices::CoreVertices(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::Sphere:
      size_ = 1;
      break;
    case ShapeKind::Capsule:
      round_[0] = Vec3(0.0, -shape.halfHeight, 0.0);
      round_[1] = Vec3(0.0, shape.halfHeight, 0.0);
      size_ = 2;
      break;
    case ShapeKind::Box:
    case ShapeKind::Hull:
      data_ = shape.hull->vertices.data();
      size_ = shape.hull->vertices.size();
      break;
    case ShapeKind::Plane:
    case ShapeKind::Mesh:
      break;
  }
}

Aabb computeAabb(const Shape& shape, const Transform& pose) {
  const Mat3 r = glm::mat3_cast(pose.rotation);
  Aabb box;
  switch (shape.kind) {
    case ShapeKind::Sphere:
      return {pose.position - Vec3(shape.radius), pose.position + Vec3(shape.radius)};
    case ShapeKind::Capsule: {
      const Vec3 axis = shape.halfHeight * r[1];
      const Vec3 e = glm::abs(axis) + Vec3(shape.radius);
      return {pose.position - e, pose.position + e};
    }
    case ShapeKind::Box: {
      // Extent along world axis i: Σ_j |R_ij| h_j (Ericson §4.2.6).
      const Vec3& h = shape.halfExtents;
      const Vec3 e = glm::abs(r[0]) * h.x + glm::abs(r[1]) * h.y + glm::abs(r[2]) * h.z;
      return {pose.position - e, pose.position + e};
    }
    case ShapeKind::Hull:
      for (const Vec3& v : shape.hull->vertices) box.grow(pose.position + r * v);
      return box;
    case ShapeKind::Plane: {
      // Unbounded: a large but finite box (keeps the broad phase's arithmetic finite).
      constexpr Real kHuge = 1e6;  // [m]
      return {Vec3(-kHuge), Vec3(kHuge)};
    }
    case ShapeKind::Mesh:
      for (const Vec3& v : shape.mesh->vertices) box.grow(pose.position + r * v);
      return box;
  }
  return box;
}

Real minimumExtent(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::Sphere:
    case ShapeKind::Capsule:
      return shape.radius;
    case ShapeKind::Box:
      return std::min({shape.halfExtents.x, shape.halfExtents.y, shape.halfExtents.z});
    case ShapeKind::Hull: {
      Real r = std::numeric_limits<Real>::max();
      for (const HullFace& f : shape.hull->faces) r = std::min(r, f.offset);
      return std::max(r, 0.0);
    }
    case ShapeKind::Plane:
    case ShapeKind::Mesh:
      return 0.0;
  }
  return 0.0;
}

Real boundingRadius(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::Sphere:
      return shape.radius;
    case ShapeKind::Capsule:
      return shape.halfHeight + shape.radius;
    case ShapeKind::Box:
      return glm::length(shape.halfExtents);
    case ShapeKind::Hull: {
      Real r = 0.0;
      for (const Vec3& v : shape.hull->vertices) r = std::max(r, glm::length(v));
      return r;
    }
    case ShapeKind::Plane:
    case ShapeKind::Mesh:
      return 0.0;
  }
  return 0.0;
}

}  // namespace pba::collision
