#include "app/lab.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <tuple>

#include "app/checks/golden_check.h"
#include "app/checks/param_extremes.h"
#include "app/checks/soak_run.h"
#include "app/runner/compare_run.h"
#include "app/runner/message_text.h"
#include "app/runner/metrics_report.h"
#include "app/runner/pose_json.h"
#include "app/runner/progress_line.h"
#include "app/runner/scene_file.h"
#include "app/runner/scene_registry.h"
#include "physics/exercises/not_implemented.h"

namespace pba::app {

Status prepareRunner(const std::string& lab, const LabOptions& o, SceneRunner& runner) {
  if (scenes().empty()) return Error{"this lab registers no scenes"};
  if (o.dt) {
    if (Status s = runner.setDt(*o.dt); !s) return Error{"--" + s.error()};
  }
  if (o.substeps) {
    if (Status s = runner.setSubsteps(*o.substeps); !s) return Error{"--" + s.error()};
  }
  if (o.timeScale) {
    if (Status s = runner.setTimeScale(*o.timeScale); !s) return Error{"--" + s.error()};
  }
  std::unique_ptr<Scene> scene;
  std::string name;
  if (looksLikeSceneFile(o.scene)) {
    Result<LoadedScene> loaded = loadSceneFile(o.scene, lab);
    if (!loaded) return Error{loaded.error()};
    scene = std::move(loaded.value().scene);
    name = loaded.value().name;
    if (loaded.value().dt && !o.dt) {
      if (Status s = runner.setDt(*loaded.value().dt); !s) return Error{oneLine(o.scene) + ": " + s.error()};
    }
  } else {
    name = !o.scene.empty() ? o.scene : !o.impliedScene.empty() ? o.impliedScene : scenes().front().name;
    const SceneEntry* entry = findScene(name);
    if (!entry) return Error{"--scene: unknown scene '" + shownText(name) + "' (see --list-scenes)"};
    scene = entry->create();
  }
  for (const ParamOverride& p : o.overrides) {
    if (Status s = scene->params().setFromText(p.param, p.value); !s) {
      // A lab flag meant for another scene: say which scene it belongs with.
      if (!scene->params().find(p.param) && p.option != "--set")
        return Error{p.option + ": not a parameter of scene '" + name +
                     "' (see --help for the scene each lab option selects)"};
      return Error{overrideError(p, s.error())};
    }
  }
  scene->setSeed(o.seed);
  if (Status s = scene->validate(); !s) {
    // What a scene file named (a model file, joint names) is that file's error: name it and the field.
    if (looksLikeSceneFile(o.scene) && o.overrides.empty()) return Error{oneLine(o.scene) + ": params." + s.error()};
    return s;
  }
  runner.adopt(std::move(scene), name);
  if (!o.poseJson.empty()) return checkPoseJson(runner);  // refused before the run, not after it
  return Status::success();
}

int runHeadless(const std::string& lab, const LabOptions& o, SceneRunner& runner) {
  const long frames = o.frameCount();
  // A long run (a batch of IK solves, a soak) shows its progress on a terminal; piped, it prints nothing.
  ProgressLine progress("pba-" + lab, frames, "frames", /*piped=*/false);
  const auto start = std::chrono::steady_clock::now();
  for (long f = 0; f < frames; ++f) {
    runner.advanceFrame(kDisplayFrame);
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(1)) progress.update(f + 1);
  }
  if (runner.guardMessage()) std::cerr << "pba-" << lab << ": " << *runner.guardMessage() << '\n';
  if (!o.metrics.empty()) {
    if (Status s = writeMetrics(metricsReport(lab, runner, frames), o.metrics); !s) {
      std::cerr << "pba-" << lab << ": " << s.error() << '\n';
      return kExitBadInput;
    }
  }
  if (!o.poseJson.empty()) {
    if (Status s = writePoseJson(lab, runner, o.poseJson); !s) {
      std::cerr << "pba-" << lab << ": " << s.error() << '\n';
      return kExitBadInput;
    }
  }
  return runner.guardMessage() ? kExitGuardPaused : kExitOk;
}

