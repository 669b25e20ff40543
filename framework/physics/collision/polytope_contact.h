#pragma once
// Contact creation between polytope features, shared by the box–box and hull–hull separating-axis
// tests and the general convex path: a reference face clips the incident polygon (Sutherland–Hodgman
// against the reference face's side planes), or two edges give one point.
#include "physics/collision/manifold.h"
#include "physics/collision/shapes.h"

namespace pba::collision::detail {

/// Feature id of a point: which body is the reference (flip), the reference and incident faces, and the
/// clipped vertex (incident vertex index or clip code).
inline std::uint32_t faceContactId(bool flip, int refFace, int incFace, std::uint32_t pointCode) {
  return (flip ? 0x80000000u : 0u) | ((static_cast<std::uint32_t>(refFace) & 0x7Fu) << 24) |
         ((static_cast<std::uint32_t>(incFace) & 0x7Fu) << 17) | (pointCode & 0x1FFFFu);
}
inline std::uint32_t edgeContactId(int edgeA, int edgeB) {
  return 0x40000000u | ((static_cast<std::uint32_t>(edgeA) & 0x7FFFu) << 15) |
         (static_cast<std::uint32_t>(edgeB) & 0x7FFFu);
}

/// The face of `hull` (at `pose`) whose world normal is most anti-parallel to `direction`.
int incidentFace(const ConvexHull& hull, const Transform& pose, const Vec3& direction);

/// Among the faces of `hull` that contain its support vertex along −direction (its deepest point), the
/// one most anti-parallel to `direction`. Unlike the most anti-parallel face overall, it always holds the
/// deepest point, which clipping must keep (hulls with many small faces need this; boxes do not).
int incidentFaceAtSupport(const ConvexHull& hull, const Transform& pose, const Vec3& direction);

/// Face contact: face `refFace` of the reference hull clips the incident polygon (world points with
/// ids, inflated by incidentRadius). Points deeper than margin are kept, at most 4. `flip` says the
/// reference hull is shape B (the manifold normal is then −face normal, so it still points A → B).
Manifold clipAgainstFace(const ConvexHull& ref, const Transform& refPose, int refFace, const ClipPolygon& incident,
                         Real incidentRadius, bool flip, Real margin, int incFaceForIds);

/// The same with a reference polygon given directly (world points, counter-clockwise about its outward
/// normal n): mesh triangles use it.
Manifold clipAgainstPolygon(const ClipPolygon& ref, const Vec3& n, const ClipPolygon& incident, Real incidentRadius,
                            bool flip, Real margin, int refFaceForIds, int incFaceForIds);

/// The incident face of `hull` as a polygon of world points with vertex ids.
ClipPolygon facePolygon(const ConvexHull& hull, const Transform& pose, int face);

/// Edge contact: the closest points of segments [a0, a1] (on A) and [b0, b1] (on B), normal A → B.
Manifold edgeContact(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1, const Vec3& normal, Real margin,
                     std::uint32_t id);

}  // namespace pba::collision::detail
