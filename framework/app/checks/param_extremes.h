#pragma once
// Every numeric parameter of every scene at its extremes, generated from the Params declarations
// (docs/decisions/2026-12-02-every-parameter-at-its-extremes.md): a lab's hidden test mode `--check-extremes` loops
// in one process over its registered scenes, so a new scene or parameter is covered without writing a test.
//   - at the declared minimum and maximum (through the command line's --set path): the scene must load,
//     run `frames` display frames and stay finite (state and metrics), or be paused by the
//     instability guard, which is the guard's job (a maximum marked Params::workload(), an amount of
//     work such as a batch's number of solves, is not run);
//   - just below the minimum and just above the maximum (the next double, or ±1 for integers), and an
//     unknown name for flags and choices: --set and a scene file's "params" must refuse the value with
//     one line naming the parameter.
#include <iosfwd>
#include <string>

namespace pba::app {

struct ExtremesOptions {
  long frames = 60;   ///< display frames of 1/60 s per in-range run
  std::string scene;  ///< only this scene when not empty
};

/// Runs the check; prints one line per case and a summary to `out`. Returns the number of failures.
int checkParamExtremes(const std::string& lab, const ExtremesOptions& options, std::ostream& out);

}  // namespace pba::app
