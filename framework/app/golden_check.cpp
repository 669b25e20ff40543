#include "app/golden_check.h"

#include <fstream>
#include <ostream>
#include <set>

#include <nlohmann/json.hpp>

#include "app/lab.h"
#include "app/message_text.h"
#include "app/resource_dir.h"
#include "app/scene_registry.h"
#include "app/state_fingerprint.h"
#include "physics/exercises/not_implemented.h"

namespace pba::app {
namespace {

constexpr const char* kRegenerate = "./pba golden --update";
constexpr std::uint64_t kGoldenSeed = 1;  // the labs' default --seed

/// `j` with the repository's location cut from every string ("/home/me/pba/resources/x.bvh" becomes
/// "resources/x.bvh"): a metric naming a resolved file would otherwise depend on where the tree lies.
nlohmann::json withoutTreeLocation(nlohmann::json j, const std::string& root) {
  if (j.is_string()) {
    std::string text = j.get<std::string>();
    for (std::size_t at = text.find(root); at != std::string::npos; at = text.find(root, at))
      text.erase(at, root.size());
    return text;
  }
  if (j.is_object() || j.is_array())  // (a range-for over a number visits the number itself)
    for (auto& value : j) value = withoutTreeLocation(std::move(value), root);
  return j;
}

/// The fingerprint of scene `name` after `frames` display frames from its defaults with `seed`.
Result<nlohmann::json> runScene(const std::string& lab, const std::string& name, long frames, std::uint64_t seed) {
  LabOptions o;
  o.scene = name;
  o.headless = true;
  o.seed = seed;
  SceneRunner runner;
  if (Status s = prepareRunner(lab, o, runner); !s) return Error{s.error()};
  for (long f = 0; f < frames; ++f) runner.advanceFrame(kDisplayFrame);
  return withoutTreeLocation(stateFingerprint(runner), repositoryRoot() + "/");
}

/// "metrics.energy_J 1.25 -> 1.5; draw_hash … -> …" for the first few differences (json::diff paths).
std::string describeDifferences(const nlohmann::json& expected, const nlohmann::json& actual) {
  const nlohmann::json patch = nlohmann::json::diff(expected, actual);
  std::string text;
  int shown = 0;
  for (const nlohmann::json& op : patch) {
    if (shown == 3) {
      text += "; and " + std::to_string(patch.size() - 3) + " more";
      break;
    }
    const nlohmann::json::json_pointer path(op["path"].get<std::string>());
    std::string key = path.to_string().substr(1);
    for (char& c : key)
      if (c == '/') c = '.';
    const std::string before = expected.contains(path) ? expected.at(path).dump() : "(none)";
    const std::string after = actual.contains(path) ? actual.at(path).dump() : "(none)";
    text += (shown ? "; " : "") + key + " " + before + " -> " + after;
    ++shown;
  }
  return text;
}

int updateGolden(const std::string& lab, const GoldenOptions& o, std::ostream& out, std::ostream& err) {
  nlohmann::json golden = {{"lab", lab},
                           {"frames", o.frames},
                           {"seed", kGoldenSeed},
                           {"regenerate", kRegenerate},
                           {"scenes", nlohmann::json::object()}};
  for (const SceneEntry& entry : scenes()) {
    Result<nlohmann::json> fp = runScene(lab, entry.name, o.frames, kGoldenSeed);
    if (!fp) {
      err << "pba-" << lab << ": --update-golden: scene " << entry.name << ": " << oneLine(fp.error()) << '\n';
      return kExitInternal;
    }
    golden["scenes"][entry.name] = fp.value();
    out << "golden " << lab << "/" << entry.name << ": draw hash " << fp.value()["draw_hash"].get<std::string>()
        << " after " << o.frames << " frames\n";
  }
  std::ofstream file(o.file);
  if (!(file << golden.dump(2) << '\n')) {
    err << "pba-" << lab << ": " << oneLine(o.file) << ": cannot write\n";
    return kExitBadInput;
  }
  out << "wrote " << o.file << " (" << scenes().size() << " scenes)\n";
  return kExitOk;
}

Result<nlohmann::json> readGolden(const std::string& lab, const std::string& path) {
  std::ifstream file(path);
  if (!file) return Error{oneLine(path) + ": cannot open (create it with " + kRegenerate + ")"};
  nlohmann::json golden = nlohmann::json::parse(file, nullptr, /*allow_exceptions=*/false);
  if (golden.is_discarded() || !golden.is_object()) return Error{oneLine(path) + ": not a JSON object"};
  if (golden.value("lab", "") != lab) return Error{oneLine(path) + ": lab: expected \"" + lab + "\""};
  if (!golden.contains("frames") || !golden["frames"].is_number_unsigned() || golden["frames"].get<long>() < 1)
    return Error{oneLine(path) + ": frames: expected a whole number >= 1"};
  if (!golden.contains("seed") || !golden["seed"].is_number_unsigned())
    return Error{oneLine(path) + ": seed: expected a whole number >= 0"};
  if (!golden.contains("scenes") || !golden["scenes"].is_object())
    return Error{oneLine(path) + ": scenes: expected an object"};
  return golden;
}

int checkGolden(const std::string& lab, const GoldenOptions& o, std::ostream& out, std::ostream& err) {
  Result<nlohmann::json> read = readGolden(lab, o.file);
  if (!read) {
    err << "pba-" << lab << ": --check-golden: " << read.error() << '\n';
    return kExitBadInput;
  }
  const nlohmann::json& golden = read.value();
  const long frames = golden["frames"].get<long>();
  const std::uint64_t seed = golden["seed"].get<std::uint64_t>();
  int failures = 0;
  std::set<std::string> seen;
  for (const SceneEntry& entry : scenes()) {
    seen.insert(entry.name);
    if (!golden["scenes"].contains(entry.name)) {
      ++failures;
      err << "FAIL " << lab << "/" << entry.name << ": not in " << o.file << " (a new scene: run " << kRegenerate
          << ")\n";
      continue;
    }
    Result<nlohmann::json> fp = runScene(lab, entry.name, frames, seed);
    if (!fp) {
      ++failures;
      err << "FAIL " << lab << "/" << entry.name << ": " << oneLine(fp.error()) << '\n';
      continue;
    }
    const nlohmann::json& expected = golden["scenes"][entry.name];
    if (fp.value() == expected) {
      out << "golden ok: " << lab << "/" << entry.name << " after " << frames << " frames (draw hash "
          << fp.value()["draw_hash"].get<std::string>() << ")\n";
      continue;
    }
    ++failures;
    err << "FAIL " << lab << "/" << entry.name << ": after " << frames << " frames the state differs from " << o.file
        << ": " << describeDifferences(expected, fp.value()) << '\n';
  }
  for (const auto& [name, value] : golden["scenes"].items()) {
    if (seen.count(name)) continue;
    ++failures;
    err << "FAIL " << lab << "/" << name << ": in " << o.file << " but no longer a scene of this lab\n";
  }
  if (failures == 0) return kExitOk;
  if (!exercises::notImplementedTags().empty()) {
    out << "golden check skipped: an exercise stub ran; the golden trajectories are the reference solutions'\n";
    return kExitOk;
  }
  err << failures << " scene(s) of " << lab << " no longer follow their golden trajectory. If the physics (or what "
      << "a scene draws) changed on purpose, regenerate with `" << kRegenerate
      << "` and give the reason in the commit message; otherwise the change is a regression.\n";
  return kExitInternal;
}

}  // namespace

int runGoldenCheck(const std::string& lab, const GoldenOptions& options, std::ostream& out, std::ostream& err) {
  // Golden trajectories are the reference solutions': with an exercise stubbed (a student release, the
  // isolation check) the scenes legitimately move otherwise.
  if (const std::vector<std::string> stubs = exercises::notImplementedTags(); !stubs.empty()) {
    out << "golden check skipped: exercise stubs run in this build (" << stubs.front()
        << (stubs.size() > 1 ? ", ..." : "") << "); the golden trajectories are the reference solutions'\n";
    return options.update ? kExitInternal : kExitOk;
  }
  return options.update ? updateGolden(lab, options, out, err) : checkGolden(lab, options, out, err);
}

}  // namespace pba::app
