// Recording a lab's window (--record, F9, the Record button): one frame of video for every displayed
// frame, each exactly 1/60 s of simulated time while recording, so slow hardware or software rendering
// still gives smooth video at real speed. Progress goes to the terminal (command line recordings) and
// to the window's title and View panel (ui.recording).
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "app/runner/progress_line.h"
#include "graphics/frame_recorder.h"
#include "physics/core/result.h"

namespace pba::app {

inline constexpr int kRecordFps = 60;  ///< frames of video per second of simulated time (1/kDisplayFrame)

class WindowRecording {
 public:
  /// A command line recording of `totalFrames` frames at `path`.
  Status start(const std::string& path, int width, int height, long totalFrames);
  /// F9: starts a recording named after the lab, scene and time (MP4 with ffmpeg, else a PNG folder), or
  /// stops the running one. Returns what to tell the user.
  std::string toggle(const std::string& lab, const std::string& scene, int width, int height);
  bool active() const { return recorder_.active(); }
  long frames() const { return recorder_.frames(); }
  /// Reads the frame just rendered (before swapBuffers) into the recording.
  Status capture(int width, int height);
  /// Finishes the file; returns "Recorded N frames (T s) to PATH", or the error.
  Result<std::string> finish();
  /// Share of a command line recording done, in [0, 1]; negative for F9's (no end set) or none.
  double fraction() const { return active() && total_ > 0 ? double(recorder_.frames()) / double(total_) : -1.0; }
  /// "REC 3.2 s (192 frames)" or "REC 40/120 frames" while recording, else empty.
  std::string statusText() const;

 private:
  graphics::FrameRecorder recorder_;
  long total_ = 0;  ///< 0: until stopped (F9)
  std::chrono::steady_clock::time_point started_;
  std::vector<unsigned char> rgb_;
  std::optional<ProgressLine> progress_;
};

}  // namespace pba::app
