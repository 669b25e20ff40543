#pragma once
// Physics time per frame [ms]: the samples behind step_ms.median / p95 / max in the metrics JSON.
// Bounded: the last kStepStatsWindow frames (a window left open in a lecture for hours, or a soak of
// millions of frames, must not grow), and clear() gives the memory back (a long stretch in one scene
// otherwise left its high-water buffer to the next: 256 KiB that the soak's memory check counted).
#include <cstddef>
#include <vector>

namespace pba::app {

inline constexpr std::size_t kStepStatsWindow = std::size_t{1} << 16;  ///< frames: 18 min at 60 Hz, 512 KiB

struct StepSummary {
  double median = 0.0, p95 = 0.0, max = 0.0;  ///< [ms]
};

class StepStats {
 public:
  explicit StepStats(std::size_t window = kStepStatsWindow) : window_(window == 0 ? 1 : window) {}
  void add(double milliseconds);
  void clear() { *this = StepStats(window_); }
  std::size_t count() const { return samples_.size(); }  ///< samples held: at most the window
  double last() const { return samples_.empty() ? 0.0 : samples_[(next_ + samples_.size() - 1) % samples_.size()]; }
  /// Nearest-rank percentiles over the samples held, the last `window` frames (zeros when empty).
  StepSummary summary() const;

 private:
  std::size_t window_;
  std::vector<double> samples_;
  std::size_t next_ = 0;  ///< once full: the oldest sample, overwritten next
};

}  // namespace pba::app
