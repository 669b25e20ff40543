#include "physics/collision/polytope_contact.h"

#include <algorithm>
#include <limits>

#include "physics/collision/closest_points.h"

namespace pba::collision::detail {

namespace {
constexpr Real kClipTolerance = 5e-4;  // [m]
}  // namespace

int incidentFace(const ConvexHull& hull, const Transform& pose, const Vec3& direction) {
  const Vec3 local = pose.rotateInverse(direction);
  int best = 0;
  Real bestDot = glm::dot(hull.faces[0].normal, local);
  for (std::size_t f = 1; f < hull.faces.size(); ++f) {
    const Real d = glm::dot(hull.faces[f].normal, local);
    if (d < bestDot) bestDot = d, best = static_cast<int>(f);
  }
  return best;
}

int incidentFaceAtSupport(const ConvexHull& hull, const Transform& pose, const Vec3& direction) {
  const Vec3 local = pose.rotateInverse(direction);
  int deepest = 0;
  for (std::size_t v = 1; v < hull.vertices.size(); ++v)
    if (glm::dot(hull.vertices[v], local) < glm::dot(hull.vertices[deepest], local)) deepest = static_cast<int>(v);
  int best = -1;
  Real bestDot = 2.0;
  for (std::size_t f = 0; f < hull.faces.size(); ++f) {
    const HullFace& face = hull.faces[f];
    if (std::find(face.vertices.begin(), face.vertices.end(), deepest) == face.vertices.end()) continue;
    const Real d = glm::dot(face.normal, local);
    if (d < bestDot) bestDot = d, best = static_cast<int>(f);
  }
  return best >= 0 ? best : incidentFace(hull, pose, direction);
}

ClipPolygon facePolygon(const ConvexHull& hull, const Transform& pose, int face) {
  ClipPolygon poly;
  for (int v : hull.faces[face].vertices) poly.push(pose.apply(hull.vertices[v]), static_cast<std::uint32_t>(v));
  return poly;
}

Manifold clipAgainstFace(const ConvexHull& ref, const Transform& refPose, int refFace, const ClipPolygon& incident,
                         Real incidentRadius, bool flip, Real margin, int incFaceForIds) {
  return clipAgainstPolygon(facePolygon(ref, refPose, refFace), refPose.rotate(ref.faces[refFace].normal), incident,
                            incidentRadius, flip, margin, refFace, incFaceForIds);
}

Manifold clipAgainstPolygon(const ClipPolygon& ref, const Vec3& n, const ClipPolygon& incident, Real incidentRadius,
                            bool flip, Real margin, int refFaceForIds, int incFaceForIds) {
  // Sutherland–Hodgman alternates between two buffers (the polygons hold 64 points: copying or
  // swapping them cost more than the clipping).
  ClipPolygon buffers[2];
  const ClipPolygon* in = &incident;
  // Side planes: through each edge of the reference face, normal cross(edge, n) pointing outward.
  for (int k = 0; k < ref.n && in->n > 0; ++k) {
    const Vec3& v0 = ref.p[k];
    const Vec3& v1 = ref.p[(k + 1) % ref.n];
    const Vec3 side = glm::cross(v1 - v0, n);
    const Real len = glm::length(side);
    if (len <= 0.0) continue;
    // The side planes are moved out by kClipTolerance, so that an incident vertex lying on the reference
    // face's edge (equal boxes stacked exactly) stays a vertex instead of flickering between a vertex and
    // a clipped point from step to step, which would defeat warm starting.
    ClipPolygon& out = in == &buffers[0] ? buffers[1] : buffers[0];
    clipPolygon(*in, side / len, glm::dot(side / len, v0) + kClipTolerance, static_cast<std::uint32_t>(k), out);
    in = &out;
  }
  const ClipPolygon& a = *in;
  const Real offset = glm::dot(n, ref.p[0]);
  const auto separation = [&](int i) { return glm::dot(n, a.p[i]) - offset - incidentRadius; };
  // Midway between the incident surface point and its projection on the reference face.
  const auto candidate = [&](int i, Real s) {
    return ManifoldPoint{a.p[i] - (incidentRadius + 0.5 * s) * n, s,
                         faceContactId(flip, refFaceForIds, incFaceForIds, a.id[i])};
  };
  int count = 0;
  Real deepest = std::numeric_limits<Real>::max();
  for (int i = 0; i < a.n; ++i) {
    const Real s = separation(i);
    deepest = std::min(deepest, s);
    if (!(s > margin)) ++count;
  }
  Manifold m;
  m.normal = flip ? -n : n;
  if (count <= 4) {  // all kept, in order (what reduceToFour does with at most four)
    for (int i = 0; i < a.n; ++i)
      if (const Real s = separation(i); !(s > margin)) m.points[m.count++] = candidate(i, s);
  } else {
    ManifoldPoint candidates[ClipPolygon::kCapacity];
    int kept = 0;
    for (int i = 0; i < a.n; ++i)
      if (const Real s = separation(i); !(s > margin)) candidates[kept++] = candidate(i, s);
    reduceToFour(candidates, kept, n, m);
  }
  m.separation = count ? deepest : 0.0;
  return m;
}

Manifold edgeContact(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1, const Vec3& normal, Real margin,
                     std::uint32_t id) {
  const SegmentPair c = closestPointsSegments(a0, a1, b0, b1);
  Manifold m;
  m.normal = normal;
  m.separation = glm::dot(normal, c.onSecond - c.onFirst);
  if (m.separation <= margin) m.add(0.5 * (c.onFirst + c.onSecond), m.separation, id);
  return m;
}

}  // namespace pba::collision::detail
