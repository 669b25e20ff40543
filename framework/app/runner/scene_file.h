#pragma once
// Scene files (docs/architecture.md §4): JSON under resources/scenes/<lab>/, round-trip exact.
//   { "lab": "hello", "scene": "drop", "dt": 0.008333, "params": { "restitution": 0.8, ... } }
// "dt" is optional. Unknown keys are errors, so that a typo never goes unnoticed.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/runner/scene.h"
#include "physics/core/result.h"

namespace pba::app {

/// Limits of what a scene file may be: a parameter file of a few kilobytes is the norm.
inline constexpr std::uintmax_t kMaxSceneFileBytes = 16u << 20;  ///< 16 MiB
inline constexpr int kMaxSceneFileDepth = 64;                    ///< arrays and objects nested

struct LoadedScene {
  std::unique_ptr<Scene> scene;      ///< created and configured, not yet reset
  std::string name;                  ///< registered scene name
  std::optional<Real> dt;            ///< [s] when the file sets one
  std::optional<CameraView> camera;  ///< the file's camera bookmark, when it has one (camera_json.h)
};

/// Builds a scene from a file. Errors read "<path>: <field>: <problem>" (with the line for syntax errors).
Result<LoadedScene> loadSceneFile(const std::string& path, const std::string& lab);
/// The same from JSON text already read; `path` is only used in messages.
Result<LoadedScene> parseSceneJson(const std::string& text, const std::string& path, const std::string& lab);

/// The file contents for the scene's current parameters.
nlohmann::json sceneToJson(const std::string& lab, const std::string& name, const Scene& scene, std::optional<Real> dt,
                           std::optional<CameraView> camera = std::nullopt);
/// Writes sceneToJson() pretty-printed. Error names the path.
Status saveSceneFile(const std::string& path, const std::string& lab, const std::string& name, const Scene& scene,
                     std::optional<Real> dt, std::optional<CameraView> camera = std::nullopt);

/// Applies a JSON object of parameters (scene file "params" or a preset); messages use fieldPrefix.
Status applyParams(Scene& scene, const nlohmann::json& params, const std::string& fieldPrefix);

/// Every parameter value of `preset` of registered scene `sceneName`: the scene's defaults (those of
/// a freshly created instance), then the preset's own values. Error when no such scene is registered
/// or a value is invalid (checked on that fresh instance, never on a running scene).
Result<nlohmann::json> presetParams(const std::string& sceneName, const Preset& preset);

}  // namespace pba::app
