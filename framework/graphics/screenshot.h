// Screenshots: read the current framebuffer into a PNG (needs GL), and imageStats, a CPU-only check
// that a PNG is not blank (used by the smoke tests of the labs).
#pragma once

#include <string>
#include <vector>

namespace pba::graphics {

/// Reads the default framebuffer's back buffer (call before swapBuffers) into `rgb`: width × height
/// RGB bytes, rows top-down. false + *error on an empty framebuffer or an OpenGL error.
bool readFramebuffer(int width, int height, std::vector<unsigned char>& rgb, std::string* error);

/// readFramebuffer, then an RGB PNG at `path`. false + *error naming the path on failure.
bool saveScreenshot(const std::string& path, int width, int height, std::string* error);

struct ImageStats {
  int width = 0;
  int height = 0;
  int distinctColors = 0;      ///< distinct RGB triples
  double luminanceStdDev = 0;  ///< of Rec. 709 luma in [0, 255]
  double meanLuminance = 0;    ///< [0, 255]
};

/// Loads a PNG (or any stb_image format) and measures it. false + *error naming the path on failure.
bool imageStats(const std::string& path, ImageStats* stats, std::string* error);

}  // namespace pba::graphics
