#include "app/runner/step_stats.h"

#include <algorithm>
#include <cmath>

namespace pba::app {

void StepStats::add(double milliseconds) {
  if (samples_.size() < window_) {
    samples_.push_back(milliseconds);
    return;
  }
  samples_[next_] = milliseconds;
  next_ = (next_ + 1) % window_;
}

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
