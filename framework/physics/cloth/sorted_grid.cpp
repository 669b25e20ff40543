#include "physics/cloth/sorted_grid.h"

#include <algorithm>
#include <cassert>

namespace pba::cloth {

void SortedGrid::build(std::span<const Vec3> x, std::span<const std::uint32_t> which, Real cell) {
  assert(cell > 0.0);
  inverseCell_ = 1.0 / cell;
  const std::size_t n = which.empty() ? x.size() : which.size();
  auto input = [&](std::size_t k) { return which.empty() ? static_cast<std::uint32_t>(k) : which[k]; };
  layout_ = particles::HashLayout::forEntries(n);
  const std::size_t table = layout_.buckets;
  start_.assign(table + 1, 0);
  bucketOfInput_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    bucketOfInput_[k] = bucketAt(x[input(k)]);
    ++start_[bucketOfInput_[k] + 1];
  }
  for (std::size_t b = 0; b < table; ++b) start_[b + 1] += start_[b];
  fill_.assign(start_.begin(), start_.end() - 1);
  particle.resize(n);
  position.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t e = fill_[bucketOfInput_[k]]++;
    particle[e] = input(k);
    position[e] = x[input(k)];
  }
}

}  // namespace pba::cloth
