#pragma once
// Particles sorted into the cells of a dense uniform grid over their bounding box (no hashing): the three
// cells of a row along x are consecutive, so the 27 cells around a point are 9 ranges of entries, and a
// pair search that visits every pair once reads 5 of them (the rows after a point's own in cell order, and
// its own row from the entry after it). Positions are copied in cell order, read in sequence.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "physics/core/types.h"

namespace pba::cloth {

class DenseGrid {
 public:
  /// Sorts x into cubic cells of edge at least cell [m] > 0 (larger when the box would need more than
  /// 8 cells per particle).
  void build(std::span<const Vec3> x, Real cell);
  /// Calls visit(e, first, last) for runs of entries [first, last) such that every pair of entries in the
  /// same or adjacent cells is (e, f) for exactly one f of one run (e ≠ f, in no particular order); the
  /// caller tests their distance (position[e], particle[e]).
  template <typename Visit>
  void forEachNearRun(Visit&& visit) const;

  std::vector<std::uint32_t> particle;  ///< entry → particle index
  std::vector<Vec3> position;           ///< entry → position [m]

 private:
  std::size_t cellIndex(const Vec3& p) const;
  Vec3 origin_{0.0};
  Real inverseCell_ = 1.0;
  std::size_t nx_ = 1, ny_ = 1, nz_ = 1;
  std::vector<std::uint32_t> start_;  ///< cells + 1 prefix sums
  std::vector<std::uint32_t> cellOfInput_, fill_;
};

inline std::size_t DenseGrid::cellIndex(const Vec3& p) const {
  const Vec3 q = (p - origin_) * inverseCell_;
  const auto i = std::min(static_cast<std::size_t>(q.x), nx_ - 1);
  const auto j = std::min(static_cast<std::size_t>(q.y), ny_ - 1);
  const auto k = std::min(static_cast<std::size_t>(q.z), nz_ - 1);
  return i + nx_ * (j + ny_ * k);
}

template <typename Visit>
void DenseGrid::forEachNearRun(Visit&& visit) const {
  // Cell by cell, so that a cell's coordinates come from the loops (no divisions per entry); locals, so
  // that what visit writes cannot make the compiler load them again.
  const std::size_t nx = nx_, ny = ny_, nz = nz_, rowStride = nx_, sliceStride = nx_ * ny_;
  const std::uint32_t* start = start_.data();
  for (std::size_t k = 0; k < nz; ++k) {
    for (std::size_t j = 0; j < ny; ++j) {
      const std::size_t rowBase = j * rowStride + k * sliceStride;
      for (std::size_t i = 0; i < nx; ++i) {
        const std::uint32_t first = start[rowBase + i], last = start[rowBase + i + 1];
        if (first == last) continue;
        const std::size_t i0 = i > 0 ? i - 1 : 0, i1 = i + 1 < nx ? i + 1 : i;
        // Rows (dj, dk) after the own row in cell order: dk = 0, dj = 1; dk = 1, dj = −1, 0, 1.
        auto row = [&](std::uint32_t e, std::size_t jj, std::size_t kk) {
          const std::size_t base = jj * rowStride + kk * sliceStride;
          visit(e, start[base + i0], start[base + i1 + 1]);
        };
        const std::uint32_t ownEnd = start[rowBase + i1 + 1];
        for (std::uint32_t e = first; e < last; ++e) {
          visit(e, e + 1, ownEnd);  // own row: the entries after e
          if (j + 1 < ny) row(e, j + 1, k);
          if (k + 1 < nz) {
            if (j > 0) row(e, j - 1, k + 1);
            row(e, j, k + 1);
            if (j + 1 < ny) row(e, j + 1, k + 1);
          }
        }
      }
    }
  }
}

}  // namespace pba::cloth
