#include "physics/cloth/tearing.h"

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "physics/cloth/topology.h"

namespace pba::cloth {
namespace {

Real strain(const Cloth& c, const Link& l) {
  return (glm::length(c.position[l.i] - c.position[l.j]) - l.restLength) / l.restLength;
}

/// Splits vertex a by the plane through x_a with normal `pull`; true when both sides had triangles.
bool splitVertex(Cloth& cloth, std::uint32_t a, const Vec3& pull, std::vector<std::vector<std::uint32_t>>& around) {
  std::vector<std::uint32_t> keep, move;
  for (std::uint32_t t : around[a]) {
    const Triangle& tri = cloth.triangles[t];
    const Vec3 centroid = (cloth.position[tri[0]] + cloth.position[tri[1]] + cloth.position[tri[2]]) / 3.0;
    (glm::dot(centroid - cloth.position[a], pull) >= 0.0 ? keep : move).push_back(t);
  }
  if (keep.empty() || move.empty()) return false;
  const auto copy = static_cast<std::uint32_t>(cloth.size());
  cloth.position.push_back(cloth.position[a]);
  cloth.velocity.push_back(cloth.velocity[a]);
  cloth.restPosition.push_back(cloth.restPosition[a]);
  cloth.mass.push_back(0.0);  // rebuildTopology() lumps the masses again
  cloth.inverseMass.push_back(0.0);
  for (std::uint32_t t : move) {
    for (std::uint32_t& v : cloth.triangles[t]) {
      if (v == a) v = copy;
    }
  }
  around[a] = std::move(keep);
  around.push_back(std::move(move));
  return true;
}

}  // namespace

std::size_t tearOverstretched(Cloth& cloth, const TearSettings& settings) {
  if (!settings.enabled) return 0;
  std::vector<std::pair<Real, std::size_t>> strained;
  for (std::size_t k = 0; k < cloth.constraints.size(); ++k) {
    const Real s = strain(cloth, cloth.constraints[k]);
    if (s > settings.threshold) strained.emplace_back(s, k);
  }
  if (strained.empty()) return 0;
  std::sort(strained.begin(), strained.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  std::vector<std::vector<std::uint32_t>> around(cloth.size());
  for (std::uint32_t t = 0; t < cloth.triangles.size(); ++t) {
    for (std::uint32_t v : cloth.triangles[t]) around[v].push_back(t);
  }
  std::size_t splits = 0;
  for (const auto& [s, k] : strained) {
    if (splits >= static_cast<std::size_t>(std::max(0, settings.maxSplitsPerStep))) break;
    const Link l = cloth.constraints[k];
    const Vec3 pull = cloth.position[l.j] - cloth.position[l.i];
    if (splitVertex(cloth, l.i, pull, around) || splitVertex(cloth, l.j, -pull, around)) ++splits;
  }
  if (splits == 0) return 0;
  cloth.torn += splits;
  cloth.layout = SpringLayout::Mesh;
  cloth.gridX = cloth.gridY = 0;
  rebuildTopology(cloth);
  return splits;
}

std::string checkMeshConsistency(const Cloth& c) {
  const std::size_t n = c.size();
  if (c.velocity.size() != n || c.restPosition.size() != n || c.mass.size() != n || c.inverseMass.size() != n) {
    return "particle arrays differ in length";
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const Link& l : c.constraints) {
    if (l.i >= n || l.j >= n || l.i == l.j)
      return "constraint (" + std::to_string(l.i) + ", " + std::to_string(l.j) + ") is invalid";
    edges.emplace(std::min(l.i, l.j), std::max(l.i, l.j));
  }
  for (std::size_t t = 0; t < c.triangles.size(); ++t) {
    const Triangle& tri = c.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
      if (a >= n || a == b) return "triangle " + std::to_string(t) + " names an invalid particle";
      if (!edges.contains({std::min(a, b), std::max(a, b)}))
        return "triangle " + std::to_string(t) + " has an edge without a constraint";
    }
  }
  for (const Link& s : c.springs) {
    if (s.i >= n || s.j >= n) return "a spring names a particle out of range";
  }
  for (const BendingStencil& b : c.bending) {
    for (std::uint32_t v : b.vertex) {
      if (v >= n) return "a bending stencil names a particle out of range";
    }
  }
  for (const Pin& p : c.pins) {
    if (p.particle >= n || c.inverseMass[p.particle] != 0.0) return "a pin is invalid";
  }
  if (edges.size() != c.constraints.size()) return "two constraints on one edge";
  return {};
}

}  // namespace pba::cloth
