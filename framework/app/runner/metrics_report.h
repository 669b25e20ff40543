#pragma once
// The metrics JSON of docs/architecture.md §4: lab, scene, frames, sim_time_s, step_ms {median, p95, max},
// finite, and the scene's own metrics under the lab's name.
#include <string>

#include <nlohmann/json.hpp>

#include "app/runner/scene_runner.h"
#include "physics/core/result.h"

namespace pba::app {

nlohmann::json metricsReport(const std::string& lab, const SceneRunner& runner, long frames);
/// True for a wall-clock metric, which legitimately differs between runs. By convention
/// (docs/decisions/2026-12-01-command-line-errors-and-exit-codes.md) a timing key has a unit word "ms" or "us" among
/// its '_'-separated words (step_ms, solve_us_median, fabrik_solve_us) or ends in "_per_s"; gl_renderer names the
/// machine.
bool isTimingMetric(const std::string& key);
/// `metrics` without its timing entries, at every depth (what two identical runs must agree on).
nlohmann::json withoutTimings(nlohmann::json metrics);

/// Writes the report to `target` ("-" = standard output). Error names the path.
Status writeMetrics(const nlohmann::json& report, const std::string& target);

}  // namespace pba::app
