#include "physics/cloth/self_collision.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "physics/core/lanes.h"

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

}  // namespace

void SelfCollision::buildPairs(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness, Real reach,
                               bool nearList) {
  nearBuilds_ = 0;
  pairs_.clear();
  // The Verlet list outlives the frame unless what decides its pairs changed (a reset to another cloth,
  // tearing, another thickness, the other mode).
  if (!nearList || !nearList_ || thickness != thickness_ || rest.size() != rest_.size() ||
      !std::equal(rest.begin(), rest.end(), rest_.begin())) {
    nearBuilt_ = false;
    near_.clear();
    contacts_.clear();
    rest_.assign(rest.begin(), rest.end());
  }
  nearList_ = nearList;
  thickness_ = thickness;
  skin_ = kSelfSkinFactor * thickness;
  if (x.empty() || !(thickness > 0.0) || nearList) return;
  start_.assign(x.begin(), x.end());
  reach_ = std::max(reach, thickness);
  // The grid of TMP's query (cells of the reach at the frame's start): it lists F and orders it. A query
  // visits its 27 cells in turn but a bucket only once: where two of them share a bucket (rare), the rank
  // of a cell is that of the first.
  wide_.build(start_, {}, reach_);
  cell_.resize(x.size());
  bucket_.resize(x.size());
  shared_.assign(x.size(), 0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    cell_[i] = wide_.cellAt(start_[i]);
    bucket_[i] = wide_.bucketNear(cell_[i], 0, 0, 0);
    std::array<std::uint32_t, 27> b{};
    int o = 0;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj)
        for (int dk = -1; dk <= 1; ++dk) b[o++] = wide_.bucketNear(cell_[i], di, dj, dk);
    std::sort(b.begin(), b.end());
    shared_[i] = std::adjacent_find(b.begin(), b.end()) != b.end() ? 1 : 0;
  }
  buildFramePairs();
}

std::uint64_t SelfCollision::key(std::uint32_t i, std::uint32_t j) const {
  const auto& ci = cell_[i];
  const auto& cj = cell_[j];
  std::uint32_t rank =
      static_cast<std::uint32_t>((cj[0] - ci[0] + 1) * 9 + (cj[1] - ci[1] + 1) * 3 + (cj[2] - ci[2] + 1));
  if (shared_[i]) {  // the first of the 27 cells with j's bucket
    rank = 0;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj)
        for (int dk = -1; dk <= 1; ++dk, ++rank) {
          if (wide_.bucketNear(ci, di, dj, dk) == bucket_[j])
            return std::uint64_t{i} << 37 | std::uint64_t{rank} << 32 | j;
        }
  }
  return std::uint64_t{i} << 37 | std::uint64_t{rank} << 32 | j;
}

void SelfCollision::buildFramePairs() {
  // TMP's query: every particle i asks the 27 cells around it for particles j > i. The grid holds the
  // positions in cell order and each cell's particles in increasing index, so the j > i of a cell are the
  // tail of its range and their positions are read in sequence.
  pairs_.clear();
  const Real reach2 = reach_ * reach_;
  for (std::uint32_t i = 0; i < start_.size(); ++i) {
    const Vec3 p = start_[i];
    const std::size_t rowBegin = pairs_.size();
    wide_.forEachNearBucket(p, [&](std::uint32_t, std::uint32_t first, std::uint32_t last) {
      const auto begin = wide_.particle.begin();
      for (auto f = static_cast<std::uint32_t>(std::upper_bound(begin + first, begin + last, i) - begin); f < last;
           ++f) {
        if (distance2(p, wide_.position[f]) >= reach2) continue;
        const std::uint32_t j = wide_.particle[f];
        if (!neighbours(rest_[i], rest_[j], thickness_)) pairs_.push_back(key(i, j));
      }
    });
    std::sort(pairs_.begin() + static_cast<std::ptrdiff_t>(rowBegin), pairs_.end());
  }
}

namespace {
/// |a − b|² for two candidates b, as distance2 computes it (glm::dot: (x² + y²) + z²). b − a is −(a − b)
/// exactly (rounding to nearest is symmetric), so its square is the same; subtracting from the loaded
/// value saves SSE2 a copy of a per coordinate.
Pair distance2(const std::array<Pair, 3>& a, const Real* bx, const Real* by, const Real* bz, std::uint32_t f) {
  const Pair dx = loadPair(bx + f) - a[0], dy = loadPair(by + f) - a[1], dz = loadPair(bz + f) - a[2];
  return dx * dx + dy * dy + dz * dz;
}
}  // namespace

