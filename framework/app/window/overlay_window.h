#pragma once
// A scene's own window in the right-hand column (Scene::overlayUi): the IK comparison's residual plot, the
// oscillator's energy plot. Window mode only; it uses ImGui, which the scenes' overlayUi may call.
#include <imgui.h>

#include "app/runner/scene.h"

namespace pba::app {

/// Begins a window of `title` docked at the bottom of `column`, as wide as it and as tall as its contents,
/// neither moved nor resized by the user. End it with ImGui::End().
void beginColumnWindow(const ScreenRect& column, const char* title);

/// A colour of the physics library's palette as ImGui's packed colour.
ImU32 imguiColor(const Color& c);

}  // namespace pba::app
