// Recording the window: a fixed number of frames a second of simulated time, written as an MP4 or a
// GIF through the system's ffmpeg (raw RGB frames on a pipe) or as a numbered PNG sequence without it.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace pba::graphics {

enum class RecordFormat { Mp4, Gif, PngSequence };

/// The format a path asks for: "*.mp4", "*.gif", or a folder ("DIR/", or a name without an extension)
/// for PNG files. nullopt for anything else ("x.avi").
std::optional<RecordFormat> recordFormatOf(const std::string& path);
/// The ffmpeg executable on PATH, or empty when there is none.
std::string findFfmpeg();

class FrameRecorder {
 public:
  FrameRecorder() = default;
  FrameRecorder(const FrameRecorder&) = delete;
  FrameRecorder& operator=(const FrameRecorder&) = delete;
  ~FrameRecorder();

  /// Starts a recording of width × height frames at `fps` frames per second of video. false + *error
  /// naming the path: unknown format, no ffmpeg for MP4/GIF (names the package), a folder that cannot
  /// be made, ffmpeg that does not start.
  bool open(const std::string& path, int width, int height, int fps, std::string* error);
  /// Appends one frame: width × height RGB bytes, rows top-down.
  bool addFrame(const std::vector<unsigned char>& rgb, std::string* error);
  /// Finishes the file (waits for ffmpeg). false + *error when ffmpeg failed.
  bool close(std::string* error);

  bool active() const { return active_; }
  long frames() const { return frames_; }
  int fps() const { return fps_; }
  const std::string& path() const { return path_; }

 private:
  bool active_ = false;
  RecordFormat format_ = RecordFormat::PngSequence;
  std::string path_;
  int width_ = 0, height_ = 0, fps_ = 60;
  long frames_ = 0;
  std::FILE* pipe_ = nullptr;
};

}  // namespace pba::graphics
