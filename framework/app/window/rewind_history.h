#pragma once
// The rewind history of a lab (docs/architecture.md §3, "Rewind"): the state after every displayed frame
// that stepped, oldest first, bounded by memory and by length, with a cursor that scrubbing moves. A
// frame pushed while the cursor is behind the newest one discards the frames after the cursor: the run
// goes on from the scrubbed point as a new branch. No GL, no ImGui: tested headless.
#include <cstddef>
#include <deque>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/runner/scene_runner.h"

namespace pba::app {

/// Default bounds: 30 s of displayed frames at 60 frames/s, or 256 MiB, whichever is reached first.
inline constexpr std::size_t kRewindMaxFrames = 1800;
inline constexpr std::size_t kRewindMaxBytes = std::size_t(256) << 20;

class RewindHistory {
 public:
  struct Frame {
    RunnerSnapshot state;
    nlohmann::json metrics;                 ///< the scene's metrics at that frame (the plots are rebuilt from them)
    std::size_t bytes = 0;                  ///< state and metrics [bytes], both sides of an A/B run
    std::optional<RunnerSnapshot> partner;  ///< B's state in an A/B run
    nlohmann::json partnerMetrics;
  };

  explicit RewindHistory(std::size_t maxBytes = kRewindMaxBytes, std::size_t maxFrames = kRewindMaxFrames)
      : maxBytes_(maxBytes), maxFrames_(maxFrames) {}

  /// Appends the state after a frame; first drops the frames after the cursor, then the oldest ones
  /// beyond the bounds (the newest frame is always kept, even alone over the byte bound). The cursor
  /// moves to the new frame.
  void push(RunnerSnapshot state, nlohmann::json metrics) { push(Frame{std::move(state), std::move(metrics)}); }
  void push(Frame frame);
  void clear();

  std::size_t size() const { return frames_.size(); }
  bool empty() const { return frames_.empty(); }
  const Frame& at(std::size_t i) const { return frames_[i]; }
  /// Index of the frame shown; size() − 1 when live.
  std::size_t cursor() const { return cursor_; }
  void setCursor(std::size_t i) { cursor_ = frames_.empty() ? 0 : std::min(i, frames_.size() - 1); }
  bool atNewest() const { return frames_.empty() || cursor_ + 1 == frames_.size(); }

  std::size_t bytes() const { return bytes_; }
  std::size_t maxBytes() const { return maxBytes_; }
  std::size_t maxFrames() const { return maxFrames_; }
  /// Simulated time the history spans [s].
  double seconds() const;
  /// Simulated time [s] the history holds when full, for the scene in it: the frame bound or the byte
  /// bound over the mean bytes of a frame, whichever allows fewer frames, times the mean simulated time of
  /// a frame. It scales inversely with the state's size. 0 with fewer than two frames (nothing to measure).
  double capacitySeconds() const;

 private:
  std::size_t maxBytes_;
  std::size_t maxFrames_;
  std::deque<Frame> frames_;
  std::size_t cursor_ = 0;
  std::size_t bytes_ = 0;
};

}  // namespace pba::app
