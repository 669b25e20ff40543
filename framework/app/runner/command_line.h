#pragma once
// The command line contract of every lab executable (docs/architecture.md §4):
//   pba-<lab> [--scene NAME|FILE.json] [--headless] [--frames N | --seconds T] [--dt H]
//             [--screenshot FILE.png] [--metrics FILE|-] [--seed N] [--lecture] [--list-scenes] [--help]
//             [--record FILE.mp4|FILE.gif|DIR/ [--record-ui on|off]] [--compare "A" "B"] [--check-rewind N]
//             [--pose-json FILE] [--check-golden FILE | --update-golden FILE] [--soak SECONDS]
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
inline constexpr int kDefaultRecordFrames = 300;      // 5 s of video
inline constexpr long kMaxFrames = 6'000'000;         // 100,000 s (over a day) of simulated time
inline constexpr double kMaxSeconds = 100'000.0;      // [s] the same bound for --seconds
inline constexpr int kMinWindowWidth = 320;           // [px] --size and the saved window size
inline constexpr int kMinWindowHeight = 240;          // [px]
inline constexpr int kMaxWindowSide = 8192;           // [px] either side

/// A scene parameter set on the command line, with the option that set it ("--set" or a lab flag
/// such as "--links"), so that an error names what the user typed.
struct ParamOverride {
  std::string param;   ///< parameter name
  std::string value;   ///< text value
  std::string option;  ///< "--set" or "--<flag>"
  bool operator==(const ParamOverride&) const = default;
};

struct LabOptions {
  std::string scene;  ///< scene name or path of a .json scene file; empty = first scene
  bool headless = false;
  std::optional<long> frames;     ///< displayed frames of 1/60 s each
  std::optional<double> seconds;  ///< alternatively: simulated seconds
  std::optional<double> dt;       ///< fixed step [s]
  std::optional<int> substeps;
  std::optional<double> timeScale;
  std::string screenshot;  ///< PNG path: render this many frames in a window, save, exit
  std::string record;      ///< video (.mp4, .gif) or PNG folder: record this many frames in a window, exit
  /// --size WxH: the window's size [px] for this run (screenshots and recordings default to 1280×720,
  /// the window to its saved size).
  std::optional<std::pair<int, int>> size;
  bool recordUi = false;  ///< --record-ui on: the panels are in the recording (default: the scene alone)
  std::string metrics;    ///< JSON path or "-" for stdout
  std::string poseJson;   ///< --pose-json FILE: every joint's world position, by name, when the run ends
  std::uint64_t seed = 1;
  bool lecture = false;
  bool listScenes = false;
  bool help = false;
  /// --compare "A" "B": two runs of the scene side by side, each with its own settings, a list of
  /// NAME=VALUE separated by spaces (dt, substeps, time_scale or any scene parameter).
  std::optional<std::pair<std::string, std::string>> compare;
  /// --check-rewind N (headless): run N frames, save, run N, restore, run N again; the states must agree.
  std::optional<long> checkRewind;
  /// --demo FILE: play a lecture demo script (demo_script.h) from step demoStep (1-based); --demo-next PATH
  /// receives the step to go on with when the next one belongs to another lab (./pba demo starts it);
  /// --demo-check validates this lab's steps and exits.
  std::string demo;
  long demoStep = 1;
  std::string demoNext;
  bool demoCheck = false;
  /// Test mode: every numeric parameter of every scene at its extremes (app/checks/param_extremes.h).
  bool checkExtremes = false;
  /// Test mode (app/checks/golden_check.h): --check-golden FILE compares every scene's state after a fixed run
  /// with FILE; --update-golden FILE rewrites it.
  std::string goldenFile;
  bool goldenUpdate = false;
  /// Test mode (app/checks/soak_run.h): --soak SECONDS of scripted interaction with every scene from --seed.
  std::optional<double> soakSeconds;
  /// Parameter overrides in command line order.
  std::vector<ParamOverride> overrides;
  /// Scene selected by a lab flag (LabFlag::impliesScene) when --scene is not given.
  std::string impliedScene;

  /// Number of frames to run in headless, screenshot and record mode.
  long frameCount() const;
};

/// Parses argv. Errors name the option ("--frames: expected a whole number >= 1, got 'x'").
/// --frames is at most kMaxFrames and --seconds at most kMaxSeconds.
Result<LabOptions> parseCommandLine(int argc, const char* const* argv);
/// The --help text of lab `lab`.
std::string usage(const std::string& lab);

/// The error of applying an override, naming the option typed: a lab flag's message replaces the
/// parameter name by the flag ("--links: must be in [1, 1000], got 0"); --set keeps it ("--set
/// links: ..."). `error` is Params::setFromText's message ("links: ...").
std::string overrideError(const ParamOverride& o, const std::string& error);

/// True when `scene` names a file rather than a registered scene.
bool looksLikeSceneFile(const std::string& scene);

}  // namespace pba::app
