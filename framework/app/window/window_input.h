#pragma once
// Keys and mouse of docs/architecture.md §3, the same in every lab. Reads ImGui's input state (ImGui 1.86:
// keys are indexed by GLFW key codes) so that typing in a text field never triggers a lab key.
#include <optional>
#include <utility>
#include <vector>

#include "app/window/lab_session.h"
#include "app/window/lab_ui.h"
#include "graphics/camera.h"

struct GLFWwindow;

namespace pba::app {

class WindowInput {
 public:
  /// Chains a GLFW key callback after ImGui's that queues key presses. ImGui 1.86 samples key state
  /// once per frame, so a tap shorter than a frame (slow scenes, remote desktops, xdotool) would be
  /// lost; the queue keeps every press. Call once after the ImGui GLFW backend is initialised.
  void install(GLFWwindow* window);
  /// Handles this frame's keys and mouse. viewport: window size in screen coordinates.
  void update(LabSession& session, UiState& ui, graphics::OrbitCamera& camera, float viewportW, float viewportH);
  /// A/B runs: two views side by side, each `width` wide, the first from x = x0 [screen coordinates]. The
  /// cursor is read in the view it is over; both views share the camera, so a pick there is the same ray.
  void setSplit(std::optional<std::pair<float, float>> x0AndWidth) { split_ = x0AndWidth; }
  bool dragging() const { return handle_.has_value(); }
  /// The object being dragged, else the one dragged last (the UI status reports it).
  std::optional<int> pickedHandle() const { return handle_ ? handle_ : lastHandle_; }
  /// [m] A point of the plane the last drag moved on (the picked surface point; it faces the camera).
  const Vec3& dragPlanePoint() const { return planePoint_; }

 private:
  void keys(LabSession& session, UiState& ui, const graphics::OrbitCamera& camera);
  void mouse(LabSession& session, graphics::OrbitCamera& camera, float w, float h);

  static void keyCallback(GLFWwindow* window, int key, int scancode, int action, int mods);

  struct KeyPress {
    int key = 0;   ///< GLFW key code
    int mods = 0;  ///< GLFW modifier bits
  };
  std::vector<KeyPress> pressed_;  ///< keys pressed since the last frame
  std::optional<int> handle_;      ///< the scene object being dragged
  std::optional<int> lastHandle_;  ///< the one dragged before
  Vec3 planePoint_{0.0};           ///< the drag plane faces the camera through the picked point
  Vec3 planeNormal_{0.0, 0.0, 1.0};
  Vec3 grabOffset_{0.0};  ///< [m] object position − grab point (Scene::dragHandles), kept while dragging
  std::optional<std::pair<float, float>> split_;
};

}  // namespace pba::app
