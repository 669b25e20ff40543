#include "physics/collision/gjk.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <utility>
#include <vector>

#include "physics/collision/closest_points.h"

namespace pba::collision {

ConvexProxy makeProxy(const Shape& shape) {
  ConvexProxy p;
  p.radius = coreRadius(shape);
  switch (shape.kind) {
    case ShapeKind::Sphere:
      p.count = 1;
      p.inlinePoints[0] = Vec3(0.0);
      break;
    case ShapeKind::Capsule:
      p.count = 2;
      p.inlinePoints[0] = Vec3(0.0, -shape.halfHeight, 0.0);
      p.inlinePoints[1] = Vec3(0.0, shape.halfHeight, 0.0);
      break;
    case ShapeKind::Box:
    case ShapeKind::Hull:
      p.external = shape.hull->vertices.data();
      p.count = static_cast<int>(shape.hull->vertices.size());
      break;
    case ShapeKind::Plane:
    case ShapeKind::Mesh:
      break;
  }
  return p;
}

ConvexProxy makeTriangleProxy(const Vec3& a, const Vec3& b, const Vec3& c, Real radius) {
  ConvexProxy p;
  p.inlinePoints = {a, b, c};
  p.count = 3;
  p.radius = radius;
  return p;
}

namespace {

int supportIndex(const ConvexProxy& p, const Vec3& d) {
  const Vec3* v = p.points();
  int best = 0;
  Real bestDot = glm::dot(v[0], d);
  for (int i = 1; i < p.count; ++i) {
    const Real dd = glm::dot(v[i], d);
    if (dd > bestDot) bestDot = dd, best = i;
  }
  return best;
}

struct Support {
  const ConvexProxy& a;
  const Transform& poseA;
  const ConvexProxy& b;
  const Transform& poseB;
  SimplexVertex operator()(const Vec3& d) const {
    SimplexVertex v;
    v.indexA = supportIndex(a, poseA.rotateInverse(d));
    v.indexB = supportIndex(b, poseB.rotateInverse(-d));
    v.a = poseA.apply(a.points()[v.indexA]);
    v.b = poseB.apply(b.points()[v.indexB]);
    v.w = v.a - v.b;
    return v;
  }
};

// A simplex with the barycentric weights of its point closest to the origin.
struct Simplex {
  std::array<SimplexVertex, 4> v{};
  std::array<Real, 4> lambda{};
  int count = 0;
  Vec3 point() const {
    Vec3 p(0.0);
    for (int i = 0; i < count; ++i) p += lambda[i] * v[i].w;
    return p;
  }
};

Simplex sub(const Simplex& s, std::initializer_list<int> keep) {
  Simplex r;
  for (int i : keep) r.v[r.count++] = s.v[i];
  return r;
}

// Johnson's sub-algorithm by Voronoi regions (Ericson §9.5.2): reduce the simplex to the face, edge or
// vertex nearest the origin and find the barycentric weights of the nearest point.
void solveSegment(Simplex& s) {
  const Vec3 e = s.v[1].w - s.v[0].w;
  const Real ee = glm::dot(e, e);
  const Real t = ee > 0.0 ? -glm::dot(s.v[0].w, e) / ee : 0.0;
  if (t <= 0.0) {
    s.count = 1;
    s.lambda[0] = 1.0;
  } else if (t >= 1.0) {
    s.v[0] = s.v[1];
    s.count = 1;
    s.lambda[0] = 1.0;
  } else {
    s.lambda[0] = 1.0 - t;
    s.lambda[1] = t;
  }
}

void solveTriangle(Simplex& s) {
  int region = 6;
  closestPointOnTriangle(Vec3(0.0), s.v[0].w, s.v[1].w, s.v[2].w, &region);
  switch (region) {
    case 0:
      s = sub(s, {0});
      s.lambda[0] = 1.0;
      return;
    case 1:
      s = sub(s, {1});
      s.lambda[0] = 1.0;
      return;
    case 2:
      s = sub(s, {2});
      s.lambda[0] = 1.0;
      return;
    case 3:
      s = sub(s, {0, 1});
      solveSegment(s);
      return;
    case 4:
      s = sub(s, {1, 2});
      solveSegment(s);
      return;
    case 5:
      s = sub(s, {2, 0});
      solveSegment(s);
      return;
    default:
      break;
  }
  // Face: barycentric coordinates of the origin's projection (Cramer's rule).
  const Vec3 v0 = s.v[1].w - s.v[0].w, v1 = s.v[2].w - s.v[0].w, v2 = -s.v[0].w;
  const Real d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
  const Real d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1);
  const Real denom = d00 * d11 - d01 * d01;
  if (!(denom > 0.0)) {  // degenerate triangle: fall back to its longest edge
    s = sub(s, {0, 1});
    solveSegment(s);
    return;
  }
  const Real b1 = (d11 * d20 - d01 * d21) / denom, b2 = (d00 * d21 - d01 * d20) / denom;
  s.lambda[0] = 1.0 - b1 - b2;
  s.lambda[1] = b1;
  s.lambda[2] = b2;
}

// Returns false when the origin is inside the tetrahedron (the cores overlap).
bool solveTetrahedron(Simplex& s) {
  static const int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};  // a, b, c, opposite
  Real bestDistance = std::numeric_limits<Real>::max();
  Simplex best;
  bool outsideAny = false;
  for (const auto& f : faces) {
    const Vec3& a = s.v[f[0]].w;
    const Vec3 n = glm::cross(s.v[f[1]].w - a, s.v[f[2]].w - a);
    const Real signOrigin = glm::dot(-a, n);
    const Real signOpposite = glm::dot(s.v[f[3]].w - a, n);
    const bool flat = std::abs(signOpposite) <= 1e-14 * glm::length(n) * (glm::length(a) + 1e-300);
    if (!(signOrigin * signOpposite < 0.0) && !flat) continue;
    outsideAny = true;
    Simplex t = sub(s, {f[0], f[1], f[2]});
    solveTriangle(t);
    const Vec3 p = t.point();
    const Real d = glm::dot(p, p);
    if (d < bestDistance) bestDistance = d, best = t;
  }
  if (!outsideAny) return false;
  s = best;
  return true;
}

}  // namespace

