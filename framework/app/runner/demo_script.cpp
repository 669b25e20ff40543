#include "app/runner/demo_script.h"

#include <fstream>
#include <sstream>
#include <tuple>

#include "app/runner/camera_json.h"
#include "app/runner/scene_file.h"
#include "app/runner/scene_registry.h"
#include "app/runner/scene_runner.h"

namespace pba::app {
namespace {

Error fail(const std::string& path, const std::string& message) { return Error{path + ": " + message}; }

Result<std::string> text(const nlohmann::json& j, const std::string& key, const std::string& field, bool required) {
  if (!j.contains(key)) {
    if (required) return Error{field + key + ": missing"};
    return std::string();
  }
  if (!j[key].is_string()) return Error{field + key + ": expected a string, got " + j[key].dump()};
  return j[key].get<std::string>();
}

Result<DemoStep> parseStep(const nlohmann::json& j, const std::string& field) {
  if (!j.is_object()) return Error{field + ": expected an object"};
  for (const auto& [key, value] : j.items()) {
    if (key != "title" && key != "lab" && key != "scene" && key != "params" && key != "dt" && key != "camera" &&
        key != "paused" && key != "record" && key != "notes")
      return Error{field + "." + key +
                   ": unknown key (expected title, lab, scene, params, dt, camera, paused, record, notes)"};
  }
  DemoStep step;
  const std::string prefix = field + ".";
  for (auto [member, key, required] :
       {std::tuple{&step.title, "title", false}, std::tuple{&step.lab, "lab", true},
        std::tuple{&step.scene, "scene", true}, std::tuple{&step.record, "record", false},
        std::tuple{&step.notes, "notes", true}}) {
    Result<std::string> value = text(j, key, prefix, required);
    if (!value) return Error{value.error()};
    *member = value.value();
  }
  if (j.contains("params")) {
    if (!j["params"].is_object()) return Error{prefix + "params: expected an object of parameters"};
    step.params = j["params"];
  }
  if (j.contains("dt")) {
    const nlohmann::json& dt = j["dt"];
    if (!dt.is_number() || !(dt.get<double>() >= kMinDt && dt.get<double>() <= kMaxDt))
      return Error{prefix + "dt: must be a number in [1e-06, 0.1] s, got " + dt.dump()};
    step.dt = dt.get<double>();
  }
  if (j.contains("camera")) {
    Result<CameraView> camera = cameraFromJson(j["camera"], prefix + "camera");
    if (!camera) return Error{camera.error()};
    step.camera = camera.value();
  }
  if (j.contains("paused")) {
    if (!j["paused"].is_boolean()) return Error{prefix + "paused: expected true or false, got " + j["paused"].dump()};
    step.paused = j["paused"].get<bool>();
  }
  return step;
}

}  // namespace

Result<DemoScript> loadDemoScript(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(path, "cannot open the file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string content = buffer.str();
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(content);
  } catch (const nlohmann::json::parse_error& e) {
    int line = 1;
    for (std::size_t i = 0; i < content.size() && i + 1 < e.byte; ++i) line += content[i] == '\n';
    return fail(path, "line " + std::to_string(line) + ": not valid JSON (" + e.what() + ")");
  }
  if (!doc.is_object()) return fail(path, "expected a JSON object at the top level");
  for (const auto& [key, value] : doc.items())
    if (key != "title" && key != "chapter" && key != "steps")
      return fail(path, key + ": unknown key (expected title, chapter, steps)");
  DemoScript script;
  script.path = path;
  for (auto [member, key] : {std::pair{&script.title, "title"}, std::pair{&script.chapter, "chapter"}}) {
    Result<std::string> value = text(doc, key, "", std::string(key) == "title");
    if (!value) return fail(path, value.error());
    *member = value.value();
  }
  if (!doc.contains("steps") || !doc["steps"].is_array() || doc["steps"].empty())
    return fail(path, "steps: expected a non-empty list of steps");
  for (std::size_t i = 0; i < doc["steps"].size(); ++i) {
    Result<DemoStep> step = parseStep(doc["steps"][i], "steps[" + std::to_string(i) + "]");
    if (!step) return fail(path, step.error());
    script.steps.push_back(std::move(step.value()));
  }
  return script;
}

Result<std::unique_ptr<Scene>> demoStepScene(const DemoScript& script, std::size_t index, std::uint64_t seed) {
  const DemoStep& step = script.steps.at(index);
  const std::string field = script.path + ": steps[" + std::to_string(index) + "].";
  const SceneEntry* entry = findScene(step.scene);
  if (!entry) return Error{field + "scene: unknown scene '" + step.scene + "' of lab '" + step.lab + "'"};
  std::unique_ptr<Scene> scene = entry->create();
  if (Status s = applyParams(*scene, step.params, "params"); !s) return Error{field + s.error()};
  scene->setSeed(seed);
  if (Status s = scene->validate(); !s) return Error{field + "params: " + s.error()};
  return scene;
}

Status checkDemoStep(const DemoScript& script, std::size_t index) {
  Result<std::unique_ptr<Scene>> scene = demoStepScene(script, index, 1);
  if (!scene) return Error{scene.error()};
  return Status::success();
}

}  // namespace pba::app
