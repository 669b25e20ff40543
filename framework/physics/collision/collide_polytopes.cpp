// Polytope pairs by the separating axis test (Ericson §4.4 for boxes; Gregorius, "The Separating Axis
// Test between Convex Polyhedra", GDC 2013, for hulls). For convex polytopes the candidate axes are the
// face normals of both and the cross products of edge pairs; the axis of largest separation is the
// minimum translation direction, so its separation equals the penetration depth EPA finds.
//
// Separation along a unit axis L (oriented from A to B) is measured through support points:
//   s(L) = L·(c_B − c_A) − ext_A(L) − ext_B(−L),   ext_X(d) = d·(support_X(d) − c_X),
// i.e. the gap between the extreme points of A along L and of B along −L.
//
// Faces are preferred over edges, and A's faces over B's, unless the other is clearly better (by
// kAxisTolerance): that keeps the chosen feature from flickering between frames (Box2D v3 prefers
// faces the same way in b2CollidePolygons).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "physics/collision/exercises.h"
#include "physics/collision/narrow_phase.h"
#include "physics/collision/polytope_contact.h"

namespace pba::collision {
namespace {

using detail::clipAgainstFace;
using detail::edgeContact;
using detail::facePolygon;
using detail::incidentFace;

constexpr Real kAxisTolerance = 5e-4;  // [m] (a tenth of Box2D's linear slop)

// The largest separations found on each kind of axis, and the faces that gave them.
struct AxisQuery {
  Real sepA, sepB, sepE;
  int faceA, faceB;
};

// The face contact both pair kinds end with when no edge pair wins: the reference face is A's unless B's
// face or an edge is better by more than the tolerance (A's face only within the tolerance of the best
// axis of all: compared with B's face alone, a face of B preferred over the edge and then A's preferred
// over B's could end up twice the tolerance deep); the incident face of the other is clipped against
// it. `pickIncident` chooses that face: over all faces for boxes, among the faces at the support vertex
// for hulls (the same face for a box, found with fewer products).
Manifold faceContact(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin,
                     const AxisQuery& q, int (*pickIncident)(const ConvexHull&, const Transform&, const Vec3&)) {
  const bool flip = std::max(q.sepB, q.sepE) > q.sepA + kAxisTolerance;
  const ConvexHull& ref = flip ? *b.hull : *a.hull;
  const ConvexHull& inc = flip ? *a.hull : *b.hull;
  const Transform& pr = flip ? pb : pa;
  const Transform& pi = flip ? pa : pb;
  const int refFace = flip ? q.faceB : q.faceA;
  const int incFace = pickIncident(inc, pi, pr.rotate(ref.faces[refFace].normal));
  Manifold m = clipAgainstFace(ref, pr, refFace, facePolygon(inc, pi, incFace), 0.0, flip, margin, incFace);
  // A face preferred within the tolerance over the true axis may not hold the deepest point in its
  // prism, and clipping can then leave nothing: the general query still finds the contact.
  if (m.count == 0) return collideConvex(a, pa, b, pb, margin);
  m.separation = flip ? q.sepB : q.sepA;
  return m;
}

}  // namespace

// The fifteen candidate axes of two boxes (Ericson §4.4.1; Gottschalk's OBB test): A's three face
// normals, B's three, and the nine cross products of an edge of A with an edge of B. The gap on each is
// the exercise COLL-2 (collision/exercises.h: obbSeparationOnAxis); parallel edge pairs give no axis
// (the face axes cover them).
Manifold collideBoxes(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin) {
  const Mat3 ra = glm::mat3_cast(pa.rotation), rb = glm::mat3_cast(pb.rotation);
  const Vec3& ha = a.halfExtents;
  const Vec3& hb = b.halfExtents;
  const Vec3 d = pb.position - pa.position;
  const Obb boxA{pa.position, pa.rotation, ha}, boxB{pb.position, pb.rotation, hb};
  Manifold none;
  Real sepA = -std::numeric_limits<Real>::max(), sepB = sepA, sepE = sepA;
  int faceA = 0, faceB = 0, edgeI = 0, edgeJ = 0;
  for (int i = 0; i < 3; ++i) {
    const Real s = obbSeparationOnAxis(boxA, boxB, ra[i]);
    if (s > margin) return none;
    if (s > sepA) sepA = s, faceA = 2 * i + (glm::dot(ra[i], d) >= 0.0 ? 0 : 1);
  }
  for (int j = 0; j < 3; ++j) {
    const Real tb = -glm::dot(rb[j], d);  // along B's axis, toward A
    const Real s = obbSeparationOnAxis(boxA, boxB, rb[j]);
    if (s > margin) return none;
    if (s > sepB) sepB = s, faceB = 2 * j + (tb >= 0.0 ? 0 : 1);
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vec3 edgeCross = glm::cross(ra[i], rb[j]);
      const Real len = glm::length(edgeCross);
      if (len < 1e-6) continue;  // parallel edges: covered by the face axes
      const Real s = obbSeparationOnAxis(boxA, boxB, edgeCross / len);
      if (s > margin) return none;
      if (s > sepE) sepE = s, edgeI = i, edgeJ = j;
    }
  }
  const Real bestFace = std::max(sepA, sepB);
  // Apart but within the margin (a speculative contact): the axis separation is only a lower bound of
  // the distance and the nearest features need not overlap in the face's plane, so the exact distance
  // and closest features come from GJK (Box2D v3's b2CollidePolygons switches to segment distance the
  // same way when the polygons are apart).
  if (std::max(bestFace, sepE) > 0.0) return collideConvex(a, pa, b, pb, margin);
  if (sepE > bestFace + kAxisTolerance) {
    // Edge–edge: the edge of A along axis i nearest B, and the edge of B along j nearest A.
    Vec3 edgeAxis = glm::normalize(glm::cross(ra[edgeI], rb[edgeJ]));
    if (glm::dot(edgeAxis, d) < 0.0) edgeAxis = -edgeAxis;
    Vec3 ca = pa.position, cb = pb.position;
    for (int k = 0; k < 3; ++k) {
      if (k != edgeI) ca += (glm::dot(ra[k], edgeAxis) >= 0.0 ? ha[k] : -ha[k]) * ra[k];
      if (k != edgeJ) cb += (glm::dot(rb[k], -edgeAxis) >= 0.0 ? hb[k] : -hb[k]) * rb[k];
    }
    const Vec3 ea = ha[edgeI] * ra[edgeI], eb = hb[edgeJ] * rb[edgeJ];
    Manifold m = edgeContact(ca - ea, ca + ea, cb - eb, cb + eb, edgeAxis, margin, detail::edgeContactId(edgeI, edgeJ));
    m.separation = sepE;
    return m;
  }
  return faceContact(a, pa, b, pb, margin, {sepA, sepB, sepE, faceA, faceB}, incidentFace);
}

