#pragma once
// Physics time per frame [ms]: the samples behind step_ms.median / p95 / max in the metrics JSON.
#include <cstddef>
#include <vector>

namespace pba::app {

struct StepSummary {
  double median = 0.0, p95 = 0.0, max = 0.0;  ///< [ms]
};

class StepStats {
 public:
  void add(double milliseconds) { samples_.push_back(milliseconds); }
  void clear() { samples_.clear(); }
  std::size_t count() const { return samples_.size(); }
  double last() const { return samples_.empty() ? 0.0 : samples_.back(); }
  /// Nearest-rank percentiles over all samples so far (zeros when empty).
  StepSummary summary() const;

 private:
  std::vector<double> samples_;
};

}  // namespace pba::app
