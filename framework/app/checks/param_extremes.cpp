#include "app/checks/param_extremes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <ostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/lab.h"
#include "app/runner/metrics_report.h"
#include "app/runner/scene_registry.h"
#include "physics/core/format.h"

namespace pba::app {
namespace {

struct Timed {
  double seconds = 0.0;
  std::string label;
};

/// The text --set is given: whole numbers for integers, else the shortest exact decimal.
std::string valueText(const Param& p, double v) {
  return p.kind == ParamKind::Integer ? std::to_string(static_cast<long long>(v)) : formatExact(v);
}

/// The first non-finite number in `j` (path of keys), or empty.
std::string firstNonFinite(const nlohmann::json& j, const std::string& path) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) return path.empty() ? "(value)" : path;
  if (j.is_object() || j.is_array()) {
    int index = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++index) {
      const std::string key = j.is_object() ? it.key() : std::to_string(index);
      if (std::string bad = firstNonFinite(*it, path.empty() ? key : path + "." + key); !bad.empty()) return bad;
    }
  }
  return {};
}

class Checker {
 public:
  Checker(const std::string& lab, const ExtremesOptions& o, std::ostream& out) : lab_(lab), o_(o), out_(out) {}

  void scene(const SceneEntry& entry) {
    const std::unique_ptr<Scene> probe = entry.create();
    for (const Param& p : probe->params().all()) {
      switch (p.kind) {
        case ParamKind::Real:
        case ParamKind::Integer: {
          inRange(entry.name, p, p.min);
          if (p.workload)
            out_ << "skip " << entry.name << ' ' << p.name << '=' << valueText(p, p.max) << " (a workload)\n";
          else if (p.max != p.min)
            inRange(entry.name, p, p.max);
          const bool whole = p.kind == ParamKind::Integer;
          const double inf = std::numeric_limits<double>::infinity();
          outOfRange(entry.name, p, whole ? p.min - 1.0 : std::nextafter(p.min, -inf));
          outOfRange(entry.name, p, whole ? p.max + 1.0 : std::nextafter(p.max, inf));
          break;
        }
        case ParamKind::Flag:
          outOfRange(entry.name, p, nlohmann::json("maybe"));
          break;
        case ParamKind::Choice:
          outOfRange(entry.name, p, nlohmann::json("no-such-choice"));
          break;
        case ParamKind::Text:
          break;  // a file or a list of names: the corpora (tests/corpora) cover what a text may hold
      }
    }
  }

  int finish() {
    std::sort(timed_.begin(), timed_.end(), [](const Timed& a, const Timed& b) { return a.seconds > b.seconds; });
    out_ << "slowest runs:";
    for (size_t i = 0; i < timed_.size() && i < 5; ++i)
      out_ << ' ' << timed_[i].label << " (" << formatFixed(timed_[i].seconds, 2) << " s)";
    out_ << "\n"
         << runs_ << " runs at the extremes (" << guarded_ << " paused by the guard), " << refusals_
         << " refusals checked, " << failures_ << " failures\n";
    return failures_;
  }

 private:
  void fail(const std::string& label, const std::string& why) {
    ++failures_;
    out_ << "FAIL " << label << ": " << why << std::endl;
  }

  // In range: loads through the command line's path and runs; finite, or paused by the guard.
  void inRange(const std::string& scene, const Param& p, double value) {
    const std::string text = valueText(p, value);
    const std::string label = scene + " " + p.name + "=" + text;
    out_ << "run " << label << std::flush;
    LabOptions o;
    o.scene = scene;
    o.headless = true;
    o.frames = o_.frames;
    o.overrides.push_back({p.name, text, "--set"});
    const auto start = std::chrono::steady_clock::now();
    try {
      SceneRunner runner;
      if (Status s = prepareRunner(lab_, o, runner); !s) {
        out_ << '\n';
        return fail(label, "refused a value in its declared range: " + s.error());
      }
      for (long f = 0; f < o_.frames && !runner.guardMessage(); ++f) runner.advanceFrame(kDisplayFrame);
      ++runs_;
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      timed_.push_back({seconds, label});
      if (runner.guardMessage()) {
        ++guarded_;
        out_ << " -> paused by the guard: " << *runner.guardMessage() << '\n';
        return;
      }
      const nlohmann::json report = metricsReport(lab_, runner, o_.frames);
      out_ << " -> finite (" << formatFixed(seconds, 2) << " s)\n";
      if (std::string bad = firstNonFinite(report, ""); !bad.empty())
        fail(label, "metric " + bad + " is not finite and the guard did not pause the scene");
    } catch (const std::exception& e) {
      out_ << '\n';
      fail(label, std::string("threw: ") + e.what());
    }
  }

  // Out of range (or not a value of a flag or choice): refused by --set and by a scene file, one line
  // naming the parameter; numbers must say the range.
  void outOfRange(const std::string& scene, const Param& p, double value) {
    outOfRange(scene, p, nlohmann::json(value));
  }
  void outOfRange(const std::string& scene, const Param& p, const nlohmann::json& value) {
    const bool number = value.is_number();
    const std::string text = number ? valueText(p, value.get<double>()) : value.get<std::string>();
    const std::string label = scene + " " + p.name + "=" + text;
    ++refusals_;
    LabOptions o;
    o.scene = scene;
    o.headless = true;
    o.overrides.push_back({p.name, text, "--set"});
    SceneRunner runner;
    const Status s = prepareRunner(lab_, o, runner);
    const std::string cli = "--set " + p.name + ": ";
    if (s) return fail(label, "--set accepted a value outside its range");
    if (s.error().rfind(cli, 0) != 0 || s.error().find('\n') != std::string::npos ||
        (number && s.error().find("must be in [") == std::string::npos))
      return fail(label, "--set's message does not name the parameter and its range on one line: " + s.error());
    // The same value in a scene file's "params" (numbers as JSON numbers, names as strings).
    const std::unique_ptr<Scene> fresh = findScene(scene)->create();
    const Status f = fresh->params().setFromJson(p.name, value, "params.");
    if (f) return fail(label, "a scene file's params accepted a value outside its range");
    if (f.error().rfind("params." + p.name + ": ", 0) != 0 || f.error().find('\n') != std::string::npos)
      fail(label, "a scene file's message does not name params." + p.name + " on one line: " + f.error());
  }

  const std::string& lab_;
  const ExtremesOptions& o_;
  std::ostream& out_;
  int failures_ = 0, runs_ = 0, guarded_ = 0, refusals_ = 0;
  std::vector<Timed> timed_;
};

}  // namespace

int checkParamExtremes(const std::string& lab, const ExtremesOptions& options, std::ostream& out) {
  Checker checker(lab, options, out);
  bool found = false;
  for (const SceneEntry& entry : scenes()) {
    if (!options.scene.empty() && entry.name != options.scene) continue;
    found = true;
    checker.scene(entry);
  }
  if (!found) {
    out << "FAIL: no scene '" << options.scene << "'\n";
    return 1;
  }
  return checker.finish();
}

}  // namespace pba::app
