#include "app/runner/command_line.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "app/runner/message_text.h"
#include "app/runner/scene_registry.h"
#include "app/runner/scene_runner.h"
#include "graphics/frame_recorder.h"

namespace pba::app {
namespace {

Result<long> parseWhole(const std::string& option, const std::string& text, long min) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || v < min)
    return Error{option + ": expected a whole number >= " + std::to_string(min) + ", got '" + shownText(text) + "'"};
  return v;
}

Result<double> parsePositive(const std::string& option, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v) || v <= 0.0)
    return Error{option + ": expected a number > 0, got '" + shownText(text) + "'"};
  return v;
}

/// "1920x1080" → (1920, 1080) within the window bounds of command_line.h.
Result<std::pair<int, int>> parseSize(const std::string& text) {
  const Error bad{"--size: expected WIDTHxHEIGHT in pixels, " + std::to_string(kMinWindowWidth) + "-" +
                  std::to_string(kMaxWindowSide) + " by " + std::to_string(kMinWindowHeight) + "-" +
                  std::to_string(kMaxWindowSide) + " (e.g. 1920x1080), got '" + shownText(text) + "'"};
  const auto x = text.find_first_of("xX");
  if (x == std::string::npos) return bad;
  auto side = [](const std::string& t, int min) -> std::optional<int> {
    if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos || t.size() > 5) return std::nullopt;
    const int v = std::atoi(t.c_str());
    if (v < min || v > kMaxWindowSide) return std::nullopt;
    return v;
  };
  const auto w = side(text.substr(0, x), kMinWindowWidth), h = side(text.substr(x + 1), kMinWindowHeight);
  if (!w || !h) return bad;
  return std::make_pair(*w, *h);
}

const LabFlag* findLabFlag(const std::string& flag) {
  for (const LabFlag& f : labFlags())
    if (f.flag == flag) return &f;
  return nullptr;
}

}  // namespace

long LabOptions::frameCount() const {
  if (frames) return *frames;
  // A positive time shorter than a frame still runs one frame (--seconds 1e-60 once gave 0 frames).
  if (seconds) return std::max(1L, static_cast<long>(std::ceil(*seconds / kDisplayFrame - 1e-9)));
  if (!record.empty()) return kDefaultRecordFrames;
  return screenshot.empty() ? kDefaultHeadlessFrames : kDefaultScreenshotFrames;
}

bool looksLikeSceneFile(const std::string& scene) {
  return scene.find('/') != std::string::npos || (scene.size() > 5 && scene.compare(scene.size() - 5, 5, ".json") == 0);
}

