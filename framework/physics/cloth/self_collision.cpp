#include "physics/cloth/self_collision.h"

#include <algorithm>
#include <cmath>

namespace pba::cloth {

void SelfCollision::update(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness, Real skin) {
  if (thickness != thickness_) list_.invalidate();
  thickness_ = thickness;
  if (!list_.update(x, thickness, skin, hash_) && minDistance_.size() == list_.pairs().size()) return;
  const auto pairs = list_.pairs();
  minDistance_.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [i, j] = pairs[k];
    minDistance_[k] = std::min(thickness, glm::length(rest[i] - rest[j]));
  }
}

SelfCollisionStats SelfCollision::solve(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> w,
                                        Real friction) {
  SelfCollisionStats stats;
  const auto pairs = list_.pairs();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [i, j] = pairs[k];
    const Real wSum = w[i] + w[j];
    if (wSum == 0.0) continue;
    const Vec3 d = x[i] - x[j];
    const Real dist2 = glm::dot(d, d);
    const Real minDist = minDistance_[k];
    if (dist2 >= minDist * minDist || dist2 == 0.0) continue;
    const Real dist = std::sqrt(dist2);
    const Real overlap = minDist - dist;
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
  if (x.empty() || thickness <= 0.0) return 0;
  hash.build(x, thickness);
  std::size_t count = 0;
  for (std::uint32_t i = 0; i < x.size(); ++i) {
    hash.forEachNear(x[i], [&](std::uint32_t j) {
      if (j <= i) return;
      const Real half = 0.5 * std::min(thickness, glm::length(rest[i] - rest[j]));
      const Vec3 d = x[i] - x[j];
      if (glm::dot(d, d) < half * half) ++count;
    });
  }
  return count;
}

}  // namespace pba::cloth
