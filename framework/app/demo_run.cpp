// --demo FILE: the lab's side of a lecture demo script (demo_script.h). --demo-check validates this lab's
// steps; otherwise the lab opens on step --demo-step (which must be one of its own) and the window
// plays on from there (window_demo.cpp).
#include <iostream>

#include "app/lab.h"
#include "app/runner/demo_script.h"

namespace pba::app {

Status prepareDemoStep(SceneRunner& runner, const DemoScript& script, std::size_t index, std::uint64_t seed) {
  Result<std::unique_ptr<Scene>> scene = demoStepScene(script, index, seed);
  if (!scene) return Error{scene.error()};
  const DemoStep& step = script.steps[index];
  runner.adopt(std::move(scene.value()), step.scene);
  if (step.dt) runner.setDt(*step.dt, /*keepAcrossScenes=*/false);
  runner.reset();
  runner.setPaused(step.paused);
  return Status::success();
}

int runDemo(const std::string& lab, const LabOptions& o, SceneRunner& runner) {
  const std::string who = "pba-" + lab + ": ";
  Result<DemoScript> loaded = loadDemoScript(o.demo);
  if (!loaded) {
    std::cerr << who << loaded.error() << '\n';
    return kExitBadInput;
  }
  const DemoScript& script = loaded.value();
  if (o.demoCheck) {
    int mine = 0;
    for (std::size_t i = 0; i < script.steps.size(); ++i) {
      if (script.steps[i].lab != lab) continue;
      if (Status s = checkDemoStep(script, i); !s) {
        std::cerr << who << s.error() << '\n';
        return kExitBadInput;
      }
      ++mine;
    }
    std::cout << "demo ok: " << script.path << ": " << mine << " step" << (mine == 1 ? "" : "s") << " of lab " << lab
              << " load and validate\n";
    return kExitOk;
  }
  const std::size_t index = static_cast<std::size_t>(o.demoStep - 1);
  if (index >= script.steps.size()) {
    std::cerr << who << "--demo-step: " << script.path << " has " << script.steps.size() << " steps, not " << o.demoStep
              << '\n';
    return kExitBadInput;
  }
  if (script.steps[index].lab != lab) {
    std::cerr << who << script.path << ": steps[" << index << "].lab: step " << o.demoStep << " is for lab '"
              << script.steps[index].lab << "' (./pba demo starts each step in its lab)\n";
    return kExitBadInput;
  }
  if (Status s = prepareDemoStep(runner, script, index, o.seed); !s) {
    std::cerr << who << s.error() << '\n';
    return kExitBadInput;
  }
  LabOptions played = o;
  played.lecture = true;  // demos are for the projector
  return o.headless ? runHeadless(lab, played, runner) : runWindow(lab, played, runner);
}

}  // namespace pba::app
