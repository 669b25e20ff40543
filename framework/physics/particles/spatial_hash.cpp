#include "physics/particles/spatial_hash.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace pba::particles {

void SpatialHash::build(std::span<const Vec3> positions, Real cellSize) {
  assert(cellSize > 0.0);
  inverseCell_ = 1.0 / cellSize;
  const std::size_t n = positions.size();
  std::size_t table = 64;  // power of two, load factor ≤ ½
  shift_ = 58;
  while (table < 2 * n) {
    table *= 2;
    --shift_;
  }
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
  for (std::size_t i = 0; i < n; ++i) entries_[fill_[bucketOf_[i]]++] = static_cast<std::uint32_t>(i);
}

PairCollisionStats collideParticlePairs(Particles& p, Real radius, Real restitution, SpatialHash& hash) {
  PairCollisionStats stats;
  const Real diameter = 2.0 * radius;
  hash.build(p.position, diameter);
  for (std::size_t i = 0; i < p.size(); ++i) {
    hash.forEachNear(p.position[i], [&](std::uint32_t j) {
      if (j <= i) return;
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
    });
  }
  return stats;
}

}  // namespace pba::particles
