#pragma once
// Particles sorted by the cell of a uniform grid, for pair searches that read positions in sequence: the
// cells hashed into a power-of-two table (Teschner et al. 2003's hash, Fibonacci-hashed to the table as in
// particles/spatial_hash.h), filled by counting sort, and each particle's position copied in that order.
// A query visits the 27 cells around a point as ranges of entries; a pair search visits every pair once by
// reading, from entry e of bucket b, only buckets after b and the entries after e in b itself.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "physics/core/types.h"

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
  /// The bucket of entry e.
  std::uint32_t bucketOfEntry(std::uint32_t e) const { return bucketOfEntry_[e]; }

  std::vector<std::uint32_t> particle;  ///< entry → particle index
  std::vector<Vec3> position;           ///< entry → position [m]

 private:
  std::uint32_t bucket(const Vec3& p, int di, int dj, int dk) const;
  Real inverseCell_ = 1.0;
  unsigned shift_ = 58;
  std::vector<std::uint32_t> start_;  ///< table size + 1 prefix sums
  std::vector<std::uint32_t> bucketOfEntry_, fill_, bucketOfInput_;
  // Buckets visited by the current query: bucket b was when visited_[b] == query_ (two cells may share one).
  mutable std::vector<std::uint32_t> visited_;
  mutable std::uint32_t query_ = 0;
};

inline std::uint32_t SortedGrid::bucket(const Vec3& p, int di, int dj, int dk) const {
  const auto i = static_cast<std::int64_t>(std::floor(p.x * inverseCell_)) + di;
  const auto j = static_cast<std::int64_t>(std::floor(p.y * inverseCell_)) + dj;
  const auto k = static_cast<std::int64_t>(std::floor(p.z * inverseCell_)) + dk;
  const auto h = static_cast<std::uint64_t>(i * 73856093) ^ static_cast<std::uint64_t>(j * 19349663) ^
                 static_cast<std::uint64_t>(k * 83492791);
  return static_cast<std::uint32_t>((h * 0x9E3779B97F4A7C15ull) >> shift_);
}

template <typename Visit>
void SortedGrid::forEachNearBucket(const Vec3& p, Visit&& visit) const {
  if (start_.empty()) return;
  if (++query_ == 0) {
    std::fill(visited_.begin(), visited_.end(), 0u);
    query_ = 1;
  }
  for (int di = -1; di <= 1; ++di)
    for (int dj = -1; dj <= 1; ++dj)
      for (int dk = -1; dk <= 1; ++dk) {
        const std::uint32_t b = bucket(p, di, dj, dk);
        if (visited_[b] == query_) continue;
        visited_[b] = query_;
        if (start_[b] != start_[b + 1]) visit(b, start_[b], start_[b + 1]);
      }
}

}  // namespace pba::cloth
