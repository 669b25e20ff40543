#pragma once
// A scene's own window in the right-hand column (Scene::overlayUi): the IK comparison's residual plot, the
// oscillator's energy plot. Window mode only; it uses ImGui, which the scenes' overlayUi may call.
#include <vector>

#include <imgui.h>

#include "app/runner/scene.h"

namespace pba::app {

/// Begins a window of `title` docked at the bottom of `column`, as wide as it and as tall as its contents,
/// neither moved nor resized by the user. End it with ImGui::End().
void beginColumnWindow(const ScreenRect& column, const char* title);

/// A colour of the physics library's palette as ImGui's packed colour.
ImU32 imguiColor(const Color& c);

/// The plot area of such a window, from the cursor: a column for the tick labels on the left, as wide as
/// `widestTick` plus `gapInFonts` font heights, then the rest of the window's width, `heightInFonts` font
/// heights tall. at() maps fractions of the area (x to the right, y up, 0 … 1) to the screen; reserve()
/// moves the cursor past the area once it is drawn.
class PlotArea {
 public:
  PlotArea(const char* widestTick, float gapInFonts, float heightInFonts);
  ImVec2 at(double fx, double fy) const {
    return ImVec2(origin_.x + axis_ + width_ * static_cast<float>(fx),
                  origin_.y + height_ * static_cast<float>(1.0 - fy));
  }
  /// `text` in the label column, centred on the height of `p`.
  void tick(const ImVec2& p, const char* text, ImU32 color) const;
  /// A polyline through `points` (none drawn with fewer than two), `thickness` pixels wide.
  void line(const std::vector<ImVec2>& points, ImU32 color, float thickness) const;
  void reserve() const { ImGui::Dummy(ImVec2(axis_ + width_, height_)); }
  ImDrawList* draw() const { return draw_; }
  float font() const { return font_; }

 private:
  float font_, axis_, width_, height_;
  ImVec2 origin_;
  ImDrawList* draw_;
};

}  // namespace pba::app
