// Convex hull construction: incremental hull (Ericson, Real-Time Collision Detection §12.4.2; O'Rourke,
// Computational Geometry in C, ch. 4): start from a tetrahedron of extreme points, add one point at a
// time, delete the triangles it sees and close the hole with a fan from the point to the horizon.
// Then coplanar neighbouring triangles are merged into polygons, which the separating-axis test and the
// contact clipping need (a box has 6 faces and 12 edges, not 12 triangles and 18 edges).
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "physics/collision/shapes.h"
#include "physics/core/format.h"

namespace pba::collision {
namespace {

struct Tri {
  int v[3];
  Vec3 normal;
  Real offset;
};

Tri makeTri(const std::vector<Vec3>& p, int a, int b, int c) {
  Tri t{{a, b, c}, glm::normalize(glm::cross(p[b] - p[a], p[c] - p[a])), 0.0};
  t.offset = glm::dot(t.normal, p[a]);
  return t;
}

// Orders the boundary of a group of triangles (directed edges whose reverse is not in the group)
// into one counter-clockwise loop.
std::vector<int> boundaryLoop(const std::vector<Tri>& tris, const std::vector<int>& group) {
  std::map<std::pair<int, int>, int> directed;
  for (int t : group)
    for (int k = 0; k < 3; ++k) directed[{tris[t].v[k], tris[t].v[(k + 1) % 3]}] = 1;
  std::map<int, int> next;
  for (const auto& [e, unused] : directed)
    if (!directed.count({e.second, e.first})) next[e.first] = e.second;
  std::vector<int> loop;
  if (next.empty()) return loop;
  const int start = next.begin()->first;
  int v = start;
  do {
    loop.push_back(v);
    const auto it = next.find(v);
    if (it == next.end() || loop.size() > next.size()) return {};
    v = it->second;
  } while (v != start);
  return loop;
}

// Drops polygon vertices that lie on the straight line between their neighbours.
std::vector<int> dropCollinear(const std::vector<Vec3>& p, std::vector<int> loop, Real tolerance) {
  bool changed = true;
  while (changed && loop.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Vec3& a = p[loop[(i + loop.size() - 1) % loop.size()]];
      const Vec3& b = p[loop[i]];
      const Vec3& c = p[loop[(i + 1) % loop.size()]];
      if (glm::length(glm::cross(b - a, c - b)) <= tolerance * glm::length(c - a)) {
        loop.erase(loop.begin() + static_cast<long>(i));
        changed = true;
        break;
      }
    }
  }
  return loop;
}

}  // namespace

