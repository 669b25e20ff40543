// The general convex pair (Jolt's approach in CollideConvexVsConvex + ManifoldBetweenTwoFaces): GJK on
// the cores gives the normal and separation when they are apart, EPA when they overlap; then the
// supporting features of both shapes along the normal decide the manifold. When one of them is a face
// (a polytope face or a triangle nearly parallel to the contact plane) and the other a face or a
// segment (a capsule lying flat), the incident feature is clipped against the reference face, which
// gives the 2–4 points a resting shape needs; otherwise the single pair of closest points is the contact.
#include <cmath>

#include "physics/collision/dynamic_tree.h"
#include "physics/collision/gjk.h"
#include "physics/collision/narrow_phase.h"
#include "physics/collision/polytope_contact.h"

namespace pba::collision {
namespace {

// cos of the largest angle between a face normal (or a segment's normal plane) and the contact normal
// for which the feature is treated as lying flat: about 2.6°.
constexpr Real kFlatCosine = 0.999;

struct Feature {
  enum class Kind { Point, Segment, Face } kind = Kind::Point;
  ClipPolygon polygon;  // world points (segment: 2, face: its polygon)
  Vec3 normal{0.0};     // face: outward unit normal (world)
  int id = 0;
};

// The feature of a convex shape that supports it in direction `dir` (unit, world, toward the other shape).
Feature supportingFeature(const Shape& s, const Transform& pose, const Vec3& dir) {
  Feature f;
  if (s.kind == ShapeKind::Capsule) {
    const Vec3 axis = pose.rotate(Vec3(0.0, 1.0, 0.0));
    if (std::abs(glm::dot(axis, dir)) < 1.0 - kFlatCosine * kFlatCosine) {
      f.kind = Feature::Kind::Segment;
      f.polygon.push(pose.position - s.halfHeight * axis, 0);
      f.polygon.push(pose.position + s.halfHeight * axis, 1);
    }
    return f;
  }
  if (s.kind == ShapeKind::Box || s.kind == ShapeKind::Hull) {
    const int face = detail::incidentFace(*s.hull, pose, -dir);  // most aligned with dir
    const Vec3 n = pose.rotate(s.hull->faces[face].normal);
    if (glm::dot(n, dir) > kFlatCosine) {
      f.kind = Feature::Kind::Face;
      f.polygon = detail::facePolygon(*s.hull, pose, face);
      f.normal = n;
      f.id = face;
    }
  }
  return f;
}

Feature triangleFeature(const Vec3 (&tri)[3], const Vec3& dir) {
  Feature f;
  Vec3 n = glm::normalize(glm::cross(tri[1] - tri[0], tri[2] - tri[0]));
  const Real c = glm::dot(n, dir);
  if (std::abs(c) > kFlatCosine) {
    f.kind = Feature::Kind::Face;
    if (c > 0.0) {
      for (int k = 0; k < 3; ++k) f.polygon.push(tri[k], static_cast<std::uint32_t>(k));
    } else {  // the back side: reverse the winding so the polygon stays counter-clockwise about n
      for (int k = 2; k >= 0; --k) f.polygon.push(tri[k], static_cast<std::uint32_t>(k));
      n = -n;
    }
    f.normal = n;
  }
  return f;
}

// Builds the manifold from the signed distance and the two supporting features.
Manifold fromFeatures(const SignedDistance& sd, const Feature& fa, Real ra, const Feature& fb, Real rb, Real margin) {
  using Kind = Feature::Kind;
  Manifold m;
  if (fa.kind == Kind::Face && fb.kind != Kind::Point) {
    m = detail::clipAgainstPolygon(fa.polygon, fa.normal, fb.polygon, rb, false, margin, fa.id, fb.id);
  } else if (fb.kind == Kind::Face && fa.kind != Kind::Point) {
    m = detail::clipAgainstPolygon(fb.polygon, fb.normal, fa.polygon, ra, true, margin, fb.id, fa.id);
  }
  if (m.count > 0) {
    // The pair's normal and separation stay those of GJK/EPA; the clipped points keep their depths
    // along the reference face.
    m.normal = sd.normal;
    m.separation = sd.separation;
    return m;
  }
  m = Manifold{};
  m.normal = sd.normal;
  m.separation = sd.separation;
  m.add(0.5 * (sd.pointA + sd.pointB), sd.separation, 0);
  return m;
}

}  // namespace

Manifold collideConvex(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin) {
  const SignedDistance sd = signedDistance(makeProxy(a), pa, makeProxy(b), pb);
  if (!sd.valid || sd.separation > margin) return {};
  return fromFeatures(sd, supportingFeature(a, pa, sd.normal), a.radius, supportingFeature(b, pb, -sd.normal), b.radius,
                      margin);
}

void collideConvexMesh(const Shape& convex, const Transform& pc, const Shape& mesh, const Transform& pm, Real margin,
                       std::vector<Manifold>& out) {
  const TriangleMesh& tm = *mesh.mesh;
  // Query the triangle tree with the convex shape's AABB in the mesh's frame.
  const Transform local = relative(pm, pc);
  const Aabb box = computeAabb(convex, local).fattened(margin);
  const ConvexProxy proxy = makeProxy(convex);
  tm.tree->query(box, [&](int leaf) {
    const int t = tm.tree->userData(leaf);
    const auto& idx = tm.triangles[t];
    const Vec3 world[3] = {pm.apply(tm.vertices[idx[0]]), pm.apply(tm.vertices[idx[1]]), pm.apply(tm.vertices[idx[2]])};
    const Vec3 front = pm.rotate(tm.normals[t]);
    // One-sided: a shape whose centre is behind the triangle does not collide with it.
    if (glm::dot(front, pc.position - world[0]) < 0.0) return true;
    const ConvexProxy tri = makeTriangleProxy(world[0], world[1], world[2]);
    const SignedDistance sd = signedDistance(proxy, pc, tri, Transform{});
    if (!sd.valid || sd.separation > margin) return true;
    Manifold m = fromFeatures(sd, supportingFeature(convex, pc, sd.normal), convex.radius,
                              triangleFeature(world, -sd.normal), 0.0, margin);
    m.key = static_cast<std::uint32_t>(t);
    if (m.count > 0) out.push_back(m);
    return true;
  });
}

}  // namespace pba::collision
