#include "app/window/window_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include "app/window/scene_draw.h"

namespace pba::app {
namespace {
Ray toRay(const graphics::Ray& r) { return Ray{Vec3(r.origin), glm::normalize(Vec3(r.direction))}; }

/// Diagonal [m] of what the scene draws (the nudge step's fallback scale).
Real drawnSize(const Scene& scene) {
  graphics::DebugRenderer probe;
  SceneDraw draw(probe);
  scene.draw(draw);
  glm::vec3 lo, hi;
  return probe.bounds(&lo, &hi) ? Real(glm::length(hi - lo)) : 1.0;
}
}  // namespace

void WindowInput::install(GLFWwindow* window) {
  glfwSetWindowUserPointer(window, this);
  glfwSetKeyCallback(window, &WindowInput::keyCallback);
}

void WindowInput::keyCallback(GLFWwindow* window, int key, int scancode, int action, int mods) {
  ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
  // Only the single-step and nudge keys repeat while held; a held Space must not toggle pause repeatedly.
  const bool repeats = key == GLFW_KEY_O || key == GLFW_KEY_COMMA || key == GLFW_KEY_PERIOD ||
                       nudgeDirectionForKey(key, mods).has_value();
  if (action == GLFW_PRESS || (action == GLFW_REPEAT && repeats)) {
    if (auto* self = static_cast<WindowInput*>(glfwGetWindowUserPointer(window))) self->pressed_.push_back({key, mods});
  }
}

void WindowInput::update(LabSession& session, UiState& ui, graphics::OrbitCamera& camera, float w, float h) {
  keys(session, ui, camera);
  mouse(session, camera, w, h);
}

void WindowInput::keys(LabSession& session, UiState& ui, const graphics::OrbitCamera& camera) {
  std::vector<KeyPress> keys;
  keys.swap(pressed_);
  if (ImGui::GetIO().WantCaptureKeyboard) return;  // typing in a text field
  for (const auto [key, mods] : keys) {
    if (ui.demoActive && (key == GLFW_KEY_PAGE_DOWN || key == GLFW_KEY_PAGE_UP)) {  // a presenter's clicker
      ui.demoMove += key == GLFW_KEY_PAGE_DOWN ? 1 : -1;
      continue;
    }
    if (ui.demoActive && key == GLFW_KEY_N) {
      ui.showNotes = !ui.showNotes;
      continue;
    }
    if (const std::optional<NudgeDirection> d = nudgeDirectionForKey(key, mods)) {
      const Real size = drawnSize(session.runner().scene());
      if (!session.nudge(*d, Vec3(camera.right()), Vec3(camera.up()), Vec3(camera.forward()), size, nudgeIsFine(mods)))
        session.setMessage("This scene has no target to move with the arrow keys");
      continue;
    }
    switch (key) {
      case GLFW_KEY_SPACE:
      case GLFW_KEY_P:
        session.togglePause();
        break;
      case GLFW_KEY_O:
        session.singleStep();
        break;              // held: repeats
      case GLFW_KEY_COMMA:  // one simulation step back (Shift: one second); held: repeats
      case GLFW_KEY_PERIOD:
        session.stepBy((key == GLFW_KEY_COMMA ? -1 : 1) *
                       ((mods & GLFW_MOD_SHIFT) != 0 ? session.stepsPerSecond() : std::int64_t{1}));
        break;
      case GLFW_KEY_R:
        session.reset();
        break;
      case GLFW_KEY_LEFT_BRACKET:
        session.nextScene(-1);
        break;
      case GLFW_KEY_RIGHT_BRACKET:
        session.nextScene(+1);
        break;
      case GLFW_KEY_F1:
      case GLFW_KEY_H:
        ui.showHelp = !ui.showHelp;
        break;
      case GLFW_KEY_F12:
        ui.screenshotRequested = true;
        break;
      case GLFW_KEY_F9:
        ui.recordRequested = kRecordingAvailable;
        break;
      // Mode changes wait for the end of the frame (UiState::applyPending).
      case GLFW_KEY_L:
        ui.request(UiChange::ToggleLecture);
        break;
      case GLFW_KEY_TAB:
        ui.request(UiChange::ToggleHideUi);
        break;
      case GLFW_KEY_F:
        ui.frameRequested = true;
        break;
      case GLFW_KEY_C:
        ui.request(UiChange::TogglePanel);
        break;
      case GLFW_KEY_M:
        ui.request(UiChange::TogglePlots);
        break;
      default:
        if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9) session.applyPreset(key - GLFW_KEY_1);
        if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z &&  // a scene's own key (PBA_REGISTER_LAB_KEY)
            session.runner().scene().keyPressed(static_cast<char>('A' + (key - GLFW_KEY_A))))
          session.runner().noteInput();  // it may throw or push: the energy bound counts from here
        break;
    }
  }
}

void WindowInput::mouse(LabSession& session, graphics::OrbitCamera& camera, float w, float h) {
  const ImGuiIO& io = ImGui::GetIO();
  ImVec2 cursor = io.MousePos;
  if (split_) {  // the cursor in the coordinates of the view it is over
    const auto [x0, width] = *split_;
    cursor.x -= cursor.x >= x0 + width ? x0 + width : x0;
    w = width;
  }
  const bool overUi = io.WantCaptureMouse && !handle_;
  Scene& scene = session.runner().scene();

  // Left button: pick on press, drag on a camera-facing plane through the hit point, release.
  if (!overUi && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    const Ray ray = toRay(camera.ray(cursor.x, cursor.y, w, h));
    if (const std::optional<PickHit> hit = scene.pick(ray)) {
      handle_ = hit->handle;
      planePoint_ = hit->point;
      planeNormal_ = -Vec3(camera.forward());
      // Where the scene reports the object's own position, the drag carries that point by the
      // cursor's displacement: the object does not jump so that its centre sits under the grab point.
      grabOffset_ = Vec3(0.0);
      for (const DragHandle& d : scene.dragHandles())
        if (d.handle == hit->handle) grabOffset_ = d.position - hit->point;
      session.drag(hit->handle, hit->point + grabOffset_);
    }
  }
  if (handle_ && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    const Ray ray = toRay(camera.ray(cursor.x, cursor.y, w, h));
    if (const std::optional<Real> t = intersectRayPlane(ray, planePoint_, planeNormal_))
      session.drag(*handle_, pointAt(ray, *t) + grabOffset_);
  }
  if (handle_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    session.release(*handle_);
    lastHandle_ = handle_;
    handle_.reset();
  }
  if (overUi) return;

  const ImVec2 delta = io.MouseDelta;
  const bool panning =
      ImGui::IsMouseDown(ImGuiMouseButton_Middle) || (io.KeyShift && ImGui::IsMouseDown(ImGuiMouseButton_Right));
  if (panning)
    camera.pan(delta.x, delta.y, glm::vec2(w, h));
  else if (ImGui::IsMouseDown(ImGuiMouseButton_Right))
    camera.rotate(delta.x, delta.y);
  if (io.MouseWheel != 0.0f) camera.zoom(io.MouseWheel);
}

}  // namespace pba::app
