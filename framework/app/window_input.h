#pragma once
// Keys and mouse of DESIGN.md §3, the same in every lab. Reads ImGui's input state (ImGui 1.86:
// keys are indexed by GLFW key codes) so that typing in a text field never triggers a lab key.
#include <optional>

#include "app/lab_session.h"
#include "app/lab_ui.h"
#include "graphics/camera.h"

namespace pba::app {

class WindowInput {
 public:
  /// Handles this frame's keys and mouse. viewport: window size in screen coordinates.
  void update(LabSession& session, UiState& ui, graphics::OrbitCamera& camera, float viewportW, float viewportH);
  bool dragging() const { return handle_.has_value(); }

 private:
  void keys(LabSession& session, UiState& ui);
  void mouse(LabSession& session, graphics::OrbitCamera& camera, float w, float h);

  std::optional<int> handle_;  ///< the scene object being dragged
  Vec3 planePoint_{0.0};       ///< the drag plane faces the camera through the picked point
  Vec3 planeNormal_{0.0, 0.0, 1.0};
};

}  // namespace pba::app
