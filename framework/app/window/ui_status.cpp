#include "app/window/ui_status.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <imgui.h>
#include <imgui_internal.h>

#include "app/runner/exercise_catalog.h"
#include "physics/exercises/not_implemented.h"

namespace pba::app {
namespace {

nlohmann::json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }
nlohmann::json vec(const Vec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json cameraJson(const graphics::OrbitCamera& c) {
  return {{"yaw", c.yaw},
          {"pitch", c.pitch},
          {"distance", c.distance},
          {"fov_y", c.fovY},
          {"target", vec(c.target)},
          {"eye", vec(c.eye())},
          {"right", vec(c.right())},
          {"up", vec(c.up())},
          {"forward", vec(c.forward())},
          {"rotate_speed", c.rotateSpeed},
          {"zoom_factor", c.zoomFactor}};
}

nlohmann::json pixelJson(const graphics::OrbitCamera& camera, const Vec3& p, const glm::vec2& viewport) {
  const graphics::ScreenPoint s = camera.project(glm::vec3(p), viewport.x, viewport.y);
  return {{"pixel", {s.pixel.x, s.pixel.y}}, {"visible", s.visible}};
}

/// The ImGui windows drawn this frame (top-level ones: panels, plots, overlays, help, legend).
nlohmann::json windowsJson() {
  nlohmann::json out = nlohmann::json::array();
  const ImGuiContext* context = ImGui::GetCurrentContext();
  if (!context) return out;
  for (const ImGuiWindow* w : context->Windows) {
    if (!w->Active || w->Hidden ||
        (w->Flags & (ImGuiWindowFlags_ChildWindow | ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_Popup)))
      continue;
    if (std::string(w->Name).rfind("Debug##", 0) == 0) continue;  // ImGui's implicit fallback window
    const float y1 = w->Collapsed ? w->TitleBarRect().Max.y : w->Pos.y + w->Size.y;
    out.push_back({{"name", w->Name}, {"rect", {w->Pos.x, w->Pos.y, w->Pos.x + w->Size.x, y1}}});
  }
  return out;
}

/// The screen rectangle of the drawn bounds' eight corners (those in front of the camera).
nlohmann::json sceneRectJson(const graphics::OrbitCamera& camera, const UiFrame& f) {
  if (!f.hasBounds) return nullptr;
  glm::vec2 lo(1e30f), hi(-1e30f);
  int inFront = 0;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner((i & 1) ? f.boundsMax.x : f.boundsMin.x, (i & 2) ? f.boundsMax.y : f.boundsMin.y,
                           (i & 4) ? f.boundsMax.z : f.boundsMin.z);
    const graphics::ScreenPoint s = camera.project(corner, f.viewport.x, f.viewport.y);
    if (glm::dot(corner - camera.eye(), camera.forward()) <= 0.0f) continue;
    ++inFront;
    lo = glm::min(lo, s.pixel);
    hi = glm::max(hi, s.pixel);
  }
  if (inFront == 0) return nullptr;
  return {lo.x, lo.y, hi.x, hi.y};
}

}  // namespace

std::string uiStatusPath() {
  const char* path = std::getenv(kUiStatusVariable);
  return path ? std::string(path) : std::string();
}

