// FrameRecorder: ffmpeg through a pipe (rawvideo rgb24 on stdin), PNG files through stb_image_write.
#include "graphics/frame_recorder.h"

#include <stb_image_write.h>

#include <cstdlib>
#include <filesystem>

#include "graphics/child_process.h"

namespace pba::graphics {
namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

std::optional<RecordFormat> recordFormatOf(const std::string& path) {
  if (path.empty()) return std::nullopt;
  if (endsWith(path, ".mp4")) return RecordFormat::Mp4;
  if (endsWith(path, ".gif")) return RecordFormat::Gif;
  if (path.back() == '/' || std::filesystem::path(path).extension().empty()) return RecordFormat::PngSequence;
  return std::nullopt;
}

std::string findFfmpeg() { return findProgramOnPath("ffmpeg"); }

FrameRecorder::~FrameRecorder() {
  if (active_) close(nullptr);
}

bool FrameRecorder::open(const std::string& path, int width, int height, int fps, std::string* error) {
  auto fail = [&](const std::string& why) {
    if (error) *error = path + ": " + why;
    return false;
  };
  const std::optional<RecordFormat> format = recordFormatOf(path);
  if (!format) return fail("cannot record this format: give FILE.mp4, FILE.gif or DIR/ (a PNG sequence)");
  if (width <= 0 || height <= 0 || fps <= 0) return fail("nothing to record (an empty window)");
  format_ = *format;
  path_ = path;
  width_ = width;
  height_ = height;
  fps_ = fps;
  frames_ = 0;
  if (format_ == RecordFormat::PngSequence) {
    std::error_code ec;
    std::filesystem::create_directories(path, ec);
    if (ec) return fail("cannot make the folder (" + ec.message() + ")");
    active_ = true;
    return true;
  }
  const std::string ffmpeg = findFfmpeg();
  if (ffmpeg.empty())
    return fail(
        "recording MP4 or GIF needs ffmpeg on the PATH (apt-get, brew or winget install ffmpeg); "
        "or record PNG files: --record DIR/");
  const std::string input = " -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgb24 -s " + std::to_string(width) +
                            "x" + std::to_string(height) + " -r " + std::to_string(fps) + " -i -";
  // MP4: H.264 in yuv420p (players want even sizes); GIF: 30 frames/s (GIF delays are in 1/100 s) with
  // a palette computed from the whole clip.
  const std::string output =
      format_ == RecordFormat::Mp4
          ? " -c:v libx264 -preset veryfast -crf 20 -pix_fmt yuv420p -vf " +
                quotedArgument("scale=trunc(iw/2)*2:trunc(ih/2)*2") + " -movflags +faststart "
          : " -vf " + quotedArgument("fps=30,split[a][b];[a]palettegen[p];[b][p]paletteuse") + " -loop 0 ";
  // A failed ffmpeg gives a write error, not the end of the lab (openWritePipe ignores SIGPIPE).
  pipe_ = openWritePipe(quotedArgument(ffmpeg) + input + output + quotedArgument(path));
  if (!pipe_) return fail("cannot start ffmpeg");
  active_ = true;
  return true;
}

bool FrameRecorder::addFrame(const std::vector<unsigned char>& rgb, std::string* error) {
  if (!active_) return false;
  const std::size_t bytes = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 3;
  if (rgb.size() != bytes) {
    if (error) *error = path_ + ": a frame of the wrong size (the window was resized while recording)";
    return false;
  }
  ++frames_;
  if (format_ == RecordFormat::PngSequence) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%06ld.png", frames_);
    const std::string file = (std::filesystem::path(path_) / name).string();
    if (stbi_write_png(file.c_str(), width_, height_, 3, rgb.data(), width_ * 3) == 0) {
      if (error) *error = file + ": cannot write PNG";
      return false;
    }
    return true;
  }
  if (std::fwrite(rgb.data(), 1, bytes, pipe_) != bytes) {
    if (error) *error = path_ + ": ffmpeg stopped reading frames";
    return false;
  }
  return true;
}

bool FrameRecorder::close(std::string* error) {
  if (!active_) return true;
  active_ = false;
  if (!pipe_) return true;
  const int status = closeWritePipe(pipe_);
  pipe_ = nullptr;
  if (status != 0) {
    if (error) *error = path_ + ": ffmpeg failed (exit " + std::to_string(status) + ")";
    return false;
  }
  return true;
}

}  // namespace pba::graphics
