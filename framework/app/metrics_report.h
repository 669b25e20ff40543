#pragma once
// The metrics JSON of docs/architecture.md §4: lab, scene, frames, sim_time_s, step_ms {median, p95, max},
// finite, and the scene's own metrics under the lab's name.
#include <string>

#include <nlohmann/json.hpp>

#include "app/scene_runner.h"
#include "physics/core/result.h"

namespace pba::app {

nlohmann::json metricsReport(const std::string& lab, const SceneRunner& runner, long frames);
/// Writes the report to `target` ("-" = standard output). Error names the path.
Status writeMetrics(const nlohmann::json& report, const std::string& target);

}  // namespace pba::app