DistanceResult gjkDistance(const ConvexProxy& a, const Transform& poseA, const ConvexProxy& b, const Transform& poseB) {
  const Support support{a, poseA, b, poseB};
  DistanceResult out;
  Simplex s;
  Vec3 d = poseB.position - poseA.position;
  if (glm::dot(d, d) == 0.0) d = Vec3(1.0, 0.0, 0.0);
  s.v[0] = support(-d);
  s.lambda[0] = 1.0;
  s.count = 1;
  Real previous = std::numeric_limits<Real>::max();
  constexpr int kMaxIterations = 64;
  for (out.iterations = 0; out.iterations < kMaxIterations; ++out.iterations) {
    if (s.count == 2)
      solveSegment(s);
    else if (s.count == 3)
      solveTriangle(s);
    else if (s.count == 4 && !solveTetrahedron(s)) {
      out.overlap = true;
      break;
    }
    const Vec3 v = s.point();
    const Real vv = glm::dot(v, v);
    const Real scale = glm::dot(s.v[0].w, s.v[0].w) + 1e-300;
    if (vv <= 1e-24 * scale) {
      out.overlap = true;  // touching (the origin is on the simplex)
      break;
    }
    if (vv >= previous) break;  // no more progress (rounding)
    previous = vv;
    const SimplexVertex w = support(-v);
    bool duplicate = false;
    for (int i = 0; i < s.count; ++i) duplicate |= s.v[i].indexA == w.indexA && s.v[i].indexB == w.indexB;
    // van den Bergen's stopping rule: |v|² − v·w ≤ ε|v|² bounds the relative error of the distance.
    if (duplicate || vv - glm::dot(v, w.w) <= 1e-13 * vv) break;
    s.v[s.count] = w;
    s.lambda[s.count] = 0.0;
    ++s.count;
  }
  out.simplexCount = s.count;
  for (int i = 0; i < s.count; ++i) out.simplex[i] = s.v[i];
  if (out.overlap) {
    Vec3 p(0.0);
    Real total = 0.0;
    for (int i = 0; i < s.count; ++i) p += s.lambda[i] * s.v[i].a, total += s.lambda[i];
    out.pointA = out.pointB = s.count == 4 || total <= 0.0 ? s.v[0].a : p;
    out.distance = 0.0;
    return out;
  }
  for (int i = 0; i < s.count; ++i) {
    out.pointA += s.lambda[i] * s.v[i].a;
    out.pointB += s.lambda[i] * s.v[i].b;
  }
  out.distance = glm::length(out.pointA - out.pointB);
  return out;
}

