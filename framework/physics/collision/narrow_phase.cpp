#include "physics/collision/narrow_phase.h"

#include <algorithm>
#include <limits>

namespace pba::collision {

Manifold collideConvexPlane(const Shape& convex, const Transform& pc, const Transform& planePose, Real margin,
                            NarrowPhaseScratch& scratch) {
  // Every core vertex v at signed height s = n·(v − p₀) − r above the plane is a candidate (the
  // deepest points of a polytope on a plane are its vertices); at most 4 are kept.
  const Vec3 n = planePose.rotate(kUp);
  const Vec3& p0 = planePose.position;
  const CoreVertices vertices(convex);  // boxes and hulls: no copy
  std::vector<ManifoldPoint>& candidates = scratch.candidates;
  candidates.clear();
  const Real r = convex.radius;
  Manifold m;
  m.normal = -n;  // from the convex shape (A) toward the plane (B)
  m.separation = std::numeric_limits<Real>::max();
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec3 v = pc.apply(vertices[i]);
    const Real s = glm::dot(n, v - p0) - r;
    m.separation = std::min(m.separation, s);
    if (s <= margin) candidates.push_back({v - (r + 0.5 * s) * n, s, static_cast<std::uint32_t>(i)});
  }
  reduceToFour(candidates.data(), static_cast<int>(candidates.size()), n, m);
  return m;
}

namespace {

void collideOrdered(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin,
                    std::vector<Manifold>& out, NarrowPhaseScratch& scratch) {
  using K = ShapeKind;
  if (b.kind == K::Mesh) {
    if (a.isConvex()) collideConvexMesh(a, pa, b, pb, margin, out);
    return;
  }
  Manifold m;
  if (b.kind == K::Plane) {
    if (a.isConvex()) m = collideConvexPlane(a, pa, pb, margin, scratch);
  } else if (a.kind == K::Sphere && b.kind == K::Sphere) {
    m = collideSpheres(a, pa, b, pb, margin);
  } else if (a.kind == K::Sphere && b.kind == K::Capsule) {
    m = collideSphereCapsule(a, pa, b, pb, margin);
  } else if (a.kind == K::Sphere && b.kind == K::Box) {
    m = collideSphereBox(a, pa, b, pb, margin);
  } else if (a.kind == K::Capsule && b.kind == K::Capsule) {
    m = collideCapsules(a, pa, b, pb, margin);
  } else if ((a.kind == K::Box || a.kind == K::Hull) && (b.kind == K::Box || b.kind == K::Hull)) {
    m = collidePolytopes(a, pa, b, pb, margin, scratch);
  } else {
    m = collideConvex(a, pa, b, pb, margin);
  }
  if (m.count > 0) out.push_back(m);
}

}  // namespace

void collide(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin,
             std::vector<Manifold>& out, NarrowPhaseScratch& scratch) {
  if (static_cast<int>(a.kind) <= static_cast<int>(b.kind)) {
    collideOrdered(a, pa, b, pb, margin, out, scratch);
    return;
  }
  const std::size_t first = out.size();
  collideOrdered(b, pb, a, pa, margin, out, scratch);
  for (std::size_t i = first; i < out.size(); ++i) out[i] = out[i].flipped();
}

}  // namespace pba::collision
