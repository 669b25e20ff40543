// Screenshots with glReadPixels + stb_image_write; image statistics with stb_image.
#include "graphics/screenshot.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include "graphics/gl.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_set>
#include <vector>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

namespace pba::graphics {
namespace {

#ifdef __EMSCRIPTEN__
// In the browser the PNG lands in the page's in-memory file system: hand it to the user as a download.
EM_JS(void, offerDownload, (const char* path), {
  var name = UTF8ToString(path);
  var link = document.createElement('a');
  link.href = URL.createObjectURL(new Blob([FS.readFile(name)]));
  link.download = name.split('/').pop();
  link.click();
});
#else
void offerDownload(const char*) {}
#endif

}  // namespace

bool readFramebuffer(int width, int height, std::vector<unsigned char>& rgb, std::string* error) {
  if (width <= 0 || height <= 0) {
    if (error)
      *error = "cannot capture an empty framebuffer (" + std::to_string(width) + "x" + std::to_string(height) + ")";
    return false;
  }
  const auto w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
  std::vector<unsigned char> rgba(w * h * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  const GLenum glError = glGetError();
  if (glError != GL_NO_ERROR) {
    if (error) *error = "glReadPixels failed with OpenGL error " + std::to_string(glError);
    return false;
  }
  // OpenGL rows go bottom-up; images top-down. Drop alpha (the window is opaque).
  rgb.resize(w * h * 3);
  for (std::size_t y = 0; y < h; ++y) {
    const unsigned char* src = &rgba[(h - 1 - y) * w * 4];
    unsigned char* dst = &rgb[y * w * 3];
    for (std::size_t x = 0; x < w; ++x) std::memcpy(dst + 3 * x, src + 4 * x, 3);
  }
  return true;
}

bool saveScreenshot(const std::string& path, int width, int height, std::string* error) {
  std::vector<unsigned char> rgb;
  std::string why;
  if (!readFramebuffer(width, height, rgb, &why)) {
    if (error) *error = path + ": " + why;
    return false;
  }
  errno = 0;
  if (stbi_write_png(path.c_str(), width, height, 3, rgb.data(), width * 3) == 0) {
    if (error) *error = path + ": cannot write PNG" + (errno ? std::string(" (") + std::strerror(errno) + ")" : "");
    return false;
  }
  offerDownload(path.c_str());
  return true;
}

bool imageStats(const std::string& path, ImageStats* stats, std::string* error) {
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!pixels) {
    if (error)
      *error = path + ": cannot read image (" + std::string(stbi_failure_reason() ? stbi_failure_reason() : "?") + ")";
    return false;
  }
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  std::unordered_set<std::uint32_t> colors;
  double sum = 0.0, sumSq = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char* p = pixels + 3 * i;
    colors.insert((std::uint32_t{p[0]} << 16) | (std::uint32_t{p[1]} << 8) | std::uint32_t{p[2]});
    const double luma = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    sum += luma;
    sumSq += luma * luma;
  }
  stbi_image_free(pixels);
  ImageStats s;
  s.width = w;
  s.height = h;
  s.distinctColors = static_cast<int>(colors.size());
  if (n > 0) {
    s.meanLuminance = sum / static_cast<double>(n);
    s.luminanceStdDev = std::sqrt(std::max(0.0, sumSq / static_cast<double>(n) - s.meanLuminance * s.meanLuminance));
  }
  if (stats) *stats = s;
  return true;
}

}  // namespace pba::graphics
