#pragma once
// Entry point shared by every lab executable: parses the command line, loads the scene, then runs
// headless or in a window. Exit codes: 0 success, 2 bad arguments or input file, 1 internal failure,
// 3 a headless run paused by the instability guard.
#include <string>

#include "app/runner/command_line.h"
#include "app/runner/scene_runner.h"

namespace pba::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;
inline constexpr int kExitBadInput = 2;
/// A headless run that the instability guard paused (non-finite state or runaway energy): the metrics
/// are still written (with "paused_by_guard": true) and the guard's message is on stderr.
inline constexpr int kExitGuardPaused = 3;

int runLab(const std::string& lab, int argc, const char* const* argv);

/// Loads the scene named by options.scene (a name or a scene file) into runner and applies dt,
/// substeps, time scale and overrides. Errors are one line naming the file or option and field.
Status prepareRunner(const std::string& lab, const LabOptions& options, SceneRunner& runner);

/// Steps `frames` display frames with no window and no GL; writes metrics when asked.
int runHeadless(const std::string& lab, const LabOptions& options, SceneRunner& runner);

/// --check-rewind N (rewind_check.cpp): save, run, restore, run again; exit 0 when the runs agree.
int runRewindCheck(const std::string& lab, const LabOptions& options, SceneRunner& runner);

/// --compare "A" "B": prepares `b` like `a` (prepareRunner), then applies each side's settings
/// (compare_run.h) and resets both. Errors name the side and the setting.
Status prepareCompare(const std::string& lab, const LabOptions& options, SceneRunner& a, SceneRunner& b);
/// Steps both runners in lock-step for options.frameCount() frames; the metrics hold "a" and "b" (each
/// the report of one run) and "compare" (the two sides' settings and where B differs).
int runCompareHeadless(const std::string& lab, const LabOptions& options, SceneRunner& a, SceneRunner& b);

struct DemoScript;
/// --demo FILE (demo_run.cpp): validates this lab's steps (--demo-check) or opens on step --demo-step.
int runDemo(const std::string& lab, const LabOptions& options, SceneRunner& runner);
/// Loads step `index` of a demo script into `runner` (scene, parameters, dt, paused). Errors name the step.
Status prepareDemoStep(SceneRunner& runner, const DemoScript& script, std::size_t index, std::uint64_t seed);

/// Opens the window (defined by the window module). With options.screenshot set, renders
/// options.frameCount() frames, saves the PNG and returns. With `partner` (an A/B run) both scenes are
/// shown side by side and step together.
int runWindow(const std::string& lab, const LabOptions& options, SceneRunner& runner, SceneRunner* partner = nullptr);

}  // namespace pba::app
