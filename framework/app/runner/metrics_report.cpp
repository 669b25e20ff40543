#include "app/runner/metrics_report.h"

#include <algorithm>
#include <fstream>
#include <iostream>

#include "physics/exercises/not_implemented.h"

namespace pba::app {

nlohmann::json metricsReport(const std::string& lab, const SceneRunner& runner, long frames) {
  const StepSummary s = runner.frameStats().summary();
  nlohmann::json report;
  report["lab"] = lab;
  report["scene"] = runner.sceneName();
  report["frames"] = frames;
  report["sim_time_s"] = runner.simTime();
  report["dt"] = runner.dt();
  report["steps"] = runner.steps();
  report["step_ms"] = {{"median", s.median}, {"p95", s.p95}, {"max", s.max}};
  report["heavy"] = runner.scene().heavy();
  report["finite"] = runner.finite() && !runner.scene().nonFiniteState();
  report["paused_by_guard"] = runner.guardMessage().has_value();
  if (runner.guardMessage()) report["guard_message"] = *runner.guardMessage();
  report["not_implemented"] = exercises::notImplementedTags();
  report[lab] = runner.scene().metrics();
  return report;
}

bool isTimingMetric(const std::string& key) {
  if (key == "gl_renderer") return true;
  if (key.size() >= 6 && key.compare(key.size() - 6, 6, "_per_s") == 0) return true;
  std::size_t start = 0;
  while (start <= key.size()) {
    const std::size_t end = std::min(key.find('_', start), key.size());
    const std::string word = key.substr(start, end - start);
    if (word == "ms" || word == "us") return true;
    start = end + 1;
  }
  return false;
}

nlohmann::json withoutTimings(nlohmann::json metrics) {
  if (!metrics.is_object()) return metrics;
  for (auto it = metrics.begin(); it != metrics.end();) {
    if (isTimingMetric(it.key())) {
      it = metrics.erase(it);
    } else {
      *it = withoutTimings(std::move(*it));
      ++it;
    }
  }
  return metrics;
}

Status writeMetrics(const nlohmann::json& report, const std::string& target) {
  // Non-finite numbers would make invalid JSON; nlohmann writes them as null, which readers accept.
  const std::string text = report.dump(2);
  if (target == "-") {
    std::cout << text << std::endl;
    return Status::success();
  }
  std::ofstream out(target, std::ios::trunc);
  if (!out) return Error{target + ": cannot write the metrics file"};
  out << text << '\n';
  return out ? Status::success() : Status(Error{target + ": write failed"});
}

}  // namespace pba::app
