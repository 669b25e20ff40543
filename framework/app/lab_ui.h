#pragma once
// The lab's ImGui panels (docs/architecture.md §3): simulation controls, scene description, parameters with
// units and (?) tooltips, metrics, live plots, scene files, exercise status, the help overlay, the
// instability guard's message and the not-implemented banner.
#include <string>

#include "app/lab_session.h"

namespace pba::app {

struct UiState {
  bool showHelp = false;
  bool hideUi = false;
  bool lecture = false;
  bool screenshotRequested = false;
  bool frameRequested = false;
  double frameMs = 0.0;     ///< wall time of the last displayed frame [ms]
  char scenePath[512] = {};  ///< the scene file field
};

/// Draws every panel for this frame. Call between ImGui::NewFrame() and ImGui::Render().
void drawLabUi(LabSession& session, UiState& ui);

/// Width of the main panel in pixels at the current font size (for camera framing).
float panelWidthPixels();
/// Width [pixels] of the right-hand column reserved for a scene's own window (Scene::wantsOverlay).
float overlayWidthPixels();

}  // namespace pba::app
