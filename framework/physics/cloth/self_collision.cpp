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

Real distance2(const Vec3& a, const Vec3& b) {
  const Vec3 d = a - b;
  return glm::dot(d, d);
}

/// |v|₁ ≥ |v|: a bound of a displacement without a square root.
Real taxicab(const Vec3& v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }
}  // namespace

bool SelfCollision::inFrame(std::uint32_t i, std::uint32_t j) const {
  return distance2(start_[i], start_[j]) < reach_ * reach_ && !neighbours(rest_[i], rest_[j], thickness_);
}

bool SelfCollision::pathsMeet(std::uint32_t i, std::uint32_t j) const {
  // Closest approach of r(τ) = r₀ + u τ over τ ∈ [0, dt]: τ* = −r₀·u / u·u, clamped.
  const Vec3 r0 = start_[i] - start_[j];
  const Vec3 u = velocity_[i] - velocity_[j];
  const Real uu = glm::dot(u, u);
  const Real tau = uu > 0.0 ? std::clamp(-glm::dot(r0, u) / uu, 0.0, dt_) : 0.0;
  const Vec3 r = r0 + tau * u;
  const Real meet = thickness_ + 2.0 * skin_;
  return glm::dot(r, r) < meet * meet;
}

void SelfCollision::buildWideGrid() {
  if (wideBuilt_) return;
  wide_.build(start_, {}, reach_);
  wideBuilt_ = true;
}

void SelfCollision::collectSlowPairs(std::span<const std::uint32_t> slow) {
  // Two slow particles close in by at most 2 s in the frame: paths that meet start within thickness + 4 s
  // (half a skin more: no round-off can lose one).
  const Real cell = std::min(reach_, thickness_ + 4.5 * skin_);
  narrow_.build(start_, slow, cell);
  const Real cell2 = cell * cell;
  for (std::uint32_t e = 0; e < narrow_.particle.size(); ++e) {
    const std::uint32_t i = narrow_.particle[e];
    const Vec3 p = narrow_.position[e];
    const std::uint32_t own = narrow_.bucketOfEntry(e);
    narrow_.forEachNearBucket(p, [&](std::uint32_t b, std::uint32_t first, std::uint32_t last) {
      if (b < own) return;  // visited from the other side
      for (std::uint32_t f = b == own ? e + 1 : first; f < last; ++f) {
        if (distance2(p, narrow_.position[f]) >= cell2) continue;
        const std::uint32_t j = narrow_.particle[f];
        if (inFrame(i, j) && pathsMeet(i, j)) pairs_.emplace_back(std::min(i, j), std::max(i, j));
      }
    });
  }
}

void SelfCollision::collectFastPairs(std::span<const std::uint32_t> fast) {
  // Every pair with a fast particle, found from the fast one (from the smaller index when both are).
  buildWideGrid();
  const Real reach2 = reach_ * reach_;
  for (std::uint32_t i : fast) {
    const Vec3 p = start_[i];
    wide_.forEachNearBucket(p, [&](std::uint32_t, std::uint32_t first, std::uint32_t last) {
      for (std::uint32_t f = first; f < last; ++f) {
        if (distance2(p, wide_.position[f]) >= reach2) continue;
        const std::uint32_t j = wide_.particle[f];
        if (j == i || (fast_[j] && j < i) || neighbours(rest_[i], rest_[j], thickness_)) continue;
        if (!tracked_[i] || !tracked_[j] || pathsMeet(i, j)) pairs_.emplace_back(std::min(i, j), std::max(i, j));
      }
    });
  }
}

void SelfCollision::buildPairs(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness, Real reach,
                               std::span<const Vec3> v, Real dt) {
  pairs_.clear();
  promotions_ = 0;
  wideBuilt_ = false;
  anyTracked_ = false;
  start_.assign(x.begin(), x.end());
  rest_.assign(rest.begin(), rest.end());
  thickness_ = thickness;
  if (x.empty() || !(thickness > 0.0)) return;
  const auto n = static_cast<std::uint32_t>(x.size());
  reach_ = std::max(reach, thickness);
  skin_ = kSelfSkinFactor * thickness;
  dt_ = std::max(dt, 0.0);
  // Tracking gains nothing when the meeting distance reaches the reach: then every particle is untracked.
  anyTracked_ = v.size() == n && thickness + 2.0 * skin_ < reach_;
  tracked_.assign(n, anyTracked_ ? 1 : 0);
  velocity_.assign(n, Vec3(0.0));
  if (anyTracked_) velocity_.assign(v.begin(), v.end());
  strayed_.assign(n, 0.0);
  moved_.assign(n, 0.0);
  fast_.assign(n, 1);
  slow_.clear();
  fastList_.clear();
  for (std::uint32_t i = 0; i < n; ++i) {
    fast_[i] = !anyTracked_ || glm::length(velocity_[i]) * dt_ > skin_ ? 1 : 0;
    (fast_[i] ? fastList_ : slow_).push_back(i);
  }
  if (!slow_.empty()) collectSlowPairs(slow_);
  if (!fastList_.empty()) collectFastPairs(fastList_);
  sortPairs(pairs_);
}

