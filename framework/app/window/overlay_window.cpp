#include "app/window/overlay_window.h"

namespace pba::app {

void beginColumnWindow(const ScreenRect& column, const char* title) {
  ImGui::SetNextWindowPos(ImVec2(column.x1, column.y1), ImGuiCond_Always, ImVec2(1.0f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(column.x1 - column.x0, 0.0f), ImGuiCond_Always);
  ImGui::Begin(title, nullptr,
               ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoScrollbar);
}

ImU32 imguiColor(const Color& c) { return ImGui::GetColorU32(ImVec4(c.r, c.g, c.b, c.a)); }

}  // namespace pba::app
