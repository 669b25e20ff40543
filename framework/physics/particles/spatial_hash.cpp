#include "physics/particles/spatial_hash.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace pba::particles {

void SpatialHash::build(std::span<const Vec3> positions, Real cellSize) {
  assert(cellSize > 0.0);
  inverseCell_ = 1.0 / cellSize;
  const std::size_t n = positions.size();
  layout_ = HashLayout::forEntries(n);
  const std::size_t table = layout_.buckets;
  // assign/resize reuse the capacity of earlier builds: no allocation once the count has been reached.
  cellStart_.assign(table + 1, 0);
  entries_.resize(n);
  bucketOf_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = positions[i];
    bucketOf_[i] = bucket(static_cast<std::int64_t>(std::floor(p.x * inverseCell_)),
                          static_cast<std::int64_t>(std::floor(p.y * inverseCell_)),
                          static_cast<std::int64_t>(std::floor(p.z * inverseCell_)));
    ++cellStart_[bucketOf_[i] + 1];
  }
  for (std::size_t b = 0; b < table; ++b) cellStart_[b + 1] += cellStart_[b];
  fill_.assign(cellStart_.begin(), cellStart_.end() - 1);
  if (visited_.size() != table) {
    visited_.assign(table, 0u);
    query_ = 0;
  }
  for (std::size_t i = 0; i < n; ++i) entries_[fill_[bucketOf_[i]]++] = static_cast<std::uint32_t>(i);
}

namespace {
// One pair of the sweep: projection split by inverse mass, then the restitution impulse.
inline void resolvePair(Particles& p, std::size_t i, std::size_t j, Real diameter, Real restitution,
                        PairCollisionStats& stats) {
  const Real wi = p.inverseMass[i], wj = p.inverseMass[j];
  if (wi + wj <= 0.0) return;
  const Vec3 d = p.position[i] - p.position[j];
  const Real dist2 = glm::dot(d, d);
  if (dist2 >= diameter * diameter || dist2 <= 0.0) return;
  const Real dist = std::sqrt(dist2);
  const Vec3 n = d / dist;
  const Real depth = diameter - dist;
  stats.deepestPenetration = std::max(stats.deepestPenetration, depth);
  ++stats.contacts;
  p.position[i] += (wi / (wi + wj) * depth) * n;
  p.position[j] -= (wj / (wi + wj) * depth) * n;
  const Real vn = glm::dot(p.velocity[i] - p.velocity[j], n);
  if (vn < 0.0) {
    const Real J = -(1.0 + restitution) * vn / (wi + wj);
    p.velocity[i] += (wi * J) * n;
    p.velocity[j] -= (wj * J) * n;
  }
}
}  // namespace

PairCollisionStats collideParticlePairs(Particles& p, Real radius, Real restitution, SpatialHash& hash) {
  PairCollisionStats stats;
  const Real diameter = 2.0 * radius;
  hash.build(p.position, diameter);
  for (std::size_t i = 0; i < p.size(); ++i) {
    hash.forEachNear(p.position[i], [&](std::uint32_t j) {
      if (j > i) resolvePair(p, i, j, diameter, restitution, stats);
    });
  }
  return stats;
}

PairCollisionStats collideParticlePairs(Particles& p, Real radius, Real restitution,
                                        std::span<const NeighbourList::Pair> pairs) {
  PairCollisionStats stats;
  const Real diameter = 2.0 * radius;
  for (const auto& [i, j] : pairs) resolvePair(p, i, j, diameter, restitution, stats);
  return stats;
}

bool NeighbourList::update(std::span<const Vec3> positions, Real contactDistance, Real skin, SpatialHash& hash) {
  assert(contactDistance > 0.0 && skin > 0.0);
  bool fresh = valid_ && builtAt_.size() == positions.size() && contactDistance == contactDistance_ && skin == skin_;
  const Real limit2 = 0.25 * skin * skin;  // (skin/2)²
  for (std::size_t i = 0; fresh && i < positions.size(); ++i) {
    const Vec3 moved = positions[i] - builtAt_[i];
    fresh = glm::dot(moved, moved) <= limit2;  // false for NaN too: rebuild, never trust a stale list
  }
  if (fresh) return false;
  const Real reach = contactDistance + skin;
  hash.build(positions, reach);
  pairs_.clear();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    hash.forEachNear(positions[i], [&](std::uint32_t j) {
      if (j <= i) return;
      const Vec3 d = positions[i] - positions[j];
      if (glm::dot(d, d) < reach * reach) pairs_.emplace_back(static_cast<std::uint32_t>(i), j);
    });
  }
  builtAt_.assign(positions.begin(), positions.end());
  contactDistance_ = contactDistance;
  skin_ = skin;
  valid_ = true;
  ++builds_;
  return true;
}

}  // namespace pba::particles
