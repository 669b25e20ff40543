#include "physics/cloth/topology.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "physics/exercises/not_implemented.h"

namespace pba::cloth {
namespace {

constexpr Real kMinArea = 1e-14;  // [m²] below this a triangle is degenerate

std::string triangleField(std::size_t t) { return "mesh.triangles[" + std::to_string(t) + "]"; }

Real triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * glm::length(glm::cross(b - a, c - a)); }

/// Cotangent of the angle between a and b.
Real cotangent(const Vec3& a, const Vec3& b) {
  const Real sine = glm::length(glm::cross(a, b));
  return sine > 0.0 ? glm::dot(a, b) / sine : 0.0;
}

/// True when grid particles p and q are diagonal neighbours of one quad.
bool isQuadDiagonal(std::uint32_t p, std::uint32_t q, int gridX) {
  if (gridX <= 0) return false;
  const auto nx = static_cast<std::int64_t>(gridX);
  const std::int64_t di = std::abs(static_cast<std::int64_t>(p % nx) - static_cast<std::int64_t>(q % nx));
  const std::int64_t dj = std::abs(static_cast<std::int64_t>(p / nx) - static_cast<std::int64_t>(q / nx));
  return di == 1 && dj == 1;
}

Link makeLink(std::uint32_t i, std::uint32_t j, std::span<const Vec3> rest, LinkKind kind) {
  return Link{i, j, glm::length(rest[i] - rest[j]), kind};
}

}  // namespace

Status validateMesh(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return Error{"mesh.triangles: the mesh has no triangles"};
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!isFinite(mesh.vertices[v])) return Error{"mesh.vertices[" + std::to_string(v) + "]: must be finite"};
  }
  const std::size_t n = mesh.vertices.size();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (std::uint32_t v : tri) {
      if (v >= n)
        return Error{triangleField(t) + ": vertex index " + std::to_string(v) + " out of range (" + std::to_string(n) +
                     " vertices)"};
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) return Error{triangleField(t) + ": repeats a vertex"};
    if (triangleArea(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]) < kMinArea) {
      return Error{triangleField(t) + ": has zero area"};
    }
  }
  // Non-manifold edges: sort (a, b, triangle) and look for three equal (a, b) in a row.
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::size_t>> halfEdges;
  halfEdges.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
      halfEdges.emplace_back(std::min(a, b), std::max(a, b), t);
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end());
  for (std::size_t e = 2; e < halfEdges.size(); ++e) {
    const auto& [a, b, t] = halfEdges[e];
    if (std::get<0>(halfEdges[e - 2]) == a && std::get<1>(halfEdges[e - 2]) == b) {
      return Error{triangleField(t) + ": edge (" + std::to_string(a) + ", " + std::to_string(b) +
                   ") is shared by more than two triangles (non-manifold mesh)"};
    }
  }
  return Status::success();
}

std::vector<Edge> buildEdges(std::span<const Triangle> triangles) {
  struct HalfEdge {
    std::uint32_t a, b, opposite;
    bool operator<(const HalfEdge& o) const { return std::tie(a, b, opposite) < std::tie(o.a, o.b, o.opposite); }
  };
  std::vector<HalfEdge> half;
  half.reserve(3 * triangles.size());
  for (const Triangle& tri : triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri[k], b = tri[(k + 1) % 3], o = tri[(k + 2) % 3];
      half.push_back({std::min(a, b), std::max(a, b), o});
    }
  }
  std::sort(half.begin(), half.end());
  std::vector<Edge> edges;
  edges.reserve(half.size() / 2 + 1);
  for (std::size_t k = 0; k < half.size();) {
    Edge e{half[k].a, half[k].b, half[k].opposite, std::nullopt};
    std::size_t next = k + 1;
    if (next < half.size() && half[next].a == e.a && half[next].b == e.b) {
      e.oppositeB = half[next].opposite;
      ++next;
    }
    while (next < half.size() && half[next].a == e.a && half[next].b == e.b) ++next;  // non-manifold extra
    edges.push_back(e);
    k = next;
  }
  return edges;
}

std::vector<GridLink> gridSpringTopology([[maybe_unused]] int nx, [[maybe_unused]] int ny) {
  // BEGIN SOLUTION
  // Each particle starts the springs to these neighbours (column step, row step, kind).
  struct Step {
    int di, dj;
    LinkKind kind;
  };
  constexpr Step kSteps[] = {{1, 0, LinkKind::Stretch}, {0, 1, LinkKind::Stretch}, {1, 1, LinkKind::Shear},
                             {-1, 1, LinkKind::Shear},  {2, 0, LinkKind::Bend},    {0, 2, LinkKind::Bend}};
  std::vector<GridLink> links;
  const int count = nx > 0 && ny > 0 ? nx * ny : 0;
  for (int p = 0; p < count; ++p) {
    for (const Step& step : kSteps) {
      const int qi = p % nx + step.di, qj = p / nx + step.dj;
      if (qi >= 0 && qi < nx && qj < ny) {
        links.push_back({static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(qj * nx + qi), step.kind});
      }
    }
  }
  return links;
  // END SOLUTION
  // STUB: return exercises::notImplemented("CLOTH-1", std::vector<GridLink>{}, nx, ny);
}

