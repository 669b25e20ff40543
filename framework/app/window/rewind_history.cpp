#include "app/window/rewind_history.h"

#include <algorithm>

namespace pba::app {

void RewindHistory::push(Frame frame) {
  while (!atNewest()) {
    bytes_ -= frames_.back().bytes;
    frames_.pop_back();
  }
  // The metrics' text is a fair measure of what their tree holds (a few dozen numbers).
  frame.bytes = frame.state.bytes() + sizeof(Frame) + frame.metrics.dump().size();
  if (frame.partner) frame.bytes += frame.partner->bytes() + frame.partnerMetrics.dump().size();
  bytes_ += frame.bytes;
  frames_.push_back(std::move(frame));
  while (frames_.size() > 1 && (frames_.size() > maxFrames_ || bytes_ > maxBytes_)) {
    bytes_ -= frames_.front().bytes;
    frames_.pop_front();
  }
  cursor_ = frames_.size() - 1;
}

void RewindHistory::clear() {
  frames_.clear();
  cursor_ = 0;
  bytes_ = 0;
}

double RewindHistory::seconds() const {
  return frames_.empty() ? 0.0 : frames_.back().state.simTime - frames_.front().state.simTime;
}

double RewindHistory::capacitySeconds() const {
  if (frames_.size() < 2) return 0.0;
  const double count = static_cast<double>(frames_.size());
  const double frameBytes = static_cast<double>(bytes_) / count;
  const double framesHeld = std::min(static_cast<double>(maxFrames_), static_cast<double>(maxBytes_) / frameBytes);
  return std::max(framesHeld, 1.0) * seconds() / (count - 1.0);
}

}  // namespace pba::app
