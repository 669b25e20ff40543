#pragma once
// Drawing shapes at poses through pba::DebugDraw: the one routine for the rigid world's bodies and the
// cloth's colliders.
#include <cstdint>
#include <vector>

#include "physics/collision/shapes.h"
#include "physics/collision/transform.h"
#include "physics/core/debug_draw.h"

namespace pba::collision {

/// Triangles gathered for one DebugDraw::triangles call: world positions, one unit normal per position,
/// indices in threes.
struct TriangleBatch {
  std::vector<Vec3> positions, normals;
  std::vector<std::uint32_t> indices;
};

/// Appends a hull's faces at `pose`, each fanned into triangles with the face's normal, to `batch` (a pile
/// of hundreds of hulls then draws in a handful of calls).
void appendHullTriangles(TriangleBatch& batch, const ConvexHull& hull, const Transform& pose);

/// Draws `shape` at `pose`: spheres, capsules and boxes as the renderer's solids, hulls and meshes as
/// triangles. A plane draws nothing where it is the ground y = 0 with normal +y (the renderer's grid
/// shows it) and a 20 m square outline elsewhere.
void drawShape(DebugDraw& d, const Shape& shape, const Transform& pose, const Color& color);

}  // namespace pba::collision
