#pragma once
// Fonts and the two ImGui styles of the labs: the normal one and lecture mode (large fonts, high
// contrast, for projectors). The UI scale follows the monitor's content scale.
struct ImFont;

namespace pba::app {

struct UiFonts {
  ImFont* regular = nullptr;  ///< DejaVu Sans at 16 px × content scale (ImGui's default font if missing)
  ImFont* lecture = nullptr;  ///< the same face at 24 px × content scale
  ImFont* lectureSide = nullptr;  ///< 19 px × content scale: lecture mode's legend and scene windows
  float contentScale = 1.0f;
  int appliedStyle = -1;      ///< 0 normal, 1 lecture, -1 none yet
};

/// Loads the fonts into the current ImGui context (before the first frame).
UiFonts loadUiFonts(float contentScale);
/// Applies the normal or the lecture style and makes its font the default one; cheap when nothing
/// changed. Call between frames only (before ImGui::NewFrame): a frame never changes font or style
/// while it is being built, so there is no PushFont/PopFont pair that a mode change could unbalance.
void applyUiStyle(UiFonts& fonts, bool lecture);

}  // namespace pba::app