std::vector<Link> acrossEdgeLinks(std::span<const Edge> edges, std::span<const Vec3> rest, int gridX) {
  std::vector<Link> links;
  for (const Edge& e : edges) {
    if (!e.oppositeB) continue;
    const std::uint32_t p = e.oppositeA, q = *e.oppositeB;
    links.push_back(makeLink(p, q, rest, isQuadDiagonal(p, q, gridX) ? LinkKind::Shear : LinkKind::Bend));
  }
  return links;
}

std::vector<Link> meshSprings(std::span<const Edge> edges, std::span<const Vec3> rest, int gridX) {
  std::vector<Link> springs = edgeConstraints(edges, rest, gridX);
  const std::vector<Link> across = acrossEdgeLinks(edges, rest, gridX);
  springs.insert(springs.end(), across.begin(), across.end());
  return springs;
}

std::vector<Link> edgeConstraints(std::span<const Edge> edges, std::span<const Vec3> rest, int gridX) {
  std::vector<Link> links;
  links.reserve(edges.size());
  for (const Edge& e : edges) {
    links.push_back(makeLink(e.a, e.b, rest, isQuadDiagonal(e.a, e.b, gridX) ? LinkKind::Shear : LinkKind::Stretch));
  }
  return links;
}

std::vector<Link> gridSprings(std::span<const GridLink> links, std::span<const Vec3> rest) {
  std::vector<Link> springs;
  springs.reserve(links.size());
  for (const GridLink& l : links) {
    if (l.p >= rest.size() || l.q >= rest.size() || l.p == l.q) continue;  // a wrong exercise answer never crashes
    springs.push_back(makeLink(l.p, l.q, rest, l.kind));
  }
  return springs;
}

std::vector<BendingStencil> bendingStencils(std::span<const Edge> edges, std::span<const Vec3> rest) {
  std::vector<BendingStencil> stencils;
  for (const Edge& e : edges) {
    if (!e.oppositeB) continue;
    // Bergou et al. 2006 §4 with x0, x1 the shared edge and x2, x3 the opposite vertices:
    // e0 = x1 − x0, e1 = x2 − x0, e2 = x3 − x0, e3 = x2 − x1, e4 = x3 − x1.
    const std::array<std::uint32_t, 4> v{e.a, e.b, e.oppositeA, *e.oppositeB};
    const Vec3 e0 = rest[v[1]] - rest[v[0]], e1 = rest[v[2]] - rest[v[0]], e2 = rest[v[3]] - rest[v[0]];
    const Vec3 e3 = rest[v[2]] - rest[v[1]], e4 = rest[v[3]] - rest[v[1]];
    const Real a0 = 0.5 * glm::length(glm::cross(e0, e1)), a1 = 0.5 * glm::length(glm::cross(e0, e2));
    if (a0 < kMinArea || a1 < kMinArea) continue;
    const Real c01 = cotangent(e0, e1), c02 = cotangent(e0, e2), c03 = cotangent(-e0, e3), c04 = cotangent(-e0, e4);
    const Real scale = std::sqrt(3.0 / (a0 + a1));
    const std::array<Real, 4> k{c03 + c04, c01 + c02, -c01 - c03, -c02 - c04};
    BendingStencil s;
    s.vertex = v;
    for (int i = 0; i < 4; ++i) s.weight[i] = scale * k[i];
    stencils.push_back(s);
  }
  return stencils;
}

namespace {
/// Greedy colouring of items by the particles they touch (verticesOf(item) gives them), then a stable
/// sort by colour. Up to 64 colours through one bit mask per particle; items that find none go last.
template <typename Item, typename VerticesOf>
void colourSort(std::vector<Item>& items, std::size_t particles, VerticesOf verticesOf) {
  std::vector<std::uint64_t> used(particles, 0);
  std::vector<std::pair<int, std::size_t>> colour(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    std::uint64_t taken = 0;
    for (std::uint32_t v : verticesOf(items[k])) taken |= used[v];
    int c = 0;
    while (c < 64 && (taken >> c & 1u)) ++c;
    if (c < 64) {
      for (std::uint32_t v : verticesOf(items[k])) used[v] |= std::uint64_t{1} << c;
    }
    colour[k] = {c, k};
  }
  std::stable_sort(colour.begin(), colour.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Item> sorted;
  sorted.reserve(items.size());
  for (const auto& [c, k] : colour) sorted.push_back(items[k]);
  items = std::move(sorted);
}
}  // namespace

void orderByColour(std::vector<Link>& links, std::size_t particles) {
  colourSort(links, particles, [](const Link& l) { return std::array<std::uint32_t, 2>{l.i, l.j}; });
}

void orderByColour(std::vector<BendingStencil>& stencils, std::size_t particles) {
  colourSort(stencils, particles, [](const BendingStencil& s) { return s.vertex; });
}

std::vector<Real> lumpedMasses(std::span<const Triangle> triangles, std::span<const Vec3> rest, Real massPerArea,
                               std::size_t particles) {
  std::vector<Real> mass(particles, 0.0);
  for (const Triangle& t : triangles) {
    const Real third = massPerArea * triangleArea(rest[t[0]], rest[t[1]], rest[t[2]]) / 3.0;
    for (std::uint32_t v : t) mass[v] += third;
  }
  return mass;
}

// Start-up probe: tells the lab whether CLOTH-1 is still a stub.
PBA_EXERCISE_PROBE(gridSpringTopology(2, 2));

}  // namespace pba::cloth
