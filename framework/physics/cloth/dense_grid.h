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
  /// Calls visit(e, f) once for every pair of entries in the same or adjacent cells (e ≠ f, in no
  /// particular order); the caller tests their distance (position[e], particle[e]).
  template <typename Visit>
  void forEachNearPair(Visit&& visit) const;

  std::vector<std::uint32_t> particle;  ///< entry → particle index
  std::vector<Vec3> position;           ///< entry → position [m]

 private:
  std::size_t cellIndex(const Vec3& p) const;
  Vec3 origin_{0.0};
  Real inverseCell_ = 1.0;
  std::size_t nx_ = 1, ny_ = 1, nz_ = 1;
  std::vector<std::uint32_t> start_;  ///< cells + 1 prefix sums
  std::vector<std::uint32_t> cellOfInput_, fill_;
  std::vector<std::uint32_t> cellOfEntry_;
};

inline std::size_t DenseGrid::cellIndex(const Vec3& p) const {
  const Vec3 q = (p - origin_) * inverseCell_;
  const auto i = std::min(static_cast<std::size_t>(q.x), nx_ - 1);
  const auto j = std::min(static_cast<std::size_t>(q.y), ny_ - 1);
  const auto k = std::min(static_cast<std::size_t>(q.z), nz_ - 1);
  return i + nx_ * (j + ny_ * k);
}

template <typename Visit>
void DenseGrid::forEachNearPair(Visit&& visit) const {
  const std::size_t rowStride = nx_, sliceStride = nx_ * ny_;
  for (std::uint32_t e = 0; e < particle.size(); ++e) {
    const std::size_t c = cellOfEntry_[e];
    const std::size_t i = c % nx_, j = (c / nx_) % ny_, k = c / sliceStride;
    const std::size_t i0 = i > 0 ? i - 1 : 0, i1 = i + 1 < nx_ ? i + 1 : i;
    // Rows (dj, dk) after the own row in cell order: dk = 0, dj = 1; dk = 1, dj = −1, 0, 1.
    auto row = [&](std::size_t jj, std::size_t kk) {
      const std::size_t base = jj * rowStride + kk * sliceStride;
      for (std::uint32_t f = start_[base + i0]; f < start_[base + i1 + 1]; ++f) visit(e, f);
    };
    {  // own row: the entries after e
      const std::size_t base = j * rowStride + k * sliceStride;
      for (std::uint32_t f = e + 1; f < start_[base + i1 + 1]; ++f) visit(e, f);
    }
    if (j + 1 < ny_) row(j + 1, k);
    if (k + 1 < nz_) {
      if (j > 0) row(j - 1, k + 1);
      row(j, k + 1);
      if (j + 1 < ny_) row(j + 1, k + 1);
    }
  }
}

}  // namespace pba::cloth
