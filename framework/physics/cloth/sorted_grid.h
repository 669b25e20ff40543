#pragma once
// Particles sorted by the cell of a uniform grid, for pair searches that read positions in sequence: the
// cells hashed into a power-of-two table (Teschner et al. 2003's hash, Fibonacci-hashed to the table), filled
// by counting sort, and each particle's position copied in that order. Table size and hash are
// particles::SpatialHash's own (particles::HashLayout), and a query visits the 27 cells in its order, so a
// query meets the particles in the same order (self-collision's order of pairs depends on it); within a
// bucket, particles are by index.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "physics/core/types.h"
#include "physics/particles/spatial_hash.h"

namespace pba::cloth {

class SortedGrid {
 public:
  /// The grid of x[k] for the particles k listed in `which` (every particle when it is empty), cubic cells
  /// of edge cell [m] > 0.
  void build(std::span<const Vec3> x, std::span<const std::uint32_t> which, Real cell);
  /// Calls visit(bucket, first, last) for each distinct bucket of the 27 cells around p, with its range
  /// of entries [first, last).
  template <typename Visit>
  void forEachNearBucket(const Vec3& p, Visit&& visit) const;
  /// The bucket of the cell holding p.
  std::uint32_t bucketAt(const Vec3& p) const;
  /// The integer coordinates of the cell holding p, and the bucket of cell c + (di, dj, dk).
  std::array<std::int64_t, 3> cellAt(const Vec3& p) const;
  std::uint32_t bucketNear(const std::array<std::int64_t, 3>& c, int di, int dj, int dk) const {
    return bucket(c[0] + di, c[1] + dj, c[2] + dk);
  }

  std::vector<std::uint32_t> particle;  ///< entry → particle index
  std::vector<Vec3> position;           ///< entry → position [m]

 private:
  std::uint32_t bucket(std::int64_t i, std::int64_t j, std::int64_t k) const { return layout_.bucket(i, j, k); }
  Real inverseCell_ = 1.0;
  particles::HashLayout layout_;
  std::vector<std::uint32_t> start_;  ///< table size + 1 prefix sums
  std::vector<std::uint32_t> fill_, bucketOfInput_;
};

inline std::array<std::int64_t, 3> SortedGrid::cellAt(const Vec3& p) const {
  return {static_cast<std::int64_t>(std::floor(p.x * inverseCell_)),
          static_cast<std::int64_t>(std::floor(p.y * inverseCell_)),
          static_cast<std::int64_t>(std::floor(p.z * inverseCell_))};
}

inline std::uint32_t SortedGrid::bucketAt(const Vec3& p) const {
  return bucket(static_cast<std::int64_t>(std::floor(p.x * inverseCell_)),
                static_cast<std::int64_t>(std::floor(p.y * inverseCell_)),
                static_cast<std::int64_t>(std::floor(p.z * inverseCell_)));
}

template <typename Visit>
void SortedGrid::forEachNearBucket(const Vec3& p, Visit&& visit) const {
  if (start_.empty()) return;
  const auto ci = static_cast<std::int64_t>(std::floor(p.x * inverseCell_));
  const auto cj = static_cast<std::int64_t>(std::floor(p.y * inverseCell_));
  const auto ck = static_cast<std::int64_t>(std::floor(p.z * inverseCell_));
  // Two of the 27 cells may share a bucket: each bucket is visited once. A 64-bit mask of the buckets'
  // low bits answers "surely new" for most; the rest are compared with the buckets seen so far.
  std::array<std::uint32_t, 27> seen;
  std::size_t count = 0;
  std::uint64_t mask = 0;
  for (std::int64_t di = -1; di <= 1; ++di)
    for (std::int64_t dj = -1; dj <= 1; ++dj)
      for (std::int64_t dk = -1; dk <= 1; ++dk) {
        const std::uint32_t b = bucket(ci + di, cj + dj, ck + dk);
        const std::uint64_t bit = std::uint64_t{1} << (b & 63u);
        if ((mask & bit) && std::find(seen.begin(), seen.begin() + static_cast<std::ptrdiff_t>(count), b) !=
                                seen.begin() + static_cast<std::ptrdiff_t>(count))
          continue;
        mask |= bit;
        seen[count++] = b;
        if (start_[b] != start_[b + 1]) visit(b, start_[b], start_[b + 1]);
      }
}

}  // namespace pba::cloth
