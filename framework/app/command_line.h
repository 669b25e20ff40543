#pragma once
// The command line contract of every lab executable (DESIGN.md §4):
//   pba-<lab> [--scene NAME|FILE.json] [--headless] [--frames N | --seconds T] [--dt H]
//             [--screenshot FILE.png] [--metrics FILE|-] [--seed N] [--lecture] [--list-scenes] [--help]
// plus --substeps N, --time-scale S, --set NAME=VALUE (any scene parameter) and the lab's own flags.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "physics/core/result.h"

namespace pba::app {

inline constexpr int kDefaultHeadlessFrames = 300;    // 5 s of simulated time at 60 frames/s
inline constexpr int kDefaultScreenshotFrames = 120;  // 2 s: scenes have started moving

struct LabOptions {
  std::string scene;                 ///< scene name or path of a .json scene file; empty = first scene
  bool headless = false;
  std::optional<long> frames;        ///< displayed frames of 1/60 s each
  std::optional<double> seconds;     ///< alternatively: simulated seconds
  std::optional<double> dt;          ///< fixed step [s]
  std::optional<int> substeps;
  std::optional<double> timeScale;
  std::string screenshot;            ///< PNG path: render this many frames in a window, save, exit
  std::string metrics;               ///< JSON path or "-" for stdout
  std::uint64_t seed = 1;
  bool lecture = false;
  bool listScenes = false;
  bool help = false;
  /// Parameter overrides in command line order: (name, text value).
  std::vector<std::pair<std::string, std::string>> overrides;
  /// Scene selected by a lab flag (LabFlag::impliesScene) when --scene is not given.
  std::string impliedScene;

  /// Number of frames to run in headless and screenshot mode.
  long frameCount() const;
};

/// Parses argv. Errors name the option ("--frames: expected a whole number >= 1, got 'x'").
Result<LabOptions> parseCommandLine(int argc, const char* const* argv);
/// The --help text of lab `lab`.
std::string usage(const std::string& lab);

/// True when `scene` names a file rather than a registered scene.
bool looksLikeSceneFile(const std::string& scene);

}  // namespace pba::app
