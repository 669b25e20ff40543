#pragma once
// Particle–particle collisions through a spatial hash grid (Teschner et al. 2003, "Optimized spatial
// hashing for collision detection of deformable objects": cell (i, j, k) ↦ (i·73856093 ⊕ j·19349663 ⊕
// k·83492791) mod T). Cells have the size of a particle diameter, so touching particles are in the same
// or adjacent cells: each particle checks 27 cells. Built by counting sort into one index array
// (no per-cell allocation): O(n) build, O(n) queries for bounded density.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "physics/core/types.h"
#include "physics/particles/particles.h"

namespace pba::particles {

/// The bucket layout of SpatialHash, shared with cloth::SortedGrid (whose order of pairs must be the
/// hash's): a table of 2^b ≥ max(64, 2n) buckets for n entries (load factor ≤ ½), and cell (i, j, k) in the
/// bucket given by the top b bits of Teschner's hash times 2⁶⁴/φ. Departure from Teschner's "mod T":
/// Fibonacci hashing (Knuth TAOCP 6.4), a multiply and a shift instead of a 64-bit modulo, 27 of which per
/// query were the most expensive part of a sweep.
struct HashLayout {
  std::size_t buckets = 64;
  unsigned shift = 58;  ///< 64 − b

  static HashLayout forEntries(std::size_t n) {
    HashLayout layout;
    while (layout.buckets < 2 * n) {
      layout.buckets *= 2;
      --layout.shift;
    }
    return layout;
  }
  std::uint32_t bucket(std::int64_t i, std::int64_t j, std::int64_t k) const {
    const auto h = static_cast<std::uint64_t>(i * 73856093) ^ static_cast<std::uint64_t>(j * 19349663) ^
                   static_cast<std::uint64_t>(k * 83492791);
    return static_cast<std::uint32_t>((h * 0x9E3779B97F4A7C15ull) >> shift);
  }
};

class SpatialHash {
 public:
  /// Rebuilds the grid for `positions` with cubic cells of edge cellSize [m] > 0.
  void build(std::span<const Vec3> positions, Real cellSize);
  /// Calls visit(j) for every particle j in the 27 cells around p (each bucket once; may include
  /// particles farther away than one cell when cells collide in the table, so callers test distance).
  /// Not const: it marks the buckets it has visited in the hash's own scratch array, so two queries on
  /// one hash may not overlap (each thread or world keeps its own hash).
  template <typename Visit>
  void forEachNear(const Vec3& p, Visit&& visit);

 private:
  std::uint32_t bucket(std::int64_t i, std::int64_t j, std::int64_t k) const { return layout_.bucket(i, j, k); }
  Real inverseCell_ = 1.0;
  std::vector<std::uint32_t> cellStart_;  ///< T + 1 prefix sums
  std::vector<std::uint32_t> entries_;    ///< particle indices grouped by bucket
  std::vector<std::uint32_t> bucketOf_;  ///< scratch of build(): each particle's bucket (kept: no allocation per build)
  std::vector<std::uint32_t> fill_;      ///< scratch of build(): next free entry per bucket
  HashLayout layout_;
  // forEachNear()'s record of the buckets it has visited: bucket b was visited by the current query
  // when visited_[b] == query_. One store and one load per cell instead of comparing each of the 27
  // buckets with all earlier ones (27·26/2 comparisons, a third of a collision sweep before).
  std::vector<std::uint32_t> visited_;
  std::uint32_t query_ = 0;
};

template <typename Visit>
void SpatialHash::forEachNear(const Vec3& p, Visit&& visit) {
  const auto ci = static_cast<std::int64_t>(std::floor(p.x * inverseCell_));
  const auto cj = static_cast<std::int64_t>(std::floor(p.y * inverseCell_));
  const auto ck = static_cast<std::int64_t>(std::floor(p.z * inverseCell_));
  if (++query_ == 0) {  // the stamp wrapped around: forget every old mark
    std::fill(visited_.begin(), visited_.end(), 0u);
    query_ = 1;
  }
  for (std::int64_t di = -1; di <= 1; ++di)
    for (std::int64_t dj = -1; dj <= 1; ++dj)
      for (std::int64_t dk = -1; dk <= 1; ++dk) {
        const std::uint32_t b = bucket(ci + di, cj + dj, ck + dk);
        if (visited_[b] == query_) continue;  // two of the 27 cells share this bucket
        visited_[b] = query_;
        for (std::uint32_t e = cellStart_[b]; e < cellStart_[b + 1]; ++e) visit(entries_[e]);
      }
}

struct PairCollisionStats {
  std::size_t contacts = 0;
  Real deepestPenetration = 0.0;  ///< [m] before projection
};
/// A Verlet neighbour list (Verlet 1967, the "skin" of molecular dynamics): the pairs i < j that were
/// closer than reach = contactDistance + skin when it was built. Two particles farther apart than reach
/// come within contactDistance only after moving more than skin between them, so while no particle has
/// moved more than skin/2 since the build, the list holds every pair that can touch. update() checks
/// exactly that (one pass over the positions) and rebuilds only when needed: the granular pile queries
/// the hash about once per step while grains fall and almost never once they rest, instead of once per
/// collision sweep.
class NeighbourList {
 public:
  using Pair = std::pair<std::uint32_t, std::uint32_t>;
  /// Makes the list complete for `positions`: rebuilds (through `hash`, cells of size reach) on first
  /// use, when the particle count, contactDistance or skin changed, or when a particle moved more than
  /// skin/2 since the last build. contactDistance and skin [m] > 0. Returns true when it rebuilt.
  bool update(std::span<const Vec3> positions, Real contactDistance, Real skin, SpatialHash& hash);
  /// Forces a rebuild on the next update() (e.g. after particles were added, removed or teleported).
  void invalidate() { valid_ = false; }
  std::span<const Pair> pairs() const { return pairs_; }
  std::size_t builds() const { return builds_; }  ///< rebuilds so far

 private:
  std::vector<Pair> pairs_;    ///< ordered by i, then by j's bucket
  std::vector<Vec3> builtAt_;  ///< [m] positions at the last build
  Real contactDistance_ = 0.0, skin_ = 0.0;
  std::size_t builds_ = 0;
  bool valid_ = false;
};

/// Separates overlapping particles of equal radius [m] (positions split by inverse mass, like the Ragdoll
/// paper's mass-weighted projection) and applies a normal impulse with restitution to approaching pairs:
///   J = −(1 + e) (v_i − v_j)·n / (w_i + w_j),  v_i += w_i J n,  v_j −= w_j J n  (momentum conserved).
/// Rebuilds `hash` first. One Gauss–Seidel sweep; call again for stiffer piles.
PairCollisionStats collideParticlePairs(Particles& p, Real radius, Real restitution, SpatialHash& hash);
/// The same sweep over the pairs of a neighbour list (call NeighbourList::update with contact distance
/// 2·radius first): no hash query at all.
PairCollisionStats collideParticlePairs(Particles& p, Real radius, Real restitution,
                                        std::span<const NeighbourList::Pair> pairs);

}  // namespace pba::particles