Result<LabOptions> parseCommandLine(int argc, const char* const* argv) {
  LabOptions o;
  int impliedPriority = 0;  // of the lab flag that set o.impliedScene
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    std::string value;
    bool hasInlineValue = false;
    // --option=value; for --set=NAME=VALUE the value is everything after the first '='.
    if (const auto eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      hasInlineValue = true;
    }
    auto next = [&](std::string& out) -> Status {
      if (hasInlineValue) {
        out = value;
        return Status::success();
      }
      if (i + 1 >= argc) return Error{shownText(arg) + ": missing value"};
      out = argv[++i];
      return Status::success();
    };
    auto flagOnly = [&]() -> Status {
      return hasInlineValue ? Status(Error{shownText(arg) + ": takes no value"}) : Status::success();
    };
    std::string v;
    Status s;
    if (arg == "--help" || arg == "-h") {
      s = flagOnly();
      o.help = true;
    } else if (arg == "--headless") {
      s = flagOnly();
      o.headless = true;
    } else if (arg == "--lecture") {
      s = flagOnly();
      o.lecture = true;
    } else if (arg == "--check-extremes") {
      s = flagOnly();
      o.checkExtremes = true;
    } else if (arg == "--check-golden" || arg == "--update-golden") {
      if (!o.goldenFile.empty()) return Error{"--check-golden and --update-golden: give one of them once"};
      if (!(s = next(o.goldenFile))) return Error{s.error()};
      if (o.goldenFile.empty()) return Error{arg + ": expected a file name"};
      o.goldenUpdate = arg == "--update-golden";
    } else if (arg == "--soak") {
      if (!(s = next(v))) return Error{s.error()};
      auto r = parsePositive(arg, v);
      if (!r || r.value() > kMaxSeconds)
        return Error{"--soak: expected a number of wall-clock seconds in (0, 100000], got '" + shownText(v) + "'"};
      o.soakSeconds = r.value();
    } else if (arg == "--list-scenes") {
      s = flagOnly();
      o.listScenes = true;
    } else if (arg == "--scene") {
      s = next(o.scene);
    } else if (arg == "--screenshot") {
      s = next(o.screenshot);
    } else if (arg == "--record") {
      if (!(s = next(o.record))) return Error{s.error()};
      if (!graphics::recordFormatOf(o.record))
        return Error{"--record: expected FILE.mp4, FILE.gif or DIR/ (PNG files), got '" + shownText(o.record) + "'"};
    } else if (arg == "--size") {
      if (!(s = next(v))) return Error{s.error()};
      auto r = parseSize(v);
      if (!r) return Error{r.error()};
      o.size = r.value();
    } else if (arg == "--record-ui") {
      if (!(s = next(v))) return Error{s.error()};
      if (v != "on" && v != "off") return Error{"--record-ui: expected on or off, got '" + shownText(v) + "'"};
      o.recordUi = v == "on";
    } else if (arg == "--metrics") {
      s = next(o.metrics);
    } else if (arg == "--pose-json") {
      s = next(o.poseJson);
    } else if (arg == "--frames") {
      if (!(s = next(v))) return Error{s.error()};
      auto r = parseWhole(arg, v, 1);
      if (!r || r.value() > kMaxFrames)
        return Error{"--frames: expected a whole number in [1, " + std::to_string(kMaxFrames) + "], got '" +
                     shownText(v) + "'"};
      o.frames = r.value();
    } else if (arg == "--demo") {
      s = next(o.demo);
    } else if (arg == "--demo-next") {
      s = next(o.demoNext);
    } else if (arg == "--demo-check") {
      s = flagOnly();
      o.demoCheck = true;
    } else if (arg == "--demo-step") {
      if (!(s = next(v))) return Error{s.error()};
      auto r = parseWhole(arg, v, 1);
      if (!r || r.value() > 10000) return Error{"--demo-step: expected a step number in [1, 10000], got '" + v + "'"};
      o.demoStep = r.value();
    } else if (arg == "--check-rewind") {
      if (!(s = next(v))) return Error{s.error()};
      auto r = parseWhole(arg, v, 1);
      if (!r || r.value() > kMaxFrames)
        return Error{"--check-rewind: expected a whole number of frames in [1, " + std::to_string(kMaxFrames) +
                     "], got '" + v + "'"};
      o.checkRewind = r.value();
    } else if (arg == "--compare") {
      if (hasInlineValue) return Error{"--compare: expected two settings after it: --compare \"A\" \"B\""};
      if (i + 2 >= argc) return Error{"--compare: expected two settings, e.g. --compare \"dt=0.0167\" \"dt=0.0042\""};
      const std::string a = argv[i + 1], b = argv[i + 2];
      i += 2;
      o.compare = std::make_pair(a, b);
    } else if (arg == "--seconds") {
      if (!(s = next(v))) return Error{s.error()};
      auto r = parsePositive(arg, v);
      if (!r || r.value() > kMaxSeconds)
        return Error{"--seconds: expected a number in (0, 100000] s, got '" + shownText(v) + "'"};
      o.seconds = r.value();
    } else if (arg == "--dt") {
      if (!(s = next(v))) return Error{s.error()};
      auto r = parsePositive(arg, v);
      if (!r) return Error{r.error()};
      if (r.value() < kMinDt || r.value() > kMaxDt)
        return Error{"--dt: must be in [" + std::to_string(kMinDt) + ", " + std::to_string(kMaxDt) + "] s, got '" +
                     shownText(v) + "'"};
      o.dt = r.value();
    } else if (arg == "--substeps") {
      if (!(s = next(v))) return Error{s.error()};
      auto r = parseWhole(arg, v, 1);
      if (!r || r.value() > kMaxSubsteps)
        return Error{"--substeps: expected a whole number in [1, " + std::to_string(kMaxSubsteps) + "], got '" +
                     shownText(v) + "'"};
      o.substeps = static_cast<int>(r.value());
    } else if (arg == "--time-scale") {
      if (!(s = next(v))) return Error{s.error()};
      auto r = parsePositive(arg, v);
      if (!r || r.value() < kMinTimeScale || r.value() > kMaxTimeScale)
        return Error{"--time-scale: expected a number in [0.1, 4], got '" + shownText(v) + "'"};
      o.timeScale = r.value();
    } else if (arg == "--seed") {
      if (!(s = next(v))) return Error{s.error()};
      auto r = parseWhole(arg, v, 0);
      if (!r) return Error{r.error()};
      o.seed = static_cast<std::uint64_t>(r.value());
    } else if (arg == "--set") {
      if (!(s = next(v))) return Error{s.error()};
      const auto eq = v.find('=');
      if (eq == std::string::npos || eq == 0) return Error{"--set: expected NAME=VALUE, got '" + shownText(v) + "'"};
      o.overrides.push_back({v.substr(0, eq), v.substr(eq + 1), "--set"});
    } else if (const LabFlag* f = arg.rfind("--", 0) == 0 ? findLabFlag(arg.substr(2)) : nullptr) {
      if (!(s = next(v))) return Error{s.error()};
      o.overrides.push_back({f->param, v, arg});
      if (!f->impliesScene.empty() && (o.impliedScene.empty() || f->priority >= impliedPriority)) {
        o.impliedScene = f->impliesScene;
        impliedPriority = f->priority;
      }
    } else {
      return Error{"unknown option '" + shownText(arg) + "' (see --help)"};
    }
    if (!s) return Error{s.error()};
  }
  if (o.frames && o.seconds) return Error{"--frames and --seconds: give one or the other"};
  if (o.headless && !o.screenshot.empty())
    return Error{"--screenshot needs a window: drop --headless (use xvfb-run without a display)"};
  if (o.headless && !o.record.empty())
    return Error{"--record needs a window: drop --headless (use xvfb-run without a display)"};
  if (o.headless && o.size) return Error{"--size sets the window's size: drop --headless"};
  if (!o.record.empty() && !o.screenshot.empty()) return Error{"--record and --screenshot: give one or the other"};
  if (o.checkRewind && !o.headless) return Error{"--check-rewind runs headless: add --headless"};
  if (o.checkRewind && o.compare) return Error{"--check-rewind and --compare: give one or the other"};
  if (!o.poseJson.empty() && (o.compare || o.checkRewind || !o.demo.empty() || o.checkExtremes))
    return Error{
        "--pose-json: writes the pose of one plain run (drop --compare, --check-rewind, --demo, --check-extremes)"};
  if (o.demo.empty() && (o.demoCheck || !o.demoNext.empty()))
    return Error{"--demo-check and --demo-next go with --demo FILE"};
  if (!o.demo.empty() && (!o.scene.empty() || o.compare))
    return Error{"--demo: the script chooses the scenes (drop --scene and --compare)"};
  return o;
}

