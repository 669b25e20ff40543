#include "app/window_recording.h"

#include <unistd.h>

#include <cstdio>
#include <ctime>

#include "graphics/screenshot.h"

namespace pba::app {

Status WindowRecording::start(const std::string& path, int width, int height, long totalFrames) {
  std::string error;
  if (!recorder_.open(path, width, height, kRecordFps, &error)) return Error{error};
  total_ = totalFrames;
  started_ = std::chrono::steady_clock::now();
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
  if (total_ > 0) printProgress();
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
void WindowRecording::printProgress() const {
  const long done = recorder_.frames();
  const bool tty = ::isatty(STDERR_FILENO) != 0;
  if (!tty && done != total_ && done % std::max<long>(1, total_ / 10) != 0) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  const double left = elapsed / static_cast<double>(done) * static_cast<double>(total_ - done);
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(kWidth * done / total_);
  std::fprintf(stderr, "%s[record] [%s%s] %ld/%ld frames, %.0f s elapsed, ~%.0f s left%s", tty ? "\r" : "",
               std::string(static_cast<std::size_t>(filled), '#').c_str(),
               std::string(static_cast<std::size_t>(kWidth - filled), ' ').c_str(), done, total_, elapsed, left,
               tty && done < total_ ? "" : "\n");
}

}  // namespace pba::app
