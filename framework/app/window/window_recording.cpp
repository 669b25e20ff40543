#include "app/window/window_recording.h"

#include <cstdio>
#include <ctime>

#include "graphics/screenshot.h"

namespace pba::app {

Status WindowRecording::start(const std::string& path, int width, int height, long totalFrames) {
  std::string error;
  if (!recorder_.open(path, width, height, kRecordFps, &error)) return Error{error};
  total_ = totalFrames;
  started_ = std::chrono::steady_clock::now();
  progress_.emplace("record", totalFrames, "frames", /*piped=*/true);
  return Status::success();
}

std::string WindowRecording::toggle(const std::string& lab, const std::string& scene, int width, int height) {
  if (active()) {
    Result<std::string> done = finish();
    return done ? done.value() : done.error();
  }
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
  const std::string base = "pba-" + lab + "-" + scene + "-" + stamp;
  const std::string path = graphics::findFfmpeg().empty() ? base + "-frames/" : base + ".mp4";
  if (Status s = start(path, width, height, 0); !s) return s.error();
  return "Recording to " + path + " (F9 stops)";
}

Status WindowRecording::capture(int width, int height) {
  std::string error;
  if (!graphics::readFramebuffer(width, height, rgb_, &error)) return Error{recorder_.path() + ": " + error};
  if (!recorder_.addFrame(rgb_, &error)) return Error{error};
  if (total_ > 0) progress_->update(recorder_.frames());
  return Status::success();
}

Result<std::string> WindowRecording::finish() {
  const long frames = recorder_.frames();
  const std::string path = recorder_.path();
  std::string error;
  if (!recorder_.close(&error)) return Error{error};
  char text[64];
  std::snprintf(text, sizeof text, "Recorded %ld frames (%.2f s at %d frames/s) to ", frames,
                static_cast<double>(frames) / kRecordFps, kRecordFps);
  return std::string(text) + path;
}

std::string WindowRecording::statusText() const {
  if (!active()) return {};
  char text[64];
  if (total_ > 0)
    std::snprintf(text, sizeof text, "REC %ld/%ld frames", recorder_.frames(), total_);
  else
    std::snprintf(text, sizeof text, "REC %.1f s (%ld frames)", static_cast<double>(recorder_.frames()) / kRecordFps,
                  recorder_.frames());
  return text;
}

// frames done / total, elapsed and remaining wall time: one line rewritten on a terminal, a line every
// tenth of the recording otherwise (logs).

}  // namespace pba::app