nlohmann::json uiStatus(const LabSession& session, const UiState& ui, const graphics::OrbitCamera& camera,
                        const UiFrame& f) {
  const SceneRunner& runner = session.runner();
  const Scene& scene = runner.scene();
  nlohmann::json presets = nlohmann::json::array();
  for (const Preset& p : scene.presets()) presets.push_back({{"name", p.name}, {"params", p.params}});
  nlohmann::json handles = nlohmann::json::array();
  nlohmann::json picked = nullptr;
  const std::vector<DragHandle> list = scene.dragHandles();
  for (size_t i = 0; i < list.size(); ++i) {
    nlohmann::json h = pixelJson(camera, list[i].position, f.viewport);
    h["handle"] = list[i].handle;
    h["position"] = vec(list[i].position);
    if (f.picked && *f.picked == list[i].handle) {
      picked = h;
      picked["drag_plane_point"] = vec(f.dragPlanePoint);
    }
    if (i < kMaxStatusHandles) handles.push_back(std::move(h));
  }
  nlohmann::json widgets = nlohmann::json::object();
  for (const auto& [name, r] : ui.widgets) widgets[name] = {r.x0, r.y0, r.x1, r.y1};
  const bool noticeShown = ui.noticeVisible(ImGui::GetTime());
  const RewindHistory& h = session.history();
  const nlohmann::json history = {{"frames", h.size()}, {"cursor", h.cursor()},      {"seconds", h.seconds()},
                                  {"bytes", h.bytes()}, {"max_bytes", h.maxBytes()}, {"max_frames", h.maxFrames()}};
  // The plotted series as the plot panel has them: their length and last sample.
  nlohmann::json plots = nlohmann::json::object();
  for (const std::string& name : session.settings().plotted) {
    const std::vector<double> series = session.plots().series(name);
    if (!series.empty()) plots[name] = {{"samples", series.size()}, {"last", series.back()}};
  }
  nlohmann::json compare = nullptr;
  if (const SceneRunner* b = session.partner())
    compare = {{"steps", b->steps()},
               {"sim_time_s", b->simTime()},
               {"paused", b->paused()},
               {"scene", b->sceneName()},
               {"params", b->scene().params().toJson()},
               {"metrics", b->scene().metrics()},
               {"editing_b", session.editingB()}};
  const StepSummary physics = runner.frameStats().summary();  // physics time per frame, recent frames
  return {{"frame", f.frame},
          {"physics_ms", {{"median", physics.median}, {"p95", physics.p95}}},
          {"frame_ms", ui.frameMs},
          {"history", history},
          {"compare", compare},
          {"plots", plots},
          {"steps", runner.steps()},
          {"sim_time_s", runner.simTime()},
          {"paused", runner.paused()},
          {"scene", runner.sceneName()},
          {"lab", session.lab()},
          {"lecture", ui.lecture},
          {"ui_hidden", ui.hideUi},
          {"panel_collapsed", ui.panelCollapsed},
          {"plots_shown", ui.showPlots},
          {"clipped_labels", ui.clippedLabels},
          {"help_shown", ui.showHelp},
          {"message", session.message()},
          {"file_error", session.fileError()},
          {"guard", runner.guardMessage() ? *runner.guardMessage() : std::string()},
          // This lab's exercises that ran as stubs (a hand-out): a check whose path runs them skips.
          {"stubbed_exercises", stubbedExercises(session.exercises(), exercises::notImplementedTags())},
          {"notice", noticeShown ? ui.notice : std::string()},
          {"last_screenshot", ui.lastScreenshot},
          {"last_scene_image", ui.lastSceneImage},
          {"recording", ui.recording},
          {"viewport", {f.viewport.x, f.viewport.y}},
          {"font_px", ImGui::GetFontSize()},
          {"camera", cameraJson(camera)},
          {"params", scene.params().toJson()},
          {"metrics", scene.metrics()},
          {"presets", presets},
          {"handles", handles},
          {"picked", picked},
          {"dragging", f.dragging},
          {"legend_entries", scene.legend().size()},
          {"windows", windowsJson()},
          {"widgets", widgets},
          {"scene_rect", sceneRectJson(camera, f)}};
}

Status writeUiStatus(const std::string& path, const nlohmann::json& status) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    if (!out) return Error{path + ": cannot write the UI status"};
    out << status.dump() << '\n';
    if (!out) return Error{path + ": cannot write the UI status"};
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) return Error{path + ": cannot write the UI status (" + ec.message() + ")"};
  return Status::success();
}

}  // namespace pba::app
