#pragma once
// The window's demo player (--demo FILE, demo_script.h): PageDown / PageUp move through the steps of the
// script like slides; a step of this lab is loaded in place (scene, parameters, dt, camera, recording),
// a step of another lab closes the window after writing its number to --demo-next, where ./pba demo
// picks it up and starts that lab. The speaker notes show in a window (key N) and on the terminal.
#include <optional>
#include <string>

#include "app/runner/demo_script.h"
#include "app/window/lab_session.h"
#include "app/window/lab_ui.h"

namespace pba::app {

class WindowDemo {
 public:
  /// Loads options.demo at step options.demoStep (runDemo has loaded that step into the runner).
  Status open(const std::string& lab, const std::string& path, long step, std::string nextPath);
  bool active() const { return !script_.steps.empty(); }

  enum class Move { None, Shown, Leave };
  /// Moves by `delta` steps: Shown when a step of this lab was loaded into the session, Leave when the
  /// window should close for a step of another lab (or past the last step), None at the first step.
  Move move(int delta, LabSession& session);
  const DemoStep& step() const { return script_.steps[index_]; }
  /// Prints the step's notes to the terminal (the presenter's screen) once per step shown.
  void printNotes() const;
  /// Width of the notes window [pixels] at the current font and display size.
  float notesWidth() const;
  /// The speaker notes window in the upper right, left of `right` [pixels].
  void notesWindow(const UiState& ui, float right) const;
  /// The camera of the step just shown (once).
  std::optional<CameraView> takeCamera();

 private:
  std::string lab_;
  std::string nextPath_;
  DemoScript script_;
  std::size_t index_ = 0;
  bool cameraPending_ = true;
};

}  // namespace pba::app