namespace {

struct EpaFace {
  int v[3];
  Vec3 normal;
  Real distance;
  bool alive = true;
};

EpaFace makeFace(const std::vector<SimplexVertex>& verts, int i, int j, int k) {
  EpaFace f{{i, j, k}, glm::cross(verts[j].w - verts[i].w, verts[k].w - verts[i].w), 0.0};
  const Real l = glm::length(f.normal);
  f.normal = l > 0.0 ? f.normal / l : Vec3(0.0, 1.0, 0.0);
  f.distance = glm::dot(f.normal, verts[i].w);
  if (l <= 0.0) f.distance = std::numeric_limits<Real>::max();  // degenerate: never chosen
  return f;
}

// Grows a GJK terminal simplex of 1–3 vertices (the origin on a vertex, edge or face) to a tetrahedron.
bool growToTetrahedron(std::vector<SimplexVertex>& verts, const Support& support, Real eps) {
  auto addIf = [&](const Vec3& dir, auto&& accept) {
    for (const Vec3& d : {dir, -dir}) {
      const SimplexVertex w = support(d);
      if (accept(w.w)) {
        verts.push_back(w);
        return true;
      }
    }
    return false;
  };
  const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  if (verts.size() == 1) {
    bool ok = false;
    for (const Vec3& d : axes)
      if (!ok) ok = addIf(d, [&](const Vec3& w) { return glm::length(w - verts[0].w) > eps; });
    if (!ok) return false;
  }
  if (verts.size() == 2) {
    const Vec3 e = glm::normalize(verts[1].w - verts[0].w);
    const Vec3 ae = glm::abs(e);
    const Vec3 axis = ae.x < ae.y ? (ae.x < ae.z ? axes[0] : axes[2]) : (ae.y < ae.z ? axes[1] : axes[2]);
    const Vec3 p1 = glm::normalize(glm::cross(e, axis));
    const Vec3 p2 = glm::cross(e, p1);
    auto offLine = [&](const Vec3& w) { return glm::length(glm::cross(w - verts[0].w, e)) > eps; };
    if (!addIf(p1, offLine) && !addIf(p2, offLine)) return false;
  }
  if (verts.size() == 3) {
    const Vec3 n = glm::normalize(glm::cross(verts[1].w - verts[0].w, verts[2].w - verts[0].w));
    if (!addIf(n, [&](const Vec3& w) { return std::abs(glm::dot(n, w - verts[0].w)) > eps; })) return false;
  }
  return verts.size() == 4;
}

}  // namespace

