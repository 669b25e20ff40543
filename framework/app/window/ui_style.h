#pragma once
// Fonts and the two ImGui styles of the labs: the normal one and lecture mode (large fonts, high
// contrast, for projectors). The UI scale follows the monitor's content scale.
struct ImFont;

namespace pba::app {

/// Lecture mode's fonts for one window size: the panel's and the smaller one beside the scene.
struct LectureFonts {
  ImFont* panel = nullptr;
  ImFont* side = nullptr;  ///< the legend and a scene's own windows
};

struct UiFonts {
  ImFont* regular = nullptr;  ///< DejaVu Sans at 16 px × content scale (ImGui's default font if missing)
  LectureFonts lecture;       ///< 24 px and 19 px × content scale: windows up to about 900 px high
  LectureFonts lectureLarge;  ///< 32 px and 25 px: taller windows (1920×1080), the same share of the screen
  float contentScale = 1.0f;
  int appliedStyle = -1;  ///< 0 normal, 1 lecture, 2 large lecture, -1 none yet
};

/// Loads the fonts into the current ImGui context (before the first frame).
UiFonts loadUiFonts(float contentScale);
/// Applies the normal or the lecture style for a window `windowHeight` pixels high and makes its font
/// the default one; returns lecture mode's side font (nullptr in normal mode). Cheap when nothing
/// changed. Call between frames only (before ImGui::NewFrame): a frame never changes font or style
/// while it is being built, so there is no PushFont/PopFont pair that a mode change could unbalance.
ImFont* applyUiStyle(UiFonts& fonts, bool lecture, float windowHeight);

}  // namespace pba::app