namespace {

// Gregorius (GDC 2013): edges A (faces a, b) and B (faces c, d) build a face of the Minkowski difference
// iff the arcs a–b and (−c)–(−d) cross on the Gauss map. Arguments: a, b, and c = −n_c, d = −n_d.
bool isMinkowskiFace(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 bxa = glm::cross(b, a), dxc = glm::cross(d, c);
  const Real cba = glm::dot(c, bxa), dba = glm::dot(d, bxa), adc = glm::dot(a, dxc), bdc = glm::dot(b, dxc);
  return cba * dba < 0.0 && adc * bdc < 0.0 && cba * bdc > 0.0;
}

void toWorld(const ConvexHull& h, const Transform& pose, WorldHull& out) {
  out.vertices.resize(h.vertices.size());
  out.normals.resize(h.faces.size());
  out.offsets.resize(h.faces.size());
  out.centroid = Vec3(0.0);
  for (std::size_t i = 0; i < h.vertices.size(); ++i) out.centroid += out.vertices[i] = pose.apply(h.vertices[i]);
  out.centroid /= static_cast<Real>(h.vertices.size());
  for (std::size_t f = 0; f < h.faces.size(); ++f) {
    out.normals[f] = pose.rotate(h.faces[f].normal);
    out.offsets[f] = glm::dot(out.normals[f], out.vertices[h.faces[f].vertices[0]]);
  }
}

// Largest separation of B from any face plane of A: n·(B's support along −n) − offset.
Real queryFaces(const WorldHull& a, const WorldHull& b, int& bestFace) {
  Real best = -std::numeric_limits<Real>::max();
  for (std::size_t f = 0; f < a.normals.size(); ++f) {
    Real lowest = std::numeric_limits<Real>::max();
    for (const Vec3& v : b.vertices) lowest = std::min(lowest, glm::dot(a.normals[f], v));
    const Real s = lowest - a.offsets[f];
    if (s > best) best = s, bestFace = static_cast<int>(f);
  }
  return best;
}

}  // namespace

