#include "app/runner/scene_file.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "app/runner/camera_json.h"
#include "app/runner/message_text.h"
#include "app/runner/scene_registry.h"
#include "app/runner/scene_runner.h"

namespace pba::app {
namespace {

int lineOfByte(const std::string& text, std::size_t byte) {
  int line = 1;
  for (std::size_t i = 0; i < text.size() && i + 1 < byte; ++i)
    if (text[i] == '\n') ++line;
  return line;
}

Error fileError(const std::string& path, const std::string& message) { return Error{oneLine(path) + ": " + message}; }

/// nlohmann's message without its "[json.exception.parse_error.101] " tag.
std::string jsonMessage(const std::exception& e) {
  const std::string what = e.what();
  const std::size_t tag = what.find("] ");
  return oneLine(!what.empty() && what[0] == '[' && tag != std::string::npos ? what.substr(tag + 2) : what);
}

/// The byte where arrays and objects nest deeper than kMaxSceneFileDepth (outside strings), or npos.
/// Checked before parsing, so that no deep value is ever built, walked or destroyed recursively.
std::size_t tooDeepAt(const std::string& text) {
  int depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxSceneFileDepth) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return std::string::npos;
}

/// Parses strictly: a key given twice in one object is an error (JSON keeps the last silently, so a
/// pasted value would win over the one the user edited). Error: "line N: ..." or "<field>: ...".
Result<nlohmann::json> parseStrict(const std::string& text) {
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    return Error{"line " + std::to_string(lineOfByte(text, nul + 1)) + ": a NUL byte (this is not a text file)"};
  if (const std::size_t at = tooDeepAt(text); at != std::string::npos)
    return Error{"line " + std::to_string(lineOfByte(text, at + 1)) + ": nested deeper than " +
                 std::to_string(kMaxSceneFileDepth) + " levels"};
  std::vector<std::set<std::string>> keys;  // per open object: the keys seen so far
  std::vector<std::string> path;            // the key of each open object (its field name)
  std::string duplicate;
  const nlohmann::json::parser_callback_t check = [&](int, nlohmann::json::parse_event_t event,
                                                      nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    if (event == E::object_start) {
      keys.emplace_back();
    } else if (event == E::object_end) {
      if (!keys.empty()) keys.pop_back();
      if (!path.empty() && path.size() > keys.size()) path.pop_back();
    } else if (event == E::key && !keys.empty()) {
      const std::string key = parsed.get<std::string>();
      path.resize(keys.size() - 1);
      if (!keys.back().insert(key).second && duplicate.empty()) {
        std::string field;
        for (const std::string& k : path) field += shownText(k) + ".";
        duplicate = field + shownText(key);
      }
      path.push_back(key);
    }
    return true;
  };
  try {
    nlohmann::json doc = nlohmann::json::parse(text, check);
    if (!duplicate.empty()) return Error{duplicate + ": given twice (each key at most once)"};
    return doc;
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is the 1-based position of the error; report the line, which is what an editor shows.
    return Error{"line " + std::to_string(lineOfByte(text, e.byte)) + ": not valid JSON (" + jsonMessage(e) + ")"};
  } catch (const nlohmann::json::exception& e) {
    // A number beyond the range of a double (1e400): nlohmann names the token but not its place.
    const std::string what = e.what();
    const std::size_t quote = what.find('\'');
    const std::string token = quote == std::string::npos ? "" : what.substr(quote + 1, what.rfind('\'') - quote - 1);
    const std::size_t at = token.empty() ? std::string::npos : text.find(token);
    return Error{(at == std::string::npos ? std::string() : "line " + std::to_string(lineOfByte(text, at + 1)) + ": ") +
                 "not valid JSON (" + jsonMessage(e) + ")"};
  }
}

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
  Result<nlohmann::json> parsed = parseStrict(text);
  if (!parsed) return fileError(path, parsed.error());
  const nlohmann::json& doc = parsed.value();
  if (!doc.is_object()) return fileError(path, "expected a JSON object at the top level");
  for (const auto& [key, value] : doc.items()) {
    if (key != "lab" && key != "scene" && key != "dt" && key != "params" && key != "description" && key != "camera")
      return fileError(path, shownText(key) + ": unknown key (expected lab, scene, dt, params, camera, description)");
  }
  if (!doc.contains("lab") || !doc["lab"].is_string()) return fileError(path, "lab: missing or not a string");
  if (doc["lab"].get<std::string>() != lab)
    return fileError(path,
                     "lab: this file is for lab '" + shownText(doc["lab"].get<std::string>()) + "', not '" + lab + "'");
  if (!doc.contains("scene") || !doc["scene"].is_string()) return fileError(path, "scene: missing or not a string");
  if (doc.contains("description") && !doc["description"].is_string())
    return fileError(path, "description: expected a string, got " + shownJson(doc["description"]));
  const std::string name = doc["scene"].get<std::string>();
  const SceneEntry* entry = findScene(name);
  if (!entry) return fileError(path, "scene: unknown scene '" + shownText(name) + "' (see --list-scenes)");

  LoadedScene out{entry->create(), name, std::nullopt};
  if (doc.contains("dt")) {
    const auto& dt = doc["dt"];
    if (!dt.is_number() || !(dt.get<double>() >= kMinDt && dt.get<double>() <= kMaxDt))
      return fileError(path, "dt: must be a number in [1e-06, 0.1] s, got " + shownJson(dt));
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
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) return fileError(path, "is a directory, not a scene file");
  // A device or a pipe (/dev/zero, /dev/stdin) would be read until it ends, which may be never.
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec))
    return fileError(path, "is not a regular file (a device or a pipe?)");
  std::ifstream in(path, std::ios::binary);
  if (!in) return fileError(path, "cannot open the file");
  if (const auto size = fs::file_size(path, ec); !ec && size > kMaxSceneFileBytes)
    return fileError(path, "is " + std::to_string(size) + " bytes; a scene file is at most " +
                               std::to_string(kMaxSceneFileBytes) + " bytes");
  // Read at most one byte past the limit, whatever size the system reported: a file that grows, or a
  // device that passes for a regular file (Wine's /dev/zero), must not be read without end.
  std::string text(kMaxSceneFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxSceneFileBytes)
    return fileError(path, "is more than " + std::to_string(kMaxSceneFileBytes) + " bytes; a scene file is at most " +
                               std::to_string(kMaxSceneFileBytes) + " bytes");
  return parseSceneJson(text, path, lab);
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
