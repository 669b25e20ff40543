#pragma once
// The lab runner's simulation core, shared by the window and headless mode: one scene, a fixed step
// with an accumulator, pause / single step / reset, time scale, substeps, step timing and the
// instability guard (docs/architecture.md §3).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/runner/scene.h"
#include "app/runner/step_stats.h"
#include "physics/core/result.h"

namespace pba::app {

/// Limits of the runner's controls (the UI sliders and the command line share them).
inline constexpr Real kMinDt = 1e-6;        // [s]
inline constexpr Real kMaxDt = 0.1;         // [s]
inline constexpr Real kMinTimeScale = 0.1;  // slow motion
inline constexpr Real kMaxTimeScale = 4.0;
inline constexpr int kMaxSubsteps = 64;
inline constexpr Real kDisplayFrame = 1.0 / 60.0;  // [s] simulated time per displayed frame at 1x
/// The runaway-energy guard trips when |E| exceeds this multiple of the scale set at reset.
inline constexpr Real kRunawayEnergyFactor = 100.0;

/// The runner's clock and guard with a copy of the scene's state: one point of the rewind history.
/// Settings (dt, substeps, time scale, pause) are not part of it: they are the user's, not the run's.
struct RunnerSnapshot {
  std::shared_ptr<const SceneState> scene;  ///< null when the scene cannot save its state
  Real simTime = 0.0;
  Real accumulator = 0.0;
  Real energyScale = 0.0;
  std::optional<Real> energyReference;
  std::vector<double> paramValues;
  std::int64_t steps = 0;
  bool finite = true;
  std::optional<std::string> guardMessage;
  /// Memory held [bytes].
  std::size_t bytes() const;
};

class SceneRunner {
 public:
  /// Creates scene `name` from the registry, applies the seed, resets it. Error names the scene.
  Status load(const std::string& name, std::uint64_t seed);
  /// Takes an already configured scene (e.g. from a scene file) and resets it.
  void adopt(std::unique_ptr<Scene> scene, std::string name);

  /// Resets the scene to its parameters; clears the guard, the clock and the timings.
  void reset();
  /// Advances by `frameSeconds` of wall time × time scale, in whole fixed steps (accumulator).
  /// maxSteps bounds the work of one frame (the remainder is dropped) so that a slow scene
  /// cannot freeze the window; headless mode passes no bound. Does nothing while paused.
  void advanceFrame(Real frameSeconds, int maxSteps = -1);
  /// One fixed step even while paused (key O).
  void singleStep();

  /// The current state (scene and clock) for the rewind history and A/B runs.
  RunnerSnapshot snapshot() const;
  /// Puts a snapshot of this scene back: stepping on reproduces the original run bit for bit. False, and
  /// nothing changed, when it holds no state or one of another scene type.
  bool restore(const RunnerSnapshot& snapshot);

  bool paused() const { return paused_; }
  void setPaused(bool paused) { paused_ = paused; }

  Real dt() const { return dt_; }
  /// Sets the fixed step. keepAcrossScenes: the command line's --dt applies to every scene loaded
  /// later; a change in the panel applies to the current scene only (the next one starts at its
  /// own default).
  Status setDt(Real dt, bool keepAcrossScenes = true);
  int substeps() const { return substeps_; }
  Status setSubsteps(int n);
  Real timeScale() const { return timeScale_; }
  Status setTimeScale(Real scale);

  Scene& scene() { return *scene_; }
  const Scene& scene() const { return *scene_; }
  bool hasScene() const { return scene_ != nullptr; }
  const std::string& sceneName() const { return sceneName_; }

  Real simTime() const { return simTime_; }
  std::int64_t steps() const { return steps_; }
  /// Physics time of each advanceFrame() that stepped [ms].
  const StepStats& frameStats() const { return frameStats_; }
  /// Set when the guard paused the scene: what happened and what to try. Cleared by reset().
  const std::optional<std::string>& guardMessage() const { return guardMessage_; }
  /// False once any step produced a non-finite state (stays false until reset).
  bool finite() const { return finite_; }
  /// The user put energy in (a drag, a nudge, a scene key): the energy bound starts again from the
  /// scene's energy now. Parameter edits are noticed by the runner itself.
  void noteInput();

 private:
  /// Runs one fixed step (as `substeps` sub-steps) and the guard; false when the guard tripped.
  bool stepOnce();
  void checkGuard();
  /// Sets the energy the bound counts from to the scene's energy now (reset, input, parameter edits).
  void rebaseEnergy();
  /// The scene's numeric parameter values, to notice edits between steps.
  std::vector<double> paramValues() const;

  std::unique_ptr<Scene> scene_;
  std::string sceneName_;
  Real dt_ = 1.0 / 120.0;
  bool dtFromUser_ = false;
  int substeps_ = 1;
  Real timeScale_ = 1.0;
  bool paused_ = false;
  Real accumulator_ = 0.0;
  Real simTime_ = 0.0;
  std::int64_t steps_ = 0;
  Real energyScale_ = 0.0;
  std::optional<Real> energyReference_;  ///< [J] energy at reset or the user's last input
  std::vector<double> paramValues_;      ///< at the last rebase
  bool finite_ = true;
  StepStats frameStats_;
  std::optional<std::string> guardMessage_;
};

}  // namespace pba::app