Result<ConvexHull> buildConvexHull(const std::vector<Vec3>& points, const std::string& field) {
  if (points.size() < 4) return Error{field + ": needs at least 4 points, got " + std::to_string(points.size())};
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!isFinite(points[i])) return Error{field + ".points[" + std::to_string(i) + "]: must be finite"};
  const std::vector<Vec3>& p = points;
  // Scale-aware tolerance: 1e-9 of the point cloud's extent.
  Aabb box;
  for (const Vec3& x : p) box.grow(x);
  const Real scale = std::max(glm::length(box.max - box.min), 1e-300);
  const Real eps = 1e-9 * scale;

  // Initial tetrahedron: the two points farthest apart along x, y or z, the point farthest from their
  // line, the point farthest from their plane.
  int i0 = 0, i1 = 0;
  Real best = -1.0;
  for (int axis = 0; axis < 3; ++axis) {
    int lo = 0, hi = 0;
    for (int i = 0; i < static_cast<int>(p.size()); ++i) {
      if (p[i][axis] < p[lo][axis]) lo = i;
      if (p[i][axis] > p[hi][axis]) hi = i;
    }
    if (p[hi][axis] - p[lo][axis] > best) best = p[hi][axis] - p[lo][axis], i0 = lo, i1 = hi;
  }
  int i2 = -1;
  best = eps;
  for (int i = 0; i < static_cast<int>(p.size()); ++i) {
    const Real d = glm::length(glm::cross(p[i] - p[i0], p[i1] - p[i0])) / std::max(glm::length(p[i1] - p[i0]), 1e-300);
    if (d > best) best = d, i2 = i;
  }
  if (i2 < 0) return Error{field + ": points are collinear (no volume)"};
  const Vec3 n0 = glm::normalize(glm::cross(p[i1] - p[i0], p[i2] - p[i0]));
  int i3 = -1;
  best = eps;
  for (int i = 0; i < static_cast<int>(p.size()); ++i) {
    const Real d = std::abs(glm::dot(n0, p[i] - p[i0]));
    if (d > best) best = d, i3 = i;
  }
  if (i3 < 0) return Error{field + ": points are coplanar (no volume)"};

  std::vector<Tri> tris;
  const Vec3 inside = 0.25 * (p[i0] + p[i1] + p[i2] + p[i3]);
  auto addOutward = [&](int a, int b, int c) {
    Tri t = makeTri(p, a, b, c);
    if (glm::dot(t.normal, inside) > t.offset) t = makeTri(p, a, c, b);
    tris.push_back(t);
  };
  addOutward(i0, i1, i2);
  addOutward(i0, i1, i3);
  addOutward(i0, i2, i3);
  addOutward(i1, i2, i3);

  for (int i = 0; i < static_cast<int>(p.size()); ++i) {
    if (i == i0 || i == i1 || i == i2 || i == i3) continue;
    std::vector<char> visible(tris.size(), 0);
    bool any = false;
    for (std::size_t t = 0; t < tris.size(); ++t) {
      if (glm::dot(tris[t].normal, p[i]) - tris[t].offset > eps) visible[t] = 1, any = true;
    }
    if (!any) continue;  // inside (or on) the current hull
    std::map<std::pair<int, int>, int> visibleEdges;
    for (std::size_t t = 0; t < tris.size(); ++t)
      if (visible[t])
        for (int k = 0; k < 3; ++k) visibleEdges[{tris[t].v[k], tris[t].v[(k + 1) % 3]}] = 1;
    std::vector<Tri> kept;
    for (std::size_t t = 0; t < tris.size(); ++t)
      if (!visible[t]) kept.push_back(tris[t]);
    for (const auto& [e, unused] : visibleEdges)
      if (!visibleEdges.count({e.second, e.first})) kept.push_back(makeTri(p, e.first, e.second, i));  // horizon
    tris.swap(kept);
  }

  // Merge coplanar neighbours: union-find over triangles sharing an edge with the same plane.
  std::vector<int> parent(tris.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::map<std::pair<int, int>, int> edgeOwner;
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) edgeOwner[{tris[t].v[k], tris[t].v[(k + 1) % 3]}] = static_cast<int>(t);
  const Real angleTolerance = 1e-9;
  for (std::size_t t = 0; t < tris.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const auto it = edgeOwner.find({tris[t].v[(k + 1) % 3], tris[t].v[k]});
      if (it == edgeOwner.end()) continue;
      const Tri& o = tris[it->second];
      if (glm::dot(o.normal, tris[t].normal) > 1.0 - angleTolerance &&
          std::abs(o.offset - tris[t].offset) <= 10.0 * eps)
        parent[find(static_cast<int>(t))] = find(it->second);
    }
  }
  std::map<int, std::vector<int>> groups;
  for (std::size_t t = 0; t < tris.size(); ++t) groups[find(static_cast<int>(t))].push_back(static_cast<int>(t));

  ConvexHull hull;
  std::vector<int> remap(p.size(), -1);
  for (const auto& [root, group] : groups) {
    std::vector<int> loop = dropCollinear(p, boundaryLoop(tris, group), 1e-9);
    if (loop.size() < 3) return Error{field + ": degenerate face while merging coplanar triangles"};
    HullFace face;
    for (int v : loop) {
      if (remap[v] < 0) {
        remap[v] = static_cast<int>(hull.vertices.size());
        hull.vertices.push_back(p[v]);
      }
      face.vertices.push_back(remap[v]);
    }
    // Newell's method for a robust polygon normal.
    Vec3 n(0.0), c(0.0);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec3& a = p[loop[k]];
      const Vec3& b = p[loop[(k + 1) % loop.size()]];
      n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
      c += a;
    }
    face.normal = glm::normalize(n);
    face.offset = glm::dot(face.normal, c / static_cast<Real>(loop.size()));
    hull.faces.push_back(std::move(face));
  }
  // Edges with the faces on both sides.
  std::map<std::pair<int, int>, int> faceOfDirected;
  for (std::size_t f = 0; f < hull.faces.size(); ++f) {
    const std::vector<int>& v = hull.faces[f].vertices;
    for (std::size_t k = 0; k < v.size(); ++k) faceOfDirected[{v[k], v[(k + 1) % v.size()]}] = static_cast<int>(f);
  }
  for (const auto& [e, f] : faceOfDirected) {
    if (e.first > e.second) continue;
    const auto other = faceOfDirected.find({e.second, e.first});
    if (other == faceOfDirected.end()) return Error{field + ": hull is not closed (internal error)"};
    hull.edges.push_back({e.first, e.second, f, other->second});
  }
  return hull;
}

ConvexHull boxHull(const Vec3& h) {
  ConvexHull hull;
  for (int i = 0; i < 8; ++i) hull.vertices.emplace_back(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z);
  // Faces ±x, ±y, ±z, counter-clockwise seen from outside.
  const int faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  for (int f = 0; f < 6; ++f) {
    HullFace face;
    face.vertices.assign(faces[f], faces[f] + 4);
    face.normal = Vec3(0.0);
    face.normal[f / 2] = f % 2 == 0 ? 1.0 : -1.0;
    face.offset = h[f / 2];
    hull.faces.push_back(face);
  }
  std::map<std::pair<int, int>, int> faceOfDirected;
  for (int f = 0; f < 6; ++f)
    for (int k = 0; k < 4; ++k) faceOfDirected[{faces[f][k], faces[f][(k + 1) % 4]}] = f;
  for (const auto& [e, f] : faceOfDirected)
    if (e.first < e.second) hull.edges.push_back({e.first, e.second, f, faceOfDirected.at({e.second, e.first})});
  return hull;
}

ConvexHull translated(const ConvexHull& hull, const Vec3& offset) {
  ConvexHull out = hull;
  for (Vec3& v : out.vertices) v += offset;
  for (HullFace& f : out.faces) f.offset += glm::dot(f.normal, offset);
  return out;
}

}  // namespace pba::collision
