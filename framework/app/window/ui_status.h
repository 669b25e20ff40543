#pragma once
// The window's machine-readable status for automated UI tests (tests/ui): with the environment
// variable PBA_UI_STATUS=FILE set, the window rewrites FILE (atomically: a temporary file renamed over
// it) after every frame with what a test needs to check the effect of a key or a drag: the frame
// counter, the runner's clock and step count, the modes (paused, lecture, hidden panels, help), the
// scene, its parameters and presets, the camera, the draggable objects on screen, the panels'
// rectangles, the last screenshot and the on-screen notice. Nothing reads it back: it is output only.
// With it on, F12 also writes the scene alone next to the screenshot (app/window/scene_image.h).
#include <optional>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "app/window/lab_session.h"
#include "app/window/lab_ui.h"
#include "graphics/camera.h"
#include "physics/core/result.h"

namespace pba::app {

inline constexpr const char* kUiStatusVariable = "PBA_UI_STATUS";
inline constexpr std::size_t kMaxStatusHandles = 48;  ///< draggable objects listed per frame

/// The status file named by PBA_UI_STATUS, or empty when the variable is unset.
std::string uiStatusPath();

/// What the window knows of this frame beyond the session and the UI state.
struct UiFrame {
  long frame = 0;                              ///< frames displayed so far
  glm::vec2 viewport{1280.0f, 720.0f};         ///< window size [screen coordinates]
  std::optional<int> picked;                   ///< handle being dragged, else the last one dragged
  glm::vec3 dragPlanePoint{0.0f};              ///< [m] on the plane that drag moved on (faces the camera)
  bool dragging = false;                       ///< the left button holds `picked` now
  bool hasBounds = false;                      ///< the scene drew something
  glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  ///< [m] of what it drew this frame
};

/// The status of this frame. Call after ImGui::Render() (it lists the ImGui windows drawn).
nlohmann::json uiStatus(const LabSession& session, const UiState& ui, const graphics::OrbitCamera& camera,
                        const UiFrame& frame);
/// Writes `status` to `path` through a temporary file and a rename, so a reader never sees half a file.
Status writeUiStatus(const std::string& path, const nlohmann::json& status);

}  // namespace pba::app
