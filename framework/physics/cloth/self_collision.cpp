#include "physics/cloth/self_collision.h"

#include <algorithm>
#include <cmath>
#include <iterator>

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
  pairs_.clear();
  near_.clear();
  framePairsBuilt_ = false;
  nearThickness_ = 0.0;
  skin_ = kSelfSkinFactor * thickness;
  untracked_.assign(x.size(), 0);
  untrackedPairs_.clear();
  untrackedCount_ = 0;
  nearList_ = nearList;
  nearBuilds_ = fullSweeps_ = 0;
  start_.assign(x.begin(), x.end());
  rest_.assign(rest.begin(), rest.end());
  thickness_ = thickness;
  if (x.empty() || !(thickness > 0.0)) return;
  reach_ = std::max(reach, thickness);
  // The grid of TMP's query (cells of the reach at the frame's start): it lists F, or a particle's pairs,
  // and orders them. A query visits its 27 cells in turn but a bucket only once: where two of them share a
  // bucket (rare), the rank of a cell is that of the first.
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
  away_.assign(x.size(), 0.0);
  moved_.assign(x.size(), 0.0);
  if (!nearList) buildFramePairs();
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

[[gnu::always_inline]] inline bool SelfCollision::inFrame(std::uint32_t i, std::uint32_t j) const {
  return distance2(start_[i], start_[j]) < reach_ * reach_ && !neighbours(rest_[i], rest_[j], thickness_);
}

void SelfCollision::framePairsOf(std::uint32_t k, std::vector<std::uint64_t>& out) const {
  const Real reach2 = reach_ * reach_;
  const Vec3 p = start_[k];
  wide_.forEachNearBucket(p, [&](std::uint32_t, std::uint32_t first, std::uint32_t last) {
    for (std::uint32_t f = first; f < last; ++f) {
      if (distance2(p, wide_.position[f]) >= reach2) continue;
      const std::uint32_t j = wide_.particle[f];
      if (j != k && !neighbours(rest_[k], rest_[j], thickness_)) out.push_back(key(std::min(k, j), std::max(k, j)));
    }
  });
}

void SelfCollision::sortKeys(std::vector<std::uint64_t>& keys) {
  // Counting sort by i, then each row by (rank, j), without repeats.
  const std::size_t n = start_.size();
  rowEnd_.assign(n + 1, 0);
  for (const std::uint64_t q : keys) ++rowEnd_[(q >> 37) + 1];
  for (std::size_t i = 0; i < n; ++i) rowEnd_[i + 1] += rowEnd_[i];
  byRow_.resize(keys.size());
  for (const std::uint64_t q : keys) byRow_[rowEnd_[q >> 37]++] = q;
  std::size_t begin = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t end = rowEnd_[i];
    if (end - begin > 1) {
      std::sort(byRow_.begin() + static_cast<std::ptrdiff_t>(begin), byRow_.begin() + static_cast<std::ptrdiff_t>(end));
    }
    begin = end;
  }
  byRow_.erase(std::unique(byRow_.begin(), byRow_.end()), byRow_.end());
  keys.swap(byRow_);
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
  framePairsBuilt_ = true;
}

void SelfCollision::buildNearList(std::span<const Vec3> x) {
  // The pairs of F closer than thickness + s now, found in cells of that size, with every pair of F of an
  // untracked particle; in F's order.
  const Real near = thickness_ + skin_;
  const Real near2 = near * near;
  near_.clear();
  narrow_.build(x, near);
  narrow_.forEachNearPair([&](std::uint32_t e, std::uint32_t f) __attribute__((always_inline)) {
    if (distance2(narrow_.position[e], narrow_.position[f]) >= near2) return;
    const std::uint32_t i = narrow_.particle[e], j = narrow_.particle[f];
    if (inFrame(i, j)) near_.push_back(key(std::min(i, j), std::max(i, j)));
  });
  sortKeys(near_);
  if (!untrackedPairs_.empty()) {
    merged_.clear();
    std::set_union(near_.begin(), near_.end(), untrackedPairs_.begin(), untrackedPairs_.end(),
                   std::back_inserter(merged_));
    near_.swap(merged_);
  }
  builtAt_.assign(x.begin(), x.end());
  nearThickness_ = thickness_;
  ++nearBuilds_;
}

