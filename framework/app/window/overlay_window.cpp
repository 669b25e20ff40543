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

PlotArea::PlotArea(const char* widestTick, float gapInFonts, float heightInFonts)
    : font_(ImGui::GetFontSize()),
      axis_(ImGui::CalcTextSize(widestTick).x + gapInFonts * font_),
      width_(ImGui::GetContentRegionAvail().x - axis_),
      height_(heightInFonts * font_),
      origin_(ImGui::GetCursorScreenPos()),
      draw_(ImGui::GetWindowDrawList()) {}

void PlotArea::tick(const ImVec2& p, const char* text, ImU32 color) const {
  draw_->AddText(ImVec2(origin_.x, p.y - 0.5f * font_), color, text);
}

void PlotArea::line(const std::vector<ImVec2>& points, ImU32 color, float thickness) const {
  if (points.size() >= 2) draw_->AddPolyline(points.data(), static_cast<int>(points.size()), color, 0, thickness);
}

}  // namespace pba::app
