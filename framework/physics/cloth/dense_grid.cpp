#include "physics/cloth/dense_grid.h"

#include <algorithm>
#include <cassert>
#include <limits>

namespace pba::cloth {

void DenseGrid::build(std::span<const Vec3> x, Real cell) {
  assert(cell > 0.0);
  const std::size_t n = x.size();
  Vec3 lo(std::numeric_limits<Real>::infinity()), hi(-std::numeric_limits<Real>::infinity());
  for (const Vec3& p : x) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  if (n == 0) lo = hi = Vec3(0.0);
  // At most 8 cells per particle (and some slack): a sparse cloud gets larger cells, never smaller ones.
  const Vec3 extent = hi - lo;
  auto cellsFor = [&](Real c) {
    return (std::floor(extent.x / c) + 1.0) * (std::floor(extent.y / c) + 1.0) * (std::floor(extent.z / c) + 1.0);
  };
  while (cellsFor(cell) > 8.0 * static_cast<Real>(n) + 64.0) cell *= 1.25;
  origin_ = lo;
  inverseCell_ = 1.0 / cell;
  nx_ = static_cast<std::size_t>(std::floor(extent.x / cell)) + 1;
  ny_ = static_cast<std::size_t>(std::floor(extent.y / cell)) + 1;
  nz_ = static_cast<std::size_t>(std::floor(extent.z / cell)) + 1;
  start_.assign(nx_ * ny_ * nz_ + 1, 0);
  cellOfInput_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    cellOfInput_[k] = static_cast<std::uint32_t>(cellIndex(x[k]));
    ++start_[cellOfInput_[k] + 1];
  }
  for (std::size_t c = 0; c + 1 < start_.size(); ++c) start_[c + 1] += start_[c];
  fill_.assign(start_.begin(), start_.end() - 1);
  particle.resize(n);
  position.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t e = fill_[cellOfInput_[k]]++;
    particle[e] = static_cast<std::uint32_t>(k);
    position[e] = x[k];
  }
}

}  // namespace pba::cloth
