#pragma once
// Particle–particle collisions through a spatial hash grid (Teschner et al. 2003, "Optimized spatial
// hashing for collision detection of deformable objects": cell (i, j, k) ↦ (i·73856093 ⊕ j·19349663 ⊕
// k·83492791) mod T). Cells have the size of a particle diameter, so touching particles are in the same
// or adjacent cells: each particle checks 27 cells. Built by counting sort into one index array
// (no per-cell allocation): O(n) build, O(n) queries for bounded density.
#include <cstdint>
#include <span>
#include <vector>

#include "physics/core/types.h"
#include "physics/particles/particles.h"

namespace pba::particles {

class SpatialHash {
 public:
  /// Rebuilds the grid for `positions` with cubic cells of edge cellSize [m] > 0.
  void build(std::span<const Vec3> positions, Real cellSize);
  /// Calls visit(j) for every particle j in the 27 cells around p (each bucket once; may include
  /// particles farther away than one cell when cells collide in the table, so callers test distance).
  template <typename Visit>
  void forEachNear(const Vec3& p, Visit&& visit) const;

  std::size_t tableSize() const { return cellStart_.empty() ? 0 : cellStart_.size() - 1; }
  /// Departure from Teschner's "mod T": the table is a power of two 2^b and the bucket is the top b bits
  /// of the hash times 2⁶⁴/φ (Fibonacci hashing, Knuth TAOCP 6.4): a multiply and a shift instead of a
  /// 64-bit modulo, 27 of which per query were the most expensive part of a sweep.

 private:
  std::uint32_t bucket(std::int64_t i, std::int64_t j, std::int64_t k) const;
  Real inverseCell_ = 1.0;
  std::vector<std::uint32_t> cellStart_;  ///< T + 1 prefix sums
  std::vector<std::uint32_t> entries_;    ///< particle indices grouped by bucket
  std::vector<std::uint32_t> bucketOf_;   ///< scratch of build(): each particle's bucket (kept: no allocation per build)
  std::vector<std::uint32_t> fill_;       ///< scratch of build(): next free entry per bucket
  unsigned shift_ = 58;                   ///< 64 − b, where tableSize() = 2^b
};

template <typename Visit>
void SpatialHash::forEachNear(const Vec3& p, Visit&& visit) const {
  const auto ci = static_cast<std::int64_t>(std::floor(p.x * inverseCell_));
  const auto cj = static_cast<std::int64_t>(std::floor(p.y * inverseCell_));
  const auto ck = static_cast<std::int64_t>(std::floor(p.z * inverseCell_));
  std::uint32_t seen[27];
  int nSeen = 0;
  for (std::int64_t di = -1; di <= 1; ++di)
    for (std::int64_t dj = -1; dj <= 1; ++dj)
      for (std::int64_t dk = -1; dk <= 1; ++dk) {
        const std::uint32_t b = bucket(ci + di, cj + dj, ck + dk);
        bool repeated = false;
        for (int s = 0; s < nSeen; ++s) repeated = repeated || seen[s] == b;
        if (repeated) continue;
        seen[nSeen++] = b;
        for (std::uint32_t e = cellStart_[b]; e < cellStart_[b + 1]; ++e) visit(entries_[e]);
      }
}

inline std::uint32_t SpatialHash::bucket(std::int64_t i, std::int64_t j, std::int64_t k) const {
  const auto h = static_cast<std::uint64_t>(i * 73856093) ^ static_cast<std::uint64_t>(j * 19349663) ^
                 static_cast<std::uint64_t>(k * 83492791);
  return static_cast<std::uint32_t>((h * 0x9E3779B97F4A7C15ull) >> shift_);
}

struct PairCollisionStats {
  std::size_t contacts = 0;
  Real deepestPenetration = 0.0;  ///< [m] before projection
};
/// Separates overlapping particles of equal radius [m] (positions split by inverse mass, like the Ragdoll
/// paper's mass-weighted projection) and applies a normal impulse with restitution to approaching pairs:
///   J = −(1 + e) (v_i − v_j)·n / (w_i + w_j),  v_i += w_i J n,  v_j −= w_j J n  (momentum conserved).
/// Rebuilds `hash` first. One Gauss–Seidel sweep; call again for stiffer piles.
PairCollisionStats collideParticlePairs(Particles& p, Real radius, Real restitution, SpatialHash& hash);

}  // namespace pba::particles