PenetrationResult epaPenetration(const ConvexProxy& a, const Transform& poseA, const ConvexProxy& b,
                                 const Transform& poseB, const DistanceResult& gjk) {
  const Support support{a, poseA, b, poseB};
  PenetrationResult out;
  std::vector<SimplexVertex> verts(gjk.simplex.begin(), gjk.simplex.begin() + std::max(1, gjk.simplexCount));
  Real scale = 0.0;
  for (const SimplexVertex& v : verts) scale = std::max(scale, glm::length(v.w));
  const SimplexVertex far = support(Vec3(1.0, 0.3, 0.2));
  scale = std::max({scale, glm::length(far.w), 1e-12});
  const Real eps = 1e-10 * scale;
  if (!growToTetrahedron(verts, support, eps)) return out;

  std::vector<EpaFace> faces;
  const Vec3 inside = 0.25 * (verts[0].w + verts[1].w + verts[2].w + verts[3].w);
  const int tet[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  for (const auto& t : tet) {
    EpaFace f = makeFace(verts, t[0], t[1], t[2]);
    if (glm::dot(f.normal, verts[t[0]].w - inside) < 0.0) f = makeFace(verts, t[0], t[2], t[1]);
    faces.push_back(f);
  }
  constexpr int kMaxIterations = 128;
  // Each iteration adds at most the horizon's edges as faces; on degenerate input (nearly coplanar
  // faces, or bodies far outside any sensible range) the horizon can take most of the polytope, and the
  // horizon search is quadratic in it. Past this many faces the best face so far is the answer (Bullet's
  // EPA bounds its faces the same way).
  constexpr std::size_t kMaxFaces = 1024;
  int bestFace = -1;
  std::vector<std::pair<int, int>> edges;
  for (out.iterations = 0; out.iterations < kMaxIterations; ++out.iterations) {
    bestFace = -1;
    for (std::size_t i = 0; i < faces.size(); ++i)
      if (faces[i].alive && (bestFace < 0 || faces[i].distance < faces[bestFace].distance))
        bestFace = static_cast<int>(i);
    if (bestFace < 0) return out;
    const EpaFace face = faces[bestFace];
    const SimplexVertex w = support(face.normal);
    // A support point that is not finite (a body's pose already NaN or ±∞): no penetration to report.
    if (!std::isfinite(glm::dot(w.w, w.w))) return PenetrationResult{};
    if (glm::dot(face.normal, w.w) - face.distance <= eps) break;  // the face is on the boundary of A − B
    if (faces.size() >= kMaxFaces) break;
    const int index = static_cast<int>(verts.size());
    verts.push_back(w);
    // Remove every face w can see; the boundary of the hole (edges not shared by two removed faces,
    // in the removed faces' order) is the horizon, fanned to w.
    edges.clear();
    for (EpaFace& f : faces) {
      if (!f.alive || glm::dot(f.normal, w.w - verts[f.v[0]].w) <= 0.0) continue;
      f.alive = false;
      for (int k = 0; k < 3; ++k) {
        const std::pair<int, int> e{f.v[k], f.v[(k + 1) % 3]};
        const auto reverse = std::find(edges.begin(), edges.end(), std::make_pair(e.second, e.first));
        if (reverse != edges.end())
          edges.erase(reverse);
        else
          edges.push_back(e);
      }
    }
    for (const auto& [i, j] : edges) faces.push_back(makeFace(verts, i, j, index));
  }
  if (bestFace < 0) return out;
  const EpaFace& f = faces[bestFace];
  out.valid = true;
  out.normal = f.normal;
  out.depth = std::max(0.0, f.distance);
  // Barycentric coordinates of the origin's projection onto the face give the deepest points.
  const Vec3 p = f.distance * f.normal;
  const Vec3 &w0 = verts[f.v[0]].w, &w1 = verts[f.v[1]].w, &w2 = verts[f.v[2]].w;
  const Vec3 v0 = w1 - w0, v1 = w2 - w0, v2 = p - w0;
  const Real d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
  const Real d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1);
  const Real denom = d00 * d11 - d01 * d01;
  const Real l1 = denom > 0.0 ? (d11 * d20 - d01 * d21) / denom : 0.0;
  const Real l2 = denom > 0.0 ? (d00 * d21 - d01 * d20) / denom : 0.0;
  const Real l0 = 1.0 - l1 - l2;
  out.pointA = l0 * verts[f.v[0]].a + l1 * verts[f.v[1]].a + l2 * verts[f.v[2]].a;
  out.pointB = l0 * verts[f.v[0]].b + l1 * verts[f.v[1]].b + l2 * verts[f.v[2]].b;
  return out;
}

SignedDistance signedDistance(const ConvexProxy& a, const Transform& poseA, const ConvexProxy& b,
                              const Transform& poseB) {
  SignedDistance out;
  const DistanceResult g = gjkDistance(a, poseA, b, poseB);
  const Real radii = a.radius + b.radius;
  if (!g.overlap && g.distance > 1e-12) {
    out.normal = (g.pointB - g.pointA) / g.distance;
    out.separation = g.distance - radii;
    out.pointA = g.pointA + a.radius * out.normal;
    out.pointB = g.pointB - b.radius * out.normal;
    return out;
  }
  const PenetrationResult e = epaPenetration(a, poseA, b, poseB, g);
  if (!e.valid) {
    out.valid = false;
    out.separation = -radii;
    return out;
  }
  out.normal = e.normal;
  out.separation = -e.depth - radii;
  out.pointA = e.pointA + a.radius * out.normal;
  out.pointB = e.pointB - b.radius * out.normal;
  return out;
}

}  // namespace pba::collision