// flatten: the grid's walk and the candidate test below are inlined into one loop nest (the walk calls
// the test once per run of entries, several runs a particle, and those calls cost a good share of the
// build; docs/performance-cloth.md has the figures).
[[gnu::flatten]] void SelfCollision::buildNearList(std::span<const Vec3> x) {
  const Real near = thickness_ + skin_;
  const Real near2 = near * near;
  near_.clear();
  const Real neighbour = kSelfNeighbourFactor * thickness_;
  const Real neighbour2 = neighbour * neighbour;
  narrow_.build(x, near);
  // Positions and rest positions in the grid's order, coordinate by coordinate (two candidates' x in one
  // load), and the particles, each with one entry of padding: a pair of entries never reads past the end.
  for (std::vector<Real>& c : byCoordinate_) c.resize(x.size() + 1, 0.0);
  particleOf_.resize(x.size() + 1, 0);
  for (std::size_t e = 0; e < x.size(); ++e) {
    const Vec3& p = narrow_.position[e];
    const Vec3& r = rest_[narrow_.particle[e]];
    for (int c = 0; c < 3; ++c) {
      byCoordinate_[c][e] = p[c];
      byCoordinate_[3 + c][e] = r[c];
    }
    particleOf_[e] = narrow_.particle[e];
  }
  const Real *px = byCoordinate_[0].data(), *py = byCoordinate_[1].data(), *pz = byCoordinate_[2].data();
  const Real *rx = byCoordinate_[3].data(), *ry = byCoordinate_[4].data(), *rz = byCoordinate_[5].data();
  const std::uint32_t* particle = particleOf_.data();
  const Pair near2s = splat(near2), neighbour2s = splat(neighbour2);
  // Most candidates are neighbours in a flat stretch of cloth, or not close: whether one is kept is
  // unpredictable, so every candidate is written and the count advances only for those kept (no branch).
  // A candidate is written as it comes, (i, j); the pairs kept are put in order (i < j) afterwards.
  std::size_t count = 0;
  narrow_.forEachNearRun([&](std::uint32_t e, std::uint32_t first, std::uint32_t last) {
    if (count + (last - first) + 1 > candidates_.size()) candidates_.resize(2 * (count + (last - first) + 1));
    std::array<std::uint32_t, 2>* out = candidates_.data();
    const std::array<Pair, 3> p{splat(px[e]), splat(py[e]), splat(pz[e])};
    const std::array<Pair, 3> r{splat(rx[e]), splat(ry[e]), splat(rz[e])};
    const std::uint32_t i = particle[e];
    std::size_t kept = count;
    // Two candidates at a time; on an odd run the second lane of the last pair tests the next entry (or
    // the padding) and is dropped. Lanes of a comparison are −1 (true) or 0.
    for (std::uint32_t f = first; f < last; f += 2) {
      const auto keep = (distance2(p, px, py, pz, f) < near2s) & (distance2(r, rx, ry, rz, f) >= neighbour2s);
      out[kept][0] = i;  // two 4-byte stores: cheaper than building the pair in a register
      out[kept][1] = particle[f];
      kept += static_cast<std::size_t>(-keep[0]);
      out[kept][0] = i;
      out[kept][1] = particle[f + 1];
      kept += static_cast<std::size_t>(-keep[1]) & static_cast<std::size_t>(f + 1 < last);
    }
    count = kept;
  });
  near_.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    const auto [i, j] = candidates_[k];
    near_[k] = {std::min(i, j), std::max(i, j)};
  }
  builtAt_.assign(x.begin(), x.end());
  nearBuilt_ = true;
  ++nearBuilds_;
}

bool SelfCollision::movedPastHalfTheSkin(std::span<const Vec3> x) const {
  // A pair's distance changes by at most |d_i − d_j| = |(d_i − c) − (d_j − c)| ≤ |d_i − c| + |d_j − c| for
  // the displacements d since the build and any common vector c: with every |d_i − c| ≤ s/2, a pair left
  // out (≥ thickness + s apart) is still ≥ thickness apart. c is the centre of the displacements' bounding
  // box, so a cloth that falls as one keeps its list however far it falls (Verlet 1967's criterion is
  // c = 0; Allen & Tildesley §5.3 note that only relative motion matters).
  if (x.empty()) return false;
  Vec3 lo(std::numeric_limits<Real>::infinity()), hi(-std::numeric_limits<Real>::infinity());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3 d = x[i] - builtAt_[i];
    lo = glm::min(lo, d);
    hi = glm::max(hi, d);
  }
  const Vec3 common = 0.5 * (lo + hi);
  // Half the skin less a margin far above round-off (a pair left out was ≥ thickness + skin apart).
  const Real budget = 0.5 * skin_ - 1e-6 * thickness_;
  const Real budget2 = budget * budget;
  bool moved = false;
  for (std::size_t i = 0; i < x.size(); ++i)
    moved |= !(distance2(x[i] - builtAt_[i], common) <= budget2);  // NaN: moved
  return moved;
}

template <typename Pairs>
SelfCollisionStats SelfCollision::sweep(const Pairs& pairs, std::span<Vec3> x, std::span<const Vec3> xPrev,
                                        std::span<const Real> w, Real thickness, Real friction, bool record) {
  SelfCollisionStats stats;
  if (record) contacts_.clear();
  const Real thickness2 = thickness * thickness;
  for (const auto& pair : pairs) {
    std::uint32_t i, j;
    if constexpr (std::is_same_v<std::decay_t<decltype(pair)>, std::uint64_t>) {
      i = static_cast<std::uint32_t>(pair >> 37);
      j = static_cast<std::uint32_t>(pair);
    } else {
      i = pair[0];
      j = pair[1];
    }
    const Vec3 d = x[i] - x[j];
    const Real dist2 = glm::dot(d, d);
    if (dist2 >= thickness2 || dist2 == 0.0) continue;
    const Real wSum = w[i] + w[j];
    if (wSum == 0.0) continue;
    if (record) contacts_.push_back({i, j});
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

SelfCollisionStats SelfCollision::solve(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> w,
                                        Real thickness, Real friction, bool again) {
  if (x.size() != rest_.size() || x.empty() || !(thickness_ > 0.0) || thickness != thickness_) {
    contacts_.clear();  // nothing for further sweeps or the collider pass between them
    return {};
  }
  if (again) return sweep(contacts_, x, xPrev, w, thickness, friction, false);
  if (!nearList_) return sweep(pairs_, x, xPrev, w, thickness, friction, true);
  if (!nearBuilt_ || movedPastHalfTheSkin(x)) buildNearList(x);
  return sweep(near_, x, xPrev, w, thickness, friction, true);
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
