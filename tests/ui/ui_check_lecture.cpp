// The lecture-layout check (issue 35): lecture mode keeps the scene the largest thing on screen in every
// scene, measured from the rendered image. F12 with the UI status on also writes the frame's scene alone
// (framework/app/window/scene_image.h: no UI, no ground, a flat magenta background), so every pixel of that image
// that is not the background is the scene's own; the windows of the same frame (the UI status) must leave
// those pixels uncovered.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

#include "ui_check_support.h"

namespace pba::uitest {
namespace {

namespace fs = std::filesystem;

// The share of the scene's pixels that windows may cover: a line's end or a dot's halo at a window's border,
// never a body (1 % of a scene that fills a tenth of a 1280×720 picture is a 30×30 pixel patch).
constexpr double kMaxCoveredShare = 0.01;

/// The background of the scene-alone image (graphics::kSceneOnlyBackground, sRGB magenta).
bool isBackground(const unsigned char* p) { return p[0] == 255 && p[1] == 0 && p[2] == 255; }

struct RgbImage {
  long width = 0, height = 0;
  std::vector<unsigned char> rgb;  // rows top-down
};

/// A binary PPM (P6, 8 bits) as framework/app/window/scene_image.cpp writes it; throws if the file is none.
RgbImage readPpm(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string magic;
  long maxValue = 0;
  RgbImage image;
  in >> magic >> image.width >> image.height >> maxValue;
  in.get();  // the one whitespace before the pixels
  expect(in && magic == "P6" && maxValue == 255 && image.width > 0 && image.height > 0,
         file.string() + " is not an 8-bit binary PPM");
  image.rgb.resize(static_cast<std::size_t>(image.width * image.height * 3));
  in.read(reinterpret_cast<char*>(image.rgb.data()), static_cast<std::streamsize>(image.rgb.size()));
  expect(static_cast<bool>(in), file.string() + " is cut short");
  return image;
}

struct Coverage {
  long scenePixels = 0;    // pixels of the scene in the whole image
  long coveredPixels = 0;  // of those, under a window
  std::string worst;       // the window over most of them
  long worstPixels = 0;
};

/// The scene's pixels in `image` and how many of them the `windows` (screen coordinates of a viewport
/// `viewportWidth` wide) cover.
Coverage coverage(const RgbImage& image, const std::vector<std::pair<std::string, Rect>>& windows,
                  double viewportWidth) {
  const double toScreen = viewportWidth / static_cast<double>(image.width);  // framebuffer → screen
  std::vector<long> under(windows.size(), 0);
  Coverage c;
  for (long y = 0; y < image.height; ++y)
    for (long x = 0; x < image.width; ++x) {
      if (isBackground(&image.rgb[static_cast<std::size_t>((y * image.width + x) * 3)])) continue;
      ++c.scenePixels;
      const double sx = (static_cast<double>(x) + 0.5) * toScreen, sy = (static_cast<double>(y) + 0.5) * toScreen;
      bool covered = false;
      for (std::size_t w = 0; w < windows.size(); ++w)
        if (windows[w].second.contains(sx, sy)) ++under[w], covered = true;
      c.coveredPixels += covered ? 1 : 0;
    }
  for (std::size_t w = 0; w < windows.size(); ++w)
    if (under[w] > c.worstPixels) c.worstPixels = under[w], c.worst = windows[w].first;
  return c;
}

}  // namespace

// Lecture mode keeps the scene the largest thing on screen in every scene: the panel is a narrow column,
// the windows do not overlap one another, the screen the windows leave free is larger than any of them
// (and at least 40 % of it), and they lie over none of the scene's pixels (kMaxCoveredShare).
void checkLectureLayout(const std::string& exe, const std::string& work) {
  const std::vector<std::string> list = listScenes(exe);
  LabWindow lab(exe, {"--lecture"}, work);
  pause(lab);  // every scene is then seen as its reset leaves it: the same picture on every run
  const bool keep = std::getenv("PBA_UI_SCREENSHOTS") != nullptr;  // for looking at them
  std::string failures;  // every scene is measured, and every failure named at the end
  for (size_t index = 0; index < list.size(); ++index) try {
      if (index > 0) {
        lab.key("bracketright");
        lab.waitFor([&](const json& s) { return s["scene"] == list[index]; }, "] to reach " + list[index]);
      }
      lab.frames(3);
      lab.key("F12");
      const json s = lab.waitFor(
          [&](const json& st) {
            return st["last_scene_image"].get<std::string>().find("-" + list[index] + "-") != std::string::npos;
          },
          "F12 to write " + list[index] + " alone");
      const fs::path sceneImage = fs::path(work) / s["last_scene_image"].get<std::string>();
      const Rect view{0, 0, vecAt(s["viewport"], 0), vecAt(s["viewport"], 1)};
      double windowsArea = 0.0, largest = 0.0, panelWidth = 0.0;
      auto all = windows(s);
      for (const auto& [name, r] : all) {
        windowsArea += r.intersect(view).area();
        largest = std::max(largest, r.intersect(view).area());
        if (name.find("###panel") != std::string::npos) panelWidth = r.width();
      }
      const double free = view.area() - windowsArea;
      // The banner of a stubbed exercise or of the instability guard is an alert, on top by design; the notice
      // is this check's own screenshot's, said for a few seconds.
      std::erase_if(all, [](const auto& w) { return w.first == "##banner" || w.first == "##notice"; });
      const Coverage cover = coverage(readPpm(sceneImage), all, view.width());
      // Docked, not stacked: no window hides part of another (the legend under the panel did).
      for (size_t a = 0; a < all.size(); ++a)
        for (size_t b = a + 1; b < all.size(); ++b)
          expect(all[a].second.intersect(all[b].second).area() <=
                     0.01 * std::min(all[a].second.area(), all[b].second.area()),
                 list[index] + ": the windows " + all[a].first + " and " + all[b].first + " overlap");
      const double share = static_cast<double>(cover.coveredPixels) / std::max(cover.scenePixels, 1L);
      std::printf(
          "%-14s panel %.0f%% of the width; free %.0f%% of the screen, largest window %.0f%%; scene %.1f%% of the "
          "picture, %.2f%% of it under windows (most under %s)\n",
          list[index].c_str(), 100 * panelWidth / view.width(), 100 * free / view.area(), 100 * largest / view.area(),
          100.0 * static_cast<double>(cover.scenePixels) / (view.area() > 0 ? view.area() : 1.0), 100 * share,
          cover.worst.empty() ? "none" : cover.worst.c_str());
      expect(cover.scenePixels > 0, list[index] + ": nothing of the scene in view");
      expect(panelWidth <= 0.30 * view.width(), list[index] + ": the lecture panel takes more than 30 % of the width");
      expect(free >= largest, list[index] + ": a window is larger than the part of the screen left to the scene");
      expect(free >= 0.4 * view.area(), list[index] + ": the windows leave the scene less than 40 % of the screen");
      expect(share <= kMaxCoveredShare, list[index] + ": " + std::to_string(cover.coveredPixels) + " of the scene's " +
                                            std::to_string(cover.scenePixels) +
                                            " pixels lie under windows (most under " + cover.worst + ")");
      expect(s["clipped_labels"].empty(), list[index] + ": labels cut off by the panel: " + s["clipped_labels"].dump());
      if (!keep) {
        fs::remove(sceneImage);
        fs::remove(fs::path(work) / s["last_screenshot"].get<std::string>());
      }
    } catch (const std::exception& e) {
      failures += std::string(failures.empty() ? "" : "; ") + e.what();
    }
  expect(lab.close() == 0, "the lab did not exit cleanly");
  expect(failures.empty(), failures);
}

}  // namespace pba::uitest
