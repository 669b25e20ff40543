#include "app/scene_file.h"

#include <fstream>
#include <sstream>

#include "app/camera_json.h"
#include "app/scene_registry.h"
#include "app/scene_runner.h"

namespace pba::app {
namespace {

int lineOfByte(const std::string& text, std::size_t byte) {
  int line = 1;
  for (std::size_t i = 0; i < text.size() && i + 1 < byte; ++i)
    if (text[i] == '\n') ++line;
  return line;
}

Error fileError(const std::string& path, const std::string& message) { return Error{path + ": " + message}; }

}  // namespace

Status applyParams(Scene& scene, const nlohmann::json& params, const std::string& prefix) {
  if (!params.is_object()) return Error{prefix + ": expected an object of parameters"};
  for (const auto& [key, value] : params.items()) {
    if (Status s = scene.params().setFromJson(key, value, prefix + "."); !s) return s;
  }
  return Status::success();
}

Result<nlohmann::json> presetParams(const std::string& sceneName, const Preset& preset) {
  const SceneEntry* entry = findScene(sceneName);
  if (!entry) return Error{"preset " + preset.name + ": scene '" + sceneName + "' is not registered"};
  const std::unique_ptr<Scene> fresh = entry->create();
  nlohmann::json values = fresh->params().toJson();
  if (!preset.params.is_object()) return Error{"preset " + preset.name + ": expected an object of parameters"};
  for (const auto& [key, value] : preset.params.items()) values[key] = value;
  // Tried on the fresh instance first, so that a bad preset leaves the running scene untouched.
  if (Status s = applyParams(*fresh, values, "preset " + preset.name); !s) return Error{s.error()};
  return values;
}

Result<LoadedScene> parseSceneJson(const std::string& text, const std::string& path, const std::string& lab) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is the 1-based position of the error; report the line, which is what an editor shows.
    return fileError(path, "line " + std::to_string(lineOfByte(text, e.byte)) + ": not valid JSON (" + e.what() + ")");
  }
  if (!doc.is_object()) return fileError(path, "expected a JSON object at the top level");
  for (const auto& [key, value] : doc.items()) {
    if (key != "lab" && key != "scene" && key != "dt" && key != "params" && key != "description" && key != "camera")
      return fileError(path, key + ": unknown key (expected lab, scene, dt, params, camera, description)");
  }
  if (!doc.contains("lab") || !doc["lab"].is_string()) return fileError(path, "lab: missing or not a string");
  if (doc["lab"].get<std::string>() != lab)
    return fileError(path, "lab: this file is for lab '" + doc["lab"].get<std::string>() + "', not '" + lab + "'");
  if (!doc.contains("scene") || !doc["scene"].is_string()) return fileError(path, "scene: missing or not a string");
  const std::string name = doc["scene"].get<std::string>();
  const SceneEntry* entry = findScene(name);
  if (!entry) return fileError(path, "scene: unknown scene '" + name + "' (see --list-scenes)");

  LoadedScene out{entry->create(), name, std::nullopt};
  if (doc.contains("dt")) {
    const auto& dt = doc["dt"];
    if (!dt.is_number() || !(dt.get<double>() >= kMinDt && dt.get<double>() <= kMaxDt))
      return fileError(path, "dt: must be a number in [1e-06, 0.1] s, got " + dt.dump());
    out.dt = dt.get<double>();
  }
  if (doc.contains("params")) {
    if (Status s = applyParams(*out.scene, doc["params"], "params"); !s) return fileError(path, s.error());
  }
  if (doc.contains("camera")) {
    Result<CameraView> camera = cameraFromJson(doc["camera"], "camera");
    if (!camera) return fileError(path, camera.error());
    out.camera = camera.value();
  }
  return out;
}

Result<LoadedScene> loadSceneFile(const std::string& path, const std::string& lab) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fileError(path, "cannot open the file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parseSceneJson(buffer.str(), path, lab);
}

nlohmann::json sceneToJson(const std::string& lab, const std::string& name, const Scene& scene, std::optional<Real> dt,
                           std::optional<CameraView> camera) {
  nlohmann::json doc;
  doc["lab"] = lab;
  doc["scene"] = name;
  if (dt) doc["dt"] = *dt;
  doc["params"] = scene.params().toJson();
  if (camera) doc["camera"] = cameraToJson(*camera);
  return doc;
}

Status saveSceneFile(const std::string& path, const std::string& lab, const std::string& name, const Scene& scene,
                     std::optional<Real> dt, std::optional<CameraView> camera) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return fileError(path, "cannot write the file");
  out << sceneToJson(lab, name, scene, dt, camera).dump(2) << '\n';
  if (!out) return fileError(path, "write failed");
  return Status::success();
}

}  // namespace pba::app
