#include "app/runner/compare_run.h"

#include <sstream>

#include "physics/core/format.h"

namespace pba::app {

Result<std::vector<CompareSetting>> parseCompareSide(const std::string& text, const std::string& side) {
  std::vector<CompareSetting> out;
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    const auto eq = word.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == word.size())
      return Error{side + ": expected NAME=VALUE pairs separated by spaces, got '" + word + "'"};
    out.push_back({word.substr(0, eq), word.substr(eq + 1)});
  }
  return out;
}

Status applyCompareSide(SceneRunner& runner, const std::vector<CompareSetting>& settings, const std::string& side) {
  for (const CompareSetting& s : settings) {
    Status applied = Status::success();
    if (s.name == "dt" || s.name == "time_scale" || s.name == "substeps") {
      char* end = nullptr;
      const double v = std::strtod(s.value.c_str(), &end);
      if (end == s.value.c_str() || *end != '\0')
        return Error{side + ": " + s.name + ": not a number: '" + s.value + "'"};
      if (s.name == "dt" && !(v >= kMinDt && v <= kMaxDt))
        return Error{side + ": dt: must be in [1e-06, 0.1] s, got " + s.value};
      if (s.name == "time_scale" && !(v >= kMinTimeScale && v <= kMaxTimeScale))
        return Error{side + ": time_scale: must be in [0.1, 4], got " + s.value};
      if (s.name == "dt") applied = runner.setDt(v);
      if (s.name == "time_scale") applied = runner.setTimeScale(v);
      if (s.name == "substeps") {
        if (v != static_cast<int>(v)) return Error{side + ": substeps: not a whole number: '" + s.value + "'"};
        applied = runner.setSubsteps(static_cast<int>(v));
      }
    } else if (!runner.scene().params().find(s.name)) {
      return Error{side + ": " + s.name + ": not a parameter of scene '" + runner.sceneName() +
                   "' (nor dt, substeps, time_scale)"};
    } else {
      applied = runner.scene().params().setFromText(s.name, s.value);
    }
    if (!applied) return Error{side + ": " + applied.error()};
  }
  if (Status s = runner.scene().validate(); !s) return Error{side + ": " + s.error()};
  runner.reset();
  return Status::success();
}

std::vector<std::string> compareDifferences(const SceneRunner& a, const SceneRunner& b) {
  std::vector<std::string> out;
  if (a.dt() != b.dt()) out.push_back("dt=" + formatFixed(b.dt(), 5));
  if (a.substeps() != b.substeps()) out.push_back("substeps=" + std::to_string(b.substeps()));
  if (a.timeScale() != b.timeScale()) out.push_back("time_scale=" + formatFixed(b.timeScale(), 2));
  const nlohmann::json pa = a.scene().params().toJson(), pb = b.scene().params().toJson();
  for (const auto& [name, value] : pb.items()) {
    if (!pa.contains(name) || pa[name] != value)
      out.push_back(name + "=" + (value.is_string() ? value.get<std::string>() : value.dump()));
  }
  return out;
}

}  // namespace pba::app
