#include "app/lab.h"

#include <cstdio>
#include <exception>
#include <iostream>

#include "app/message_text.h"
#include "app/metrics_report.h"
#include "app/param_extremes.h"
#include "app/scene_file.h"
#include "app/scene_registry.h"
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
  return Status::success();
}

int runHeadless(const std::string& lab, const LabOptions& o, SceneRunner& runner) {
  const long frames = o.frameCount();
  for (long f = 0; f < frames; ++f) runner.advanceFrame(kDisplayFrame);
  if (runner.guardMessage()) std::cerr << "pba-" << lab << ": " << *runner.guardMessage() << '\n';
  if (!o.metrics.empty()) {
    if (Status s = writeMetrics(metricsReport(lab, runner, frames), o.metrics); !s) {
      std::cerr << "pba-" << lab << ": " << s.error() << '\n';
      return kExitBadInput;
    }
  }
  return runner.guardMessage() ? kExitGuardPaused : kExitOk;
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
    SceneRunner runner;
    if (Status s = prepareRunner(lab, o, runner); !s) {
      std::cerr << "pba-" << lab << ": " << oneLine(s.error()) << '\n';
      return kExitBadInput;
    }
    return o.headless ? runHeadless(lab, o, runner) : runWindow(lab, o, runner);
  } catch (const std::exception& e) {
    std::cerr << "pba-" << lab << ": internal error: " << oneLine(e.what()) << '\n';
    return kExitInternal;
  }
}

}  // namespace pba::app
