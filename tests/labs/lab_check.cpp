// Checks used by the lab smoke tests:
//   pba_lab_check metrics FILE LAB [SCENE]   the metrics JSON has the shape of docs/architecture.md §4
//   pba_lab_check same A B                   two metrics files agree except for timings
//   pba_lab_check image FILE.png             the screenshot is not blank
//   pba_lab_check same-sides|different-sides FILE LAB   an A/B report's runs agree / differ
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/runner/metrics_report.h"
#include "graphics/screenshot.h"

namespace {
using nlohmann::json;

bool load(const std::string& path, json& out) {
  std::ifstream in(path);
  if (!in) {
    std::cerr << path << ": cannot open\n";
    return false;
  }
  try {
    out = json::parse(in);
  } catch (const std::exception& e) {
    std::cerr << path << ": not JSON: " << e.what() << '\n';
    return false;
  }
  return true;
}

int checkMetrics(const std::string& path, const std::string& lab, const std::string& scene) {
  json m;
  if (!load(path, m)) return 1;
  auto bad = [&](const std::string& what) {
    std::cerr << path << ": " << what << "\n" << m.dump(2) << '\n';
    return 1;
  };
  if (!m.is_object()) return bad("not an object");
  if (m.value("lab", "") != lab) return bad("lab is not '" + lab + "'");
  if (!m.contains("scene") || !m["scene"].is_string()) return bad("scene missing");
  if (!scene.empty() && m["scene"] != scene) return bad("scene is not '" + scene + "'");
  if (!m.contains("frames") || !m["frames"].is_number_integer() || m["frames"].get<long>() < 1)
    return bad("frames missing or < 1");
  if (!m.contains("sim_time_s") || !m["sim_time_s"].is_number() || !(m["sim_time_s"].get<double>() > 0.0))
    return bad("sim_time_s missing or not > 0");
  for (const char* k : {"median", "p95", "max"}) {
    if (!m.contains("step_ms") || !m["step_ms"].contains(k) || !m["step_ms"][k].is_number() ||
        m["step_ms"][k].get<double>() < 0.0)
      return bad(std::string("step_ms.") + k + " missing or negative");
  }
  if (!(m["step_ms"]["median"].get<double>() <= m["step_ms"]["p95"].get<double>() &&
        m["step_ms"]["p95"].get<double>() <= m["step_ms"]["max"].get<double>()))
    return bad("step_ms must satisfy median <= p95 <= max");
  if (m.value("finite", false) != true) return bad("finite is not true");
  if (!m.contains(lab) || !m[lab].is_object() || m[lab].empty()) return bad("no scene metrics under '" + lab + "'");
  for (const auto& [key, value] : m[lab].items()) {
    if (value.is_null()) return bad("scene metric " + key + " is null (non-finite)");
    if (value.is_number_float() && !std::isfinite(value.get<double>()))
      return bad("scene metric " + key + " is not finite");
  }
  return 0;
}

int checkSame(const std::string& a, const std::string& b) {
  json ja, jb;
  if (!load(a, ja) || !load(b, jb)) return 1;
  ja = pba::app::withoutTimings(std::move(ja));
  jb = pba::app::withoutTimings(std::move(jb));
  if (ja == jb) return 0;
  std::cerr << "metrics differ:\n" << json::diff(ja, jb).dump(2) << '\n';
  return 1;
}

// An A/B report (--compare): "a" and "b" are each a full report of their run, "compare" says what the sides
// were; `same` says whether the two runs must agree (timings aside) or differ.
int checkSides(const std::string& path, const std::string& lab, bool same) {
  json m;
  if (!load(path, m)) return 1;
  for (const char* k : {"a", "b", "compare"}) {
    if (!m.contains(k) || !m[k].is_object()) {
      std::cerr << path << ": no \"" << k << "\" object\n";
      return 1;
    }
  }
  if (!m["a"].contains(lab) || !m["b"].contains(lab)) {
    std::cerr << path << ": a or b has no scene metrics under '" << lab << "'\n";
    return 1;
  }
  if (same) {
    const json a = pba::app::withoutTimings(m["a"]), b = pba::app::withoutTimings(m["b"]);
    if (a == b) return 0;
    std::cerr << path << ": A and B differ: " << json::diff(a, b).dump() << '\n';
    return 1;
  }
  // Different settings must change what the scene measures (not only the reports' dt and step count),
  // unless an exercise stub holds the physics still (the student release): then both sides agree.
  const json a = pba::app::withoutTimings(m["a"][lab]), b = pba::app::withoutTimings(m["b"][lab]);
  if (a != b) return 0;
  if (m["a"].contains("not_implemented") && !m["a"]["not_implemented"].empty()) {
    std::cout << path << ": A and B agree while exercises are stubbed: " << m["a"]["not_implemented"].dump() << '\n';
    return 0;
  }
  std::cerr << path << ": A and B have equal scene metrics with different settings\n";
  return 1;
}

int checkImage(const std::string& path) {
  std::string error;
  pba::graphics::ImageStats s;
  const pba::graphics::ImageStats* stats = &s;
  if (!pba::graphics::imageStats(path, &s, &error)) {
    std::cerr << error << '\n';
    return 1;
  }
  std::cout << path << ": " << stats->width << "x" << stats->height << ", " << stats->distinctColors
            << " colours, luminance stddev " << stats->luminanceStdDev << '\n';
  // A blank or cleared-only frame has a handful of colours and almost no contrast; a lit scene with
  // a grid, shadows and panels has thousands of colours and a standard deviation well above 10.
  if (stats->distinctColors < 64 || stats->luminanceStdDev < 8.0) {
    std::cerr << path << ": looks blank\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "metrics" && (argc == 4 || argc == 5)) return checkMetrics(argv[2], argv[3], argc == 5 ? argv[4] : "");
  if (mode == "same" && argc == 4) return checkSame(argv[2], argv[3]);
  if (mode == "image" && argc == 3) return checkImage(argv[2]);
  if ((mode == "same-sides" || mode == "different-sides") && argc == 4)
    return checkSides(argv[2], argv[3], mode == "same-sides");
  std::cerr << "usage: pba_lab_check metrics FILE LAB [SCENE] | same A B | image FILE.png | same-sides FILE LAB | "
               "different-sides FILE LAB\n";
  return 2;
}