Manifold collidePolytopes(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin,
                          NarrowPhaseScratch& scratch) {
  if (a.kind == ShapeKind::Box && b.kind == ShapeKind::Box) return collideBoxes(a, pa, b, pb, margin);
  WorldHull& wa = scratch.hullA;
  WorldHull& wb = scratch.hullB;
  const ConvexHull& ha = *a.hull;
  const ConvexHull& hb = *b.hull;
  toWorld(ha, pa, wa);
  toWorld(hb, pb, wb);
  Manifold none;
  int faceA = 0, faceB = 0;
  const Real sepA = queryFaces(wa, wb, faceA);
  if (sepA > margin) return none;
  const Real sepB = queryFaces(wb, wa, faceB);
  if (sepB > margin) return none;
  Real sepE = -std::numeric_limits<Real>::max();
  int edgeA = -1, edgeB = -1;
  Vec3 edgeAxis(0.0);
  for (std::size_t i = 0; i < ha.edges.size(); ++i) {
    const HullEdge& ea = ha.edges[i];
    const Vec3 pa0 = wa.vertices[ea.a], da = wa.vertices[ea.b] - pa0;
    const Vec3 &na = wa.normals[ea.faceA], &nb = wa.normals[ea.faceB];
    for (std::size_t j = 0; j < hb.edges.size(); ++j) {
      const HullEdge& eb = hb.edges[j];
      if (!isMinkowskiFace(na, nb, -wb.normals[eb.faceA], -wb.normals[eb.faceB])) continue;
      const Vec3 pb0 = wb.vertices[eb.a], db = wb.vertices[eb.b] - pb0;
      Vec3 l = glm::cross(da, db);
      const Real len = glm::length(l);
      if (len < 1e-6 * glm::length(da) * glm::length(db)) continue;  // parallel: a face axis covers it
      l /= len;
      if (glm::dot(l, pa0 - wa.centroid) < 0.0) l = -l;  // outward from A
      const Real s = glm::dot(l, pb0 - pa0);
      if (s > margin) return none;
      if (s > sepE) sepE = s, edgeA = static_cast<int>(i), edgeB = static_cast<int>(j), edgeAxis = l;
    }
  }
  if (std::max({sepA, sepB, sepE}) > 0.0) return collideConvex(a, pa, b, pb, margin);  // apart: as for boxes
  if (edgeA >= 0 && sepE > std::max(sepA, sepB) + kAxisTolerance) {
    const HullEdge& ea = ha.edges[edgeA];
    const HullEdge& eb = hb.edges[edgeB];
    Manifold m = edgeContact(wa.vertices[ea.a], wa.vertices[ea.b], wb.vertices[eb.a], wb.vertices[eb.b], edgeAxis,
                             margin, detail::edgeContactId(edgeA, edgeB));
    m.separation = sepE;
    return m;
  }
  return faceContact(a, pa, b, pb, margin, {sepA, sepB, sepE, faceA, faceB}, detail::incidentFaceAtSupport);
}

}  // namespace pba::collision
