#pragma once
// Camera bookmarks in scene files and demo steps: {"target": [x, y, z], "distance": d, "yaw_deg": a,
// "pitch_deg": b} [m, m, degrees], the orbit camera's own terms (docs/architecture.md §4, "Scene files").
#include <string>

#include <nlohmann/json.hpp>

#include "app/runner/scene.h"
#include "physics/core/result.h"

namespace pba::app {

/// Reads a camera; errors name `field` and the member ("camera.distance: must be a number in ...").
Result<CameraView> cameraFromJson(const nlohmann::json& j, const std::string& field);
nlohmann::json cameraToJson(const CameraView& view);

}  // namespace pba::app
