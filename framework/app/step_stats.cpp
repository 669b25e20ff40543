#include "app/step_stats.h"

#include <algorithm>
#include <cmath>

namespace pba::app {

StepSummary StepStats::summary() const {
  if (samples_.empty()) return {};
  std::vector<double> sorted = samples_;
  std::sort(sorted.begin(), sorted.end());
  // Nearest rank: the smallest sample with at least p of the samples at or below it.
  auto rank = [&](double p) {
    const auto index = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size()))) - 1;
    return sorted[std::min(index, sorted.size() - 1)];
  };
  return {rank(0.5), rank(0.95), sorted.back()};
}

}  // namespace pba::app
