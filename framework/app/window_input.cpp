#include "app/window_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace pba::app {
namespace {
Ray toRay(const graphics::Ray& r) { return Ray{Vec3(r.origin), glm::normalize(Vec3(r.direction))}; }
}  // namespace

void WindowInput::update(LabSession& session, UiState& ui, graphics::OrbitCamera& camera, float w, float h) {
  keys(session, ui);
  mouse(session, camera, w, h);
}

void WindowInput::keys(LabSession& session, UiState& ui) {
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (pressed(GLFW_KEY_SPACE) || pressed(GLFW_KEY_P)) session.togglePause();
  if (ImGui::IsKeyPressed(GLFW_KEY_O, true)) session.singleStep();  // held: steps repeatedly
  if (pressed(GLFW_KEY_R)) session.reset();
  if (pressed(GLFW_KEY_LEFT_BRACKET)) session.nextScene(-1);
  if (pressed(GLFW_KEY_RIGHT_BRACKET)) session.nextScene(+1);
  for (int i = 0; i < 9; ++i)
    if (pressed(GLFW_KEY_1 + i)) session.applyPreset(i);
  if (pressed(GLFW_KEY_F1) || pressed(GLFW_KEY_H)) ui.showHelp = !ui.showHelp;
  if (pressed(GLFW_KEY_F12)) ui.screenshotRequested = true;
  if (pressed(GLFW_KEY_L)) ui.lecture = !ui.lecture;
  if (pressed(GLFW_KEY_TAB)) ui.hideUi = !ui.hideUi;
  if (pressed(GLFW_KEY_F)) ui.frameRequested = true;
}

void WindowInput::mouse(LabSession& session, graphics::OrbitCamera& camera, float w, float h) {
  const ImGuiIO& io = ImGui::GetIO();
  const ImVec2 cursor = io.MousePos;
  const bool overUi = io.WantCaptureMouse && !handle_;
  Scene& scene = session.runner().scene();

  // Left button: pick on press, drag on a camera-facing plane through the hit point, release.
  if (!overUi && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    const Ray ray = toRay(camera.ray(cursor.x, cursor.y, w, h));
    if (const std::optional<PickHit> hit = scene.pick(ray)) {
      handle_ = hit->handle;
      planePoint_ = hit->point;
      planeNormal_ = -Vec3(camera.forward());
      scene.drag(hit->handle, hit->point);
    }
  }
  if (handle_ && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    const Ray ray = toRay(camera.ray(cursor.x, cursor.y, w, h));
    if (const std::optional<Real> t = intersectRayPlane(ray, planePoint_, planeNormal_)) scene.drag(*handle_, pointAt(ray, *t));
  }
  if (handle_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    scene.release(*handle_);
    handle_.reset();
  }
  if (overUi) return;

  const ImVec2 delta = io.MouseDelta;
  const bool panning = ImGui::IsMouseDown(ImGuiMouseButton_Middle) || (io.KeyShift && ImGui::IsMouseDown(ImGuiMouseButton_Right));
  if (panning) camera.pan(delta.x, delta.y, glm::vec2(w, h));
  else if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) camera.rotate(delta.x, delta.y);
  if (io.MouseWheel != 0.0f) camera.zoom(io.MouseWheel);
}

}  // namespace pba::app
