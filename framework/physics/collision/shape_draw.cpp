#include "physics/collision/shape_draw.h"

namespace pba::collision {
namespace {

void drawMesh(DebugDraw& d, const TriangleMesh& m, const Transform& pose, const Color& color) {
  TriangleBatch batch;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto base = static_cast<std::uint32_t>(batch.positions.size());
    for (std::uint32_t v : m.triangles[t])
      batch.positions.push_back(pose.apply(m.vertices[v])), batch.normals.push_back(pose.rotate(m.normals[t]));
    batch.indices.insert(batch.indices.end(), {base, base + 1, base + 2});
  }
  d.triangles(batch.positions, batch.normals, batch.indices, color);
}

/// The renderer's ground grid shows the plane y = 0; any other plane gets a square outline 20 m wide.
void drawPlane(DebugDraw& d, const Transform& pose, const Color& color) {
  const Vec3& p = pose.position;
  if (p.y == 0.0 && glm::dot(pose.rotate(Vec3(0.0, 1.0, 0.0)), Vec3(0.0, 1.0, 0.0)) > 1.0 - 1e-9) return;
  const Vec3 u = pose.rotate(Vec3(10, 0, 0)), v = pose.rotate(Vec3(0, 0, 10));
  d.line(p - u - v, p + u - v, color), d.line(p + u - v, p + u + v, color);
  d.line(p + u + v, p - u + v, color), d.line(p - u + v, p - u - v, color);
}

}  // namespace

void appendHullTriangles(TriangleBatch& batch, const ConvexHull& hull, const Transform& pose) {
  for (const HullFace& f : hull.faces) {
    const auto base = static_cast<std::uint32_t>(batch.positions.size());
    const Vec3 n = pose.rotate(f.normal);
    for (int v : f.vertices) batch.positions.push_back(pose.apply(hull.vertices[v])), batch.normals.push_back(n);
    for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k)
      batch.indices.insert(batch.indices.end(),
                           {base, base + static_cast<std::uint32_t>(k), base + static_cast<std::uint32_t>(k + 1)});
  }
}

void drawShape(DebugDraw& d, const Shape& shape, const Transform& pose, const Color& color) {
  switch (shape.kind) {
    case ShapeKind::Sphere:
      d.sphere(pose.position, shape.radius, color);
      break;
    case ShapeKind::Capsule: {
      const Vec3 axis = pose.rotate(Vec3(0.0, shape.halfHeight, 0.0));
      d.capsule(pose.position - axis, pose.position + axis, shape.radius, color);
      break;
    }
    case ShapeKind::Box:
      d.box(pose.position, shape.halfExtents, pose.rotation, color);
      break;
    case ShapeKind::Hull: {
      TriangleBatch batch;
      appendHullTriangles(batch, *shape.hull, pose);
      d.triangles(batch.positions, batch.normals, batch.indices, color);
      break;
    }
    case ShapeKind::Mesh:
      drawMesh(d, *shape.mesh, pose, color);
      break;
    case ShapeKind::Plane:
      drawPlane(d, pose, color);
      break;
  }
}

}  // namespace pba::collision
