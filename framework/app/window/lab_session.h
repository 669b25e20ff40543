#pragma once
// The state of a lab in its window, and the actions that keys and buttons share (pause, step,
// reset, scene switch, presets, scene files). No GL and no ImGui here, so the actions are tested
// headless (tests/app/lab_session_test.cpp).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/runner/exercise_catalog.h"
#include "app/runner/scene_runner.h"
#include "app/window/lab_settings.h"
#include "app/window/plot_history.h"
#include "app/window/rewind_history.h"
#include "app/window/target_nudge.h"

namespace pba::app {

class LabSession {
 public:
  LabSession(std::string lab, SceneRunner& runner, std::uint64_t seed);

  const std::string& lab() const { return lab_; }
  SceneRunner& runner() { return runner_; }
  const SceneRunner& runner() const { return runner_; }

  void togglePause();
  void singleStep();
  void reset();
  /// Switches to scene `index` of the registry (wraps around); keeps the current one on failure.
  void switchScene(int index);
  void nextScene(int delta);
  int sceneIndex() const;
  /// Applies preset `index` (0-based) of the current scene and resets: every parameter takes the
  /// scene's default, then the preset's value (presetParams). Message on failure.
  void applyPreset(int index);

  /// Mouse drag and keyboard nudge of the scene's objects. While the scene is paused each is followed
  /// by Scene::refresh(), so a paused scene shows the effect of a goal change whatever moved it.
  void drag(int handle, const Vec3& target);
  void release(int handle);
  /// Nudges the scene's target (target_nudge.h); false when the scene has none.
  bool nudge(NudgeDirection direction, const Vec3& right, const Vec3& up, const Vec3& forward, Real sceneSize,
             bool fine);

  /// Shows an already configured scene (a demo step): adopted, reset, B rebuilt, the camera framed.
  void adoptScene(std::unique_ptr<Scene> scene, std::string name);
  /// Loads a scene file. On error the running scene stays and the error is kept for the UI.
  bool loadSceneFile(const std::string& path);
  /// Saves the current scene's parameters as a scene file.
  bool saveSceneFile(const std::string& path);

  /// Once per displayed frame, after the runner advanced: records the metrics for the plots (while
  /// running or dragging: a paused plot stays still) and, when the scene stepped, its state in the
  /// rewind history.
  void afterFrame(bool dragging = false);

  /// Rewind (keys , and . and the timeline strip): shows frame `i` of the history, paused, with its
  /// state put back and the plots rebuilt up to it. Space resumes from there as a new branch.
  void scrubTo(std::size_t i);
  void stepBack();
  /// One frame forward: the next frame of the history, or a new step when at the newest one.
  void stepForward();
  /// Keys , and . (Shift: a second's worth, stepsPerSecond()): moves the shown state by `delta` simulation
  /// steps. The history keeps one snapshot per displayed frame, so a step between two frames is reached by
  /// restoring the frame at or before it and stepping on (deterministic: the same state as the run had);
  /// the history is kept. Past the newest frame it takes new steps. An A/B run moves by frames (its two
  /// sides take different numbers of steps per frame).
  void stepBy(std::int64_t delta);
  /// Fixed steps in one second of simulated time at the current dt (at least 1).
  std::int64_t stepsPerSecond() const;
  const RewindHistory& history() const { return history_; }

  /// A/B runs (compare_run.h): B steps with A (pause, step, reset, presets, scene switches, drags and
  /// rewind act on both), each side keeping its own settings.
  void startCompare(std::unique_ptr<SceneRunner> b, std::string sideA, std::string sideB);
  /// "Duplicate as B": B gets A's scene, parameters and settings; both start again from reset.
  void duplicateAsB();
  void endCompare();
  bool comparing() const { return partner_ != nullptr; }
  SceneRunner* partner() { return partner_.get(); }
  const SceneRunner* partner() const { return partner_.get(); }
  const PlotHistory& partnerPlots() const { return partnerPlots_; }
  /// The side the parameter panel edits.
  bool editingB() const { return editingB_ && partner_; }
  void setEditingB(bool b) { editingB_ = b; }
  SceneRunner& editedRunner() { return editingB() ? *partner_ : runner_; }
  /// What A and B were started with ("dt=0.0167"); empty for a duplicate.
  const std::string& sideText(bool b) const { return b ? sideB_ : sideA_; }

  /// A message for the status line (what just happened), and the last scene file error.
  const std::string& message() const { return message_; }
  const std::string& fileError() const { return fileError_; }
  void setMessage(std::string text) { message_ = std::move(text); }

  PlotHistory& plots() { return plots_; }
  const PlotHistory& plots() const { return plots_; }
  LabSettings& settings() { return settings_; }
  const LabSettings& settings() const { return settings_; }
  const std::vector<ExerciseInfo>& exercises() const { return exercises_; }
  void setExercises(std::vector<ExerciseInfo> list) { exercises_ = std::move(list); }

  /// Camera bookmarks: the window reports its camera every frame (saved with a scene file), and takes
  /// the camera of a scene file that has one once it is loaded.
  void setCurrentCamera(const CameraView& view) { currentCamera_ = view; }
  void requestCamera(const CameraView& view) { cameraRequest_ = view; }
  std::optional<CameraView> takeCameraRequest() {
    std::optional<CameraView> v = cameraRequest_;
    cameraRequest_.reset();
    return v;
  }

  /// Set when another scene is loaded (switch or scene file): the window frames the camera on it.
  /// A reset keeps the camera where the user put it.
  bool takeFrameRequest();
  void requestFrame() { frameRequested_ = true; }

 private:
  void sceneChanged();
  /// Forgets the plots and the rewind history (reset, preset, another scene).
  void restartHistory();

  std::string lab_;
  SceneRunner& runner_;
  std::uint64_t seed_;
  PlotHistory plots_;
  RewindHistory history_;
  std::unique_ptr<SceneRunner> partner_;
  PlotHistory partnerPlots_;
  std::string sideA_, sideB_;
  bool editingB_ = false;
  std::optional<CameraView> currentCamera_;
  std::optional<CameraView> cameraRequest_;
  /// After a scene switch, preset or scene file: B takes the scene A has now, then each side its settings.
  void rebuildPartner();
  std::int64_t historySteps_ = -1;  ///< the runner's step count at the newest frame pushed
  LabSettings settings_;
  std::vector<ExerciseInfo> exercises_;
  std::string message_;
  std::string fileError_;
  bool frameRequested_ = true;
};

}  // namespace pba::app
