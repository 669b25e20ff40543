// --check-rewind N: the rewind contract checked on any scene of any lab (tests/labs, "rewind"): run N
// frames and save the state, run N frames (run A), restore, drop the saved copy (so a scene whose
// restored state pointed into it would fail under ASan), run N frames (run B), restore a second copy
// and run N again (run C). A, B and C must have equal fingerprints (state_fingerprint.h).
#include <chrono>
#include <cstdio>
#include <iostream>

#include "app/checks/state_fingerprint.h"
#include "app/lab.h"
#include "physics/core/format.h"

namespace pba::app {
namespace {
void runFrames(SceneRunner& runner, long frames) {
  for (long f = 0; f < frames; ++f) runner.advanceFrame(kDisplayFrame);
}
}  // namespace

int runRewindCheck(const std::string& lab, const LabOptions& o, SceneRunner& runner) {
  const long n = *o.checkRewind;
  const std::string who = "pba-" + lab + ": --check-rewind: scene " + runner.sceneName();
  runFrames(runner, n);
  // Pausing is the user's setting, not part of a state: a run the guard pauses during A must start B
  // and C unpaused, as A did.
  const bool pausedAtSave = runner.paused();
  const auto start = std::chrono::steady_clock::now();
  RunnerSnapshot saved = runner.snapshot();
  const double saveMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!saved.scene) {
    std::cerr << who << ": the scene cannot save its state\n";
    return kExitInternal;
  }
  const std::size_t bytes = saved.bytes();
  runFrames(runner, n);
  const nlohmann::json a = stateFingerprint(runner);

  if (!runner.restore(saved)) {
    std::cerr << who << ": the saved state does not restore\n";
    return kExitInternal;
  }
  runner.setPaused(pausedAtSave);
  RunnerSnapshot second = runner.snapshot();
  saved = RunnerSnapshot{};  // the first copy is gone before run B
  runFrames(runner, n);
  const nlohmann::json b = stateFingerprint(runner);

  runner.restore(second);
  runner.setPaused(pausedAtSave);
  second = RunnerSnapshot{};
  runFrames(runner, n);
  const nlohmann::json c = stateFingerprint(runner);

  for (const auto& [name, run] : {std::pair{"B", &b}, std::pair{"C", &c}}) {
    if (*run != a) {
      std::cerr << who << ": run " << name
                << " after restoring differs from run A: " << nlohmann::json::diff(a, *run).dump() << '\n';
      return kExitInternal;
    }
  }
  std::cout << "rewind ok: " << lab << "/" << runner.sceneName() << ": state " << formatFixed(bytes / 1024.0, 1)
            << " KiB saved in " << formatFixed(saveMs, 3) << " ms; " << n
            << " frames run again twice after restoring agree bit for bit (draw hash "
            << a["draw_hash"].get<std::string>() << ", " << a["steps"] << " steps)\n";
  return kExitOk;
}

}  // namespace pba::app