void SelfCollision::untrack(std::span<const std::uint32_t> particles) {
  added_.clear();
  for (std::uint32_t k : particles) {
    if (untracked_[k]) continue;
    untracked_[k] = 1;
    ++untrackedCount_;
    framePairsOf(k, added_);
  }
  sortKeys(added_);
  for (std::vector<std::uint64_t>* list : {&untrackedPairs_, &near_}) {
    merged_.clear();
    std::set_union(list->begin(), list->end(), added_.begin(), added_.end(), std::back_inserter(merged_));
    list->swap(merged_);
  }
}

SelfCollisionStats SelfCollision::sweep(std::span<const std::uint64_t> pairs, std::span<Vec3> x,
                                        std::span<const Vec3> xPrev, std::span<const Real> w, Real thickness,
                                        Real friction, bool track) {
  SelfCollisionStats stats;
  const Real thickness2 = thickness * thickness;
  for (const std::uint64_t pair : pairs) {
    const auto i = static_cast<std::uint32_t>(pair >> 37), j = static_cast<std::uint32_t>(pair);
    const Vec3 d = x[i] - x[j];
    const Real dist2 = glm::dot(d, d);
    if (dist2 >= thickness2 || dist2 == 0.0) continue;
    const Real wSum = w[i] + w[j];
    if (wSum == 0.0) continue;
    const Vec3 oldI = x[i], oldJ = x[j];
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
    if (track) {
      undo_[undone_++] = {i, oldI};
      undo_[undone_++] = {j, oldJ};
      moved_[i] += glm::length(x[i] - oldI);
      moved_[j] += glm::length(x[j] - oldJ);
    }
  }
  return stats;
}

void SelfCollision::undo(std::span<Vec3> x) {
  for (std::size_t u = undone_; u-- > 0;) x[undo_[u].particle] = undo_[u].position;
}

SelfCollisionStats SelfCollision::solve(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> w,
                                        Real thickness, Real friction) {
  if (x.size() != start_.size() || x.empty() || !(thickness_ > 0.0) || thickness != thickness_) return {};
  if (!nearList_) {
    if (!framePairsBuilt_) buildFramePairs();
    ++fullSweeps_;
    return sweep(pairs_, x, xPrev, w, thickness, friction, false);
  }
  // How far a tracked particle may go from where it was at the build: half the skin, less a margin far
  // above round-off (a pair of F left out was ≥ thickness + skin apart).
  const Real budget = 0.5 * skin_ - 1e-6 * thickness;
  far_.clear();
  if (nearThickness_ == thickness) {
    for (std::uint32_t i = 0; i < x.size(); ++i) {
      if (untracked_[i]) continue;
      away_[i] = std::sqrt(distance2(x[i], builtAt_[i]));
      if (away_[i] > budget) far_.push_back(i);
    }
  }
  // Many particles went too far (or there is no list yet): a new list; a few: they are untracked.
  if (nearThickness_ != thickness || static_cast<Real>(far_.size()) > kSelfRebuildShare * static_cast<Real>(x.size())) {
    buildNearList(x);
    std::fill(away_.begin(), away_.end(), 0.0);
  } else if (!far_.empty()) {
    untrack(far_);
  }
  for (;;) {
    undone_ = 0;
    if (undo_.size() < 2 * near_.size()) undo_.resize(2 * near_.size());
    const SelfCollisionStats stats = sweep(near_, x, xPrev, w, thickness, friction, true);
    far_.clear();
    for (std::size_t u = 0; u < undone_; ++u) {
      const std::uint32_t k = undo_[u].particle;  // a particle listed twice is judged at its first entry
      if (!untracked_[k] && away_[k] + moved_[k] > budget) far_.push_back(k);
      moved_[k] = 0.0;
    }
    if (far_.empty()) return stats;
    // A tracked particle went too far during the sweep: undo it, let its pairs in, sweep again.
    undo(x);
    untrack(far_);
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