void SelfCollision::sortPairs(std::vector<Pair>& pairs) {
  const std::size_t n = start_.size();
  rowCount_.assign(n + 1, 0);
  for (const Pair& p : pairs) ++rowCount_[p.first + 1];
  for (std::size_t i = 0; i < n; ++i) rowCount_[i + 1] += rowCount_[i];
  scratch_.resize(pairs.size());
  for (const Pair& p : pairs) scratch_[rowCount_[p.first]++] = p;
  // rowCount_[i] is now the end of row i, the start of row i + 1.
  std::size_t begin = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t end = rowCount_[i];
    if (end - begin > 1) {
      std::sort(scratch_.begin() + static_cast<std::ptrdiff_t>(begin),
                scratch_.begin() + static_cast<std::ptrdiff_t>(end));
    }
    begin = end;
  }
  pairs.swap(scratch_);
}

void SelfCollision::promote(std::span<const std::uint32_t> particles) {
  buildWideGrid();
  // A pair of F of a tracked particle k is in the list already when its partner is untracked or when their
  // paths meet; the others join. tracked_ changes only after the whole batch, so a pair of two untracked
  // particles is found twice and kept once.
  scratch_.clear();
  const Real reach2 = reach_ * reach_;
  for (std::uint32_t k : particles) {
    if (!tracked_[k]) continue;
    const Vec3 p = start_[k];
    wide_.forEachNearBucket(p, [&](std::uint32_t, std::uint32_t first, std::uint32_t last) {
      for (std::uint32_t f = first; f < last; ++f) {
        if (distance2(p, wide_.position[f]) >= reach2) continue;
        const std::uint32_t j = wide_.particle[f];
        if (j == k || !tracked_[j] || neighbours(rest_[k], rest_[j], thickness_) || pathsMeet(k, j)) continue;
        scratch_.emplace_back(std::min(k, j), std::max(k, j));
      }
    });
  }
  for (std::uint32_t k : particles) {
    if (tracked_[k]) ++promotions_;
    tracked_[k] = 0;
  }
  std::sort(scratch_.begin(), scratch_.end());
  scratch_.erase(std::unique(scratch_.begin(), scratch_.end()), scratch_.end());
  merged_.resize(pairs_.size() + scratch_.size());
  std::merge(pairs_.begin(), pairs_.end(), scratch_.begin(), scratch_.end(), merged_.begin());
  pairs_.swap(merged_);
}

SelfCollisionStats SelfCollision::sweep(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> w,
                                        Real friction, bool track) {
  SelfCollisionStats stats;
  const Real thickness2 = thickness_ * thickness_;
  for (const auto& [i, j] : pairs_) {
    const Vec3 d = x[i] - x[j];
    const Real dist2 = glm::dot(d, d);
    if (dist2 >= thickness2 || dist2 == 0.0) continue;
    const Real wSum = w[i] + w[j];
    if (wSum == 0.0) continue;
    const Vec3 oldI = x[i], oldJ = x[j];
    const Real dist = std::sqrt(dist2);
    const Real overlap = thickness_ - dist;
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
    if (track) {
      undo_.push_back({i, oldI});
      undo_.push_back({j, oldJ});
      moved_[i] += taxicab(x[i] - oldI);
      moved_[j] += taxicab(x[j] - oldJ);
    }
  }
  return stats;
}

SelfCollisionStats SelfCollision::solve(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> w,
                                        Real thickness, Real friction, Real time) {
  if (x.size() != start_.size() || x.empty() || thickness != thickness_) return {};
  if (!anyTracked_) return sweep(x, xPrev, w, friction, false);
  const auto n = static_cast<std::uint32_t>(x.size());
  stray_.clear();
  if (!(time >= 0.0 && time <= dt_ * (1.0 + 1e-9))) {  // outside the frame the paths say nothing
    for (std::uint32_t i = 0; i < n; ++i) stray_.push_back(i);
    promote(stray_);
    anyTracked_ = false;
    return sweep(x, xPrev, w, friction, false);
  }
  // How far a tracked particle may stray from its path: the skin, less a margin far above round-off.
  const Real budget = skin_ - 1e-6 * thickness_;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!tracked_[i]) continue;
    strayed_[i] = glm::length(x[i] - (start_[i] + time * velocity_[i]));
    if (strayed_[i] > budget) stray_.push_back(i);
  }
  if (!stray_.empty()) promote(stray_);
  for (;;) {
    undo_.clear();
    const SelfCollisionStats stats = sweep(x, xPrev, w, friction, true);
    stray_.clear();
    for (const Undo& u : undo_) {
      const std::uint32_t k = u.particle;  // a particle listed twice is judged at its first entry
      if (tracked_[k] && strayed_[k] + moved_[k] > budget) stray_.push_back(k);
      moved_[k] = 0.0;
    }
    if (stray_.empty()) return stats;
    // A tracked particle strayed during the sweep: undo it, let the particle's pairs in, sweep again.
    for (auto u = undo_.rbegin(); u != undo_.rend(); ++u) x[u->particle] = u->position;
    std::sort(stray_.begin(), stray_.end());
    stray_.erase(std::unique(stray_.begin(), stray_.end()), stray_.end());
    promote(stray_);
  }
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