std::string overrideError(const ParamOverride& o, const std::string& error) {
  if (o.option == "--set") return "--set " + error;
  const std::string prefix = o.param + ": ";
  return o.option + ": " + (error.rfind(prefix, 0) == 0 ? error.substr(prefix.size()) : error);
}

std::string usage(const std::string& lab) {
  std::string text =
      "Usage: pba-" + lab +
      " [options]\n"
      "\n"
      "  --scene NAME|FILE.json  scene to start (default: the first; see --list-scenes)\n"
      "  --headless              no window and no OpenGL: step the scene and exit\n"
      "  --frames N              frames of 1/60 s to run headless or before a screenshot\n"
      "                          (default 300 headless, 120 for --screenshot)\n"
      "  --seconds T             simulated seconds instead of --frames (at most 100000)\n"
      "  --dt H                  fixed time step in seconds (default: the scene's)\n"
      "  --substeps N            split each step into N substeps (1-64)\n"
      "  --time-scale S          slow motion or fast forward, 0.1-4\n"
      "  --screenshot FILE.png   open the window, render, save the image, exit (works under xvfb-run)\n"
      "  --record FILE.mp4|FILE.gif|DIR/\n"
      "                          record --frames (default 300) or --seconds of simulated time at 60\n"
      "                          frames/s, then exit: MP4 and GIF through ffmpeg, PNG files into DIR/\n"
      "  --size WxH              the window's size in pixels, e.g. 1920x1080 (default 1280x720 for\n"
      "                          --screenshot and --record, else the size the lab saved)\n"
      "  --record-ui on|off      the panels in the recording, or the scene alone (default off)\n"
      "  --metrics FILE|-        write the run's metrics as one JSON object (- = standard output)\n"
      "  --pose-json FILE        when the run ends, write the world position [m] of every joint of the\n"
      "                          scene's skeleton, by name (scenes with a skeleton only)\n"
      "  --seed N                random seed (default 1)\n"
      "  --compare \"A\" \"B\"       two copies of the scene side by side in lock-step, each with its own\n"
      "                          settings: NAME=VALUE pairs separated by spaces (dt, substeps,\n"
      "                          time_scale or scene parameters); headless metrics hold \"a\" and \"b\"\n"
      "  --check-rewind N        (with --headless) run N frames, save the state, run N, restore, run N\n"
      "                          again: exit 0 when both runs agree bit for bit, 1 when they differ\n"
      "  --set NAME=VALUE        set any scene parameter (see the scene's panel for names)\n"
      "  --lecture               large fonts, high contrast (key L toggles)\n"
      "  --list-scenes           print the scenes and exit\n"
      "  --help                  this text\n"
      "  --check-extremes        test mode: run every scene with each numeric parameter at its\n"
      "                          minimum and maximum (--frames, default 60; --scene to pick one)\n"
      "                          and check that values just outside are refused; exit 1 on failure\n"
      "  --check-golden FILE     test mode: run every scene --frames (default: the file's) from its\n"
      "                          defaults and compare its state with FILE (tests/golden/LAB.json)\n"
      "  --update-golden FILE    rewrite FILE from this build (./pba golden --update: every lab)\n"
      "  --soak SECONDS          test mode: scripted drags, parameter changes, presets, resets and scene\n"
      "                          switches from --seed for SECONDS of wall time; exit 1 on a NaN in an\n"
      "                          untouched scene, a stalled frame or resident memory growing > 1 %\n";

  if (!labFlags().empty()) {
    text += "\nLab options:\n";
    for (const LabFlag& f : labFlags()) {
      const std::string option = "--" + f.flag + " VALUE";
      text += "  " + option + std::string(option.size() < 24 ? 24 - option.size() : 1, ' ') + f.help + " (parameter '" +
              f.param + "'" + (f.impliesScene.empty() ? std::string() : "; selects scene '" + f.impliesScene + "'") +
              ")\n";
    }
  }
  if (!labKeys().empty()) {
    text += "\nScene keys:\n";
    for (const LabKey& k : labKeys())
      text += std::string("  ") + k.key + "  (scene " + k.scene + ") " + k.action + "\n";
  }
  text +=
      "\nKeys: Space/P pause  O step  , . back / forward one step (Shift: 1 s)  R reset  [ ] scene  1-9 presets\n"
      "      F1/H help  F12 screenshot  F9 record\n"
      "      L lecture mode  Tab hide UI  F frame scene.  Arrows nudge the target in the view plane,\n"
      "      PageUp/PageDown or Shift+Up/Down away/toward the camera, Ctrl for a fine step.\n"
      "      Mouse: left drag picks, right drag orbits, middle or Shift+right drag pans, wheel zooms.\n"
      "Exit codes: 0 success, 1 internal failure, 2 bad arguments or input file, 3 a --headless run that the\n"
      "            instability guard paused (metrics still written, \"paused_by_guard\": true).\n";
  return text;
}

}  // namespace pba::app
