#pragma once
// A/B runs (docs/architecture.md §3, "A/B comparison"): two copies of one scene with different settings,
// stepped in lock-step, side by side in the window and together in the headless metrics. A side's
// settings are NAME=VALUE pairs separated by spaces: the runner's dt, substeps and time_scale, or any
// parameter of the scene ("dt=0.0042", "integrator=rk4 substeps=2").
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/runner/scene_runner.h"
#include "physics/core/result.h"

namespace pba::app {

struct CompareSetting {
  std::string name;
  std::string value;
};

/// Splits "a=1 b=two" into settings; an empty text is no settings. Errors name the side ("--compare B").
Result<std::vector<CompareSetting>> parseCompareSide(const std::string& text, const std::string& side);

/// Applies the settings to `runner`'s scene and clock, then validates and resets it. Errors name the side
/// and the setting: "--compare B: dt: must be in [1e-06, 0.1], got 5".
Status applyCompareSide(SceneRunner& runner, const std::vector<CompareSetting>& settings, const std::string& side);

/// The parameters (and dt, substeps, time scale) in which `b` differs from `a`, as "name=value" text.
std::vector<std::string> compareDifferences(const SceneRunner& a, const SceneRunner& b);

}  // namespace pba::app