Status prepareCompare(const std::string& lab, const LabOptions& o, SceneRunner& a, SceneRunner& b) {
  if (Status s = prepareRunner(lab, o, b); !s) return s;
  for (const auto& [runner, text, side] :
       {std::tuple{&a, o.compare->first, "--compare A"}, std::tuple{&b, o.compare->second, "--compare B"}}) {
    Result<std::vector<CompareSetting>> settings = parseCompareSide(text, side);
    if (!settings) return Error{settings.error()};
    if (Status s = applyCompareSide(*runner, settings.value(), side); !s) return s;
  }
  return Status::success();
}

int runCompareHeadless(const std::string& lab, const LabOptions& o, SceneRunner& a, SceneRunner& b) {
  const long frames = o.frameCount();
  for (long f = 0; f < frames; ++f) {
    a.advanceFrame(kDisplayFrame);
    b.advanceFrame(kDisplayFrame);
  }
  for (const auto& [runner, side] : {std::pair{&a, "A"}, std::pair{&b, "B"}})
    if (runner->guardMessage()) std::cerr << "pba-" << lab << ": " << side << ": " << *runner->guardMessage() << '\n';
  if (!o.metrics.empty()) {
    nlohmann::json report = {
        {"lab", lab},
        {"scene", a.sceneName()},
        {"frames", frames},
        {"compare", {{"a", o.compare->first}, {"b", o.compare->second}, {"differences", compareDifferences(a, b)}}},
        {"a", metricsReport(lab, a, frames)},
        {"b", metricsReport(lab, b, frames)}};
    if (Status s = writeMetrics(report, o.metrics); !s) {
      std::cerr << "pba-" << lab << ": " << s.error() << '\n';
      return kExitBadInput;
    }
  }
  return a.guardMessage() || b.guardMessage() ? kExitGuardPaused : kExitOk;
}

int runLab(const std::string& lab, int argc, const char* const* argv) {
  try {
    Result<LabOptions> parsed = parseCommandLine(argc, argv);
    if (!parsed) {
      std::cerr << "pba-" << lab << ": " << oneLine(parsed.error()) << '\n';
      return kExitBadInput;
    }
    const LabOptions& o = parsed.value();
    if (o.help) {
      std::cout << usage(lab);
      return kExitOk;
    }
    if (o.listScenes) {
      for (const SceneEntry& e : scenes()) {
        const std::string description = e.create()->description();
        std::printf("%-16s %-12s %s\n", e.name.c_str(), e.category.c_str(), description.c_str());
      }
      return kExitOk;
    }
    exercises::runProbes();  // stubs record themselves: banner, Exercises panel, "not_implemented"
    if (o.checkExtremes) {
      const ExtremesOptions extremes{o.frames.value_or(ExtremesOptions{}.frames), o.scene};
      return checkParamExtremes(lab, extremes, std::cout) == 0 ? kExitOk : kExitInternal;
    }
    if (!o.goldenFile.empty()) {
      const GoldenOptions golden{o.goldenFile, o.goldenUpdate, o.frames.value_or(kDefaultGoldenFrames)};
      return runGoldenCheck(lab, golden, std::cout, std::cerr);
    }
    if (o.soakSeconds) {
      restartWithoutThreadCache(argv);
      return runSoak(lab, SoakOptions{*o.soakSeconds, o.seed}, std::cout, std::cerr);
    }
    SceneRunner runner;
    if (!o.demo.empty()) return runDemo(lab, o, runner);
    if (Status s = prepareRunner(lab, o, runner); !s) {
      std::cerr << "pba-" << lab << ": " << oneLine(s.error()) << '\n';
      return kExitBadInput;
    }
    if (o.checkRewind) return runRewindCheck(lab, o, runner);
    if (o.compare) {
      SceneRunner partner;
      if (Status s = prepareCompare(lab, o, runner, partner); !s) {
        std::cerr << "pba-" << lab << ": " << s.error() << '\n';
        return kExitBadInput;
      }
      return o.headless ? runCompareHeadless(lab, o, runner, partner) : runWindow(lab, o, runner, &partner);
    }
    return o.headless ? runHeadless(lab, o, runner) : runWindow(lab, o, runner);
  } catch (const std::exception& e) {
    std::cerr << "pba-" << lab << ": internal error: " << oneLine(e.what()) << '\n';
    return kExitInternal;
  }
}

}  // namespace pba::app
