#include "app/runner/camera_json.h"

#include <cmath>

#include "physics/core/types.h"

namespace pba::app {
namespace {
bool finiteIn(const nlohmann::json& v, double lo, double hi) {
  return v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() >= lo && v.get<double>() <= hi;
}
}  // namespace

Result<CameraView> cameraFromJson(const nlohmann::json& j, const std::string& field) {
  if (!j.is_object()) return Error{field + ": expected an object {target, distance, yaw_deg, pitch_deg}"};
  for (const auto& [key, value] : j.items()) {
    if (key != "target" && key != "distance" && key != "yaw_deg" && key != "pitch_deg")
      return Error{field + "." + key + ": unknown key (expected target, distance, yaw_deg, pitch_deg)"};
  }
  CameraView view;
  if (j.contains("target")) {
    const nlohmann::json& t = j["target"];
    if (!t.is_array() || t.size() != 3 || !finiteIn(t[0], -1e4, 1e4) || !finiteIn(t[1], -1e4, 1e4) ||
        !finiteIn(t[2], -1e4, 1e4))
      return Error{field + ".target: expected [x, y, z] in metres, got " + t.dump()};
    view.target = Vec3(t[0].get<double>(), t[1].get<double>(), t[2].get<double>());
  }
  if (j.contains("distance")) {
    if (!finiteIn(j["distance"], 0.01, 1e4))
      return Error{field + ".distance: must be a number in [0.01, 10000] m, got " + j["distance"].dump()};
    view.distance = j["distance"].get<double>();
  }
  if (j.contains("yaw_deg")) {
    if (!finiteIn(j["yaw_deg"], -360.0, 360.0))
      return Error{field + ".yaw_deg: must be a number in [-360, 360], got " + j["yaw_deg"].dump()};
    view.yaw = degToRad(j["yaw_deg"].get<double>());
  }
  if (j.contains("pitch_deg")) {
    if (!finiteIn(j["pitch_deg"], -89.0, 89.0))
      return Error{field + ".pitch_deg: must be a number in [-89, 89], got " + j["pitch_deg"].dump()};
    view.pitch = degToRad(j["pitch_deg"].get<double>());
  }
  return view;
}

nlohmann::json cameraToJson(const CameraView& v) {
  return {{"target", {v.target.x, v.target.y, v.target.z}},
          {"distance", v.distance},
          {"yaw_deg", radToDeg(v.yaw)},
          {"pitch_deg", radToDeg(v.pitch)}};
}

}  // namespace pba::app
