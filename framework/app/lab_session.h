#pragma once
// The state of a lab in its window, and the actions that keys and buttons share (pause, step,
// reset, scene switch, presets, scene files). No GL and no ImGui here, so the actions are tested
// headless (tests/app/lab_session_test.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include "app/exercise_catalog.h"
#include "app/lab_settings.h"
#include "app/plot_history.h"
#include "app/scene_runner.h"
#include "app/target_nudge.h"

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

  /// Loads a scene file. On error the running scene stays and the error is kept for the UI.
  bool loadSceneFile(const std::string& path);
  /// Saves the current scene's parameters as a scene file.
  bool saveSceneFile(const std::string& path);

  /// Records the current metrics for the plots (once per displayed frame).
  void recordPlots();

  /// A message for the status line (what just happened), and the last scene file error.
  const std::string& message() const { return message_; }
  const std::string& fileError() const { return fileError_; }
  void setMessage(std::string text) { message_ = std::move(text); }

  PlotHistory& plots() { return plots_; }
  LabSettings& settings() { return settings_; }
  const std::vector<ExerciseInfo>& exercises() const { return exercises_; }
  void setExercises(std::vector<ExerciseInfo> list) { exercises_ = std::move(list); }

  /// Set when another scene is loaded (switch or scene file): the window frames the camera on it.
  /// A reset keeps the camera where the user put it.
  bool takeFrameRequest();
  void requestFrame() { frameRequested_ = true; }

 private:
  void sceneChanged();

  std::string lab_;
  SceneRunner& runner_;
  std::uint64_t seed_;
  PlotHistory plots_;
  LabSettings settings_;
  std::vector<ExerciseInfo> exercises_;
  std::string message_;
  std::string fileError_;
  bool frameRequested_ = true;
};

}  // namespace pba::app
