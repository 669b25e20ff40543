#include "physics/cloth/self_collision.h"

#include <algorithm>
#include <cmath>

namespace pba::cloth {
namespace {
bool neighbours(const Vec3& restI, const Vec3& restJ, Real thickness) {
  const Real limit = kSelfNeighbourFactor * thickness;
  const Vec3 d = restI - restJ;
  return glm::dot(d, d) < limit * limit;
}
}  // namespace

void SelfCollision::buildPairs(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness, Real reach) {
  pairs_.clear();
  if (x.empty() || !(thickness > 0.0)) return;
  reach = std::max(reach, thickness);
  hash_.build(x, reach);
  const Real reach2 = reach * reach;
  for (std::uint32_t i = 0; i < x.size(); ++i) {
    hash_.forEachNear(x[i], [&](std::uint32_t j) {
      if (j <= i || neighbours(rest[i], rest[j], thickness)) return;
      const Vec3 d = x[i] - x[j];
      if (glm::dot(d, d) < reach2) pairs_.emplace_back(i, j);
    });
  }
}

SelfCollisionStats SelfCollision::solve(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> w,
                                        Real thickness, Real friction) const {
  SelfCollisionStats stats;
  const Real thickness2 = thickness * thickness;
  for (const auto& [i, j] : pairs_) {
    const Vec3 d = x[i] - x[j];
    const Real dist2 = glm::dot(d, d);
    if (dist2 >= thickness2 || dist2 == 0.0) continue;
    const Real wSum = w[i] + w[j];
    if (wSum == 0.0) continue;
    const Real dist = std::sqrt(dist2);
    const Real overlap = thickness - dist;
    stats.deepest = std::max(stats.deepest, overlap);
    ++stats.contacts;
    const Vec3 correction = (overlap / dist) * d;
    x[i] += (w[i] / wSum) * correction;
    x[j] -= (w[j] / wSum) * correction;
    // Friction: both move toward their mean displacement over the substep.
    const Vec3 di = x[i] - xPrev[i], dj = x[j] - xPrev[j];
    const Vec3 mean = 0.5 * (di + dj);
    if (w[i] > 0.0) x[i] += friction * (mean - di);
    if (w[j] > 0.0) x[j] += friction * (mean - dj);
  }
  return stats;
}

std::size_t countSelfIntersections(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness,
                                   particles::SpatialHash& hash) {
  if (x.empty() || !(thickness > 0.0)) return 0;
  hash.build(x, thickness);
  const Real half2 = 0.25 * thickness * thickness;
  std::size_t count = 0;
  for (std::uint32_t i = 0; i < x.size(); ++i) {
    hash.forEachNear(x[i], [&](std::uint32_t j) {
      if (j <= i || neighbours(rest[i], rest[j], thickness)) return;
      const Vec3 d = x[i] - x[j];
      if (glm::dot(d, d) < half2) ++count;
    });
  }
  return count;
}

}  // namespace pba::cloth
