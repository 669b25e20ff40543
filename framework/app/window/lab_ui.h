#pragma once
// The lab's ImGui panels (docs/architecture.md §3): simulation controls, scene description, parameters with
// units and (?) tooltips, metrics, live plots, scene files, exercise status, the help overlay, the
// instability guard's message, the not-implemented banner, the scene's legend and short notices.
#include <map>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/window/lab_session.h"

namespace pba::app {

/// Recording (F9, the Record button) writes MP4 through ffmpeg or PNG files to the disk; a browser page
/// has neither, so there the button gives way to a line saying so and F9 does nothing.
#ifdef __EMSCRIPTEN__
inline constexpr bool kRecordingAvailable = false;
#else
inline constexpr bool kRecordingAvailable = true;
#endif

/// A change of the window's mode. Keys and widgets only ask for it during a frame; UiState::applyPending
/// carries it out between frames, so no frame is built under two readings of a mode (issue 15: L
/// inside a frame unbalanced the lecture font's push and pop and aborted every lab).
/// TogglePanel (C): the control panel collapses to a strip at the left edge and back; TogglePlots (M): the
/// plot window hides and shows.
enum class UiChange { ToggleLecture, ToggleHideUi, TogglePanel, TogglePlots };

/// A rectangle of the window [pixels, y down].
struct LabelBox {
  float x0 = 0.0f, y0 = 0.0f, x1 = 0.0f, y1 = 0.0f;
};

struct UiState {
  bool showHelp = false;
  bool hideUi = false;
  bool lecture = false;
  bool screenshotRequested = false;
  bool recordRequested = false;  ///< F9 or the Record button: start or stop a recording
  bool demoActive = false;       ///< playing a demo script: PageDown / PageUp move through its steps
  int demoMove = 0;              ///< steps asked for this frame (PageDown +1, PageUp −1)
  bool panelCollapsed = false;   ///< the control panel is a strip (key C): the scene takes the width
  bool showPlots = true;         ///< the plot window (key M)
  /// Labels of the panel's widgets that did not fit in it this frame (the UI status reports them; a
  /// lecture-layout test requires none).
  std::vector<std::string> clippedLabels;
  bool showNotes = false;         ///< the demo's speaker notes window (key N; the terminal has them always)
  std::string recording;          ///< while recording: "REC 3.2 s (192 frames)", else empty
  double recordingFraction = -1;  ///< share done of a recording with an end (--record), else negative
  bool frameRequested = false;
  /// Set when the layout changed between frames (lecture mode): panels take their new size once.
  bool relayout = true;
  double frameMs = 0.0;           ///< wall time of the last displayed frame [ms]
  char scenePath[512] = {};       ///< the scene file field
  std::vector<UiChange> pending;  ///< asked for during this frame, applied before the next one
  std::string notice;             ///< short on-screen confirmation ("Screenshot saved: …")
  double noticeUntil = 0.0;       ///< [s, ImGui time] when the notice disappears
  int noticeFrames = 0;           ///< frames it is still shown whatever the time (a slow frame rate still sees it)
  std::string lastScreenshot;     ///< path of the last screenshot written
  std::string lastSceneImage;     ///< its scene alone (app/window/scene_image.h), with the UI status on
  /// Where a few named widgets were drawn this frame, while visible ("header:View", "file_field",
  /// "load_button", "lecture_checkbox"): the UI status reports them so tests can click them.
  std::map<std::string, LabelBox> widgets;
  /// Lecture mode's smaller font for the legend and a scene's own windows (set by the window).
  ImFont* sideFont = nullptr;

  void request(UiChange change) { pending.push_back(change); }
  /// Applies the queued changes in order. Call between frames (before ImGui::NewFrame). A change of
  /// lecture mode also asks for a relayout and a new framing of the camera.
  void applyPending();
  /// Shows `text` on screen until `now + seconds` [s], and for at least kNoticeFrames frames.
  void showNotice(std::string text, double now, double seconds = kNoticeSeconds);
  /// True while the notice is on screen at ImGui time `now` [s].
  bool noticeVisible(double now) const { return !notice.empty() && (now < noticeUntil || noticeFrames > 0); }
  static constexpr double kNoticeSeconds = 2.0;
  static constexpr int kNoticeFrames = 3;
};

/// Draws every panel for this frame. Call between ImGui::NewFrame() and ImGui::Render().
void drawLabUi(LabSession& session, UiState& ui);

/// Width of the main panel in pixels at the current font size (for camera framing). Lecture mode caps
/// it at a smaller share of the window, so that the scene stays the largest thing on screen.
float panelWidthPixels(const UiState& ui);
/// Width [pixels] of the right-hand column reserved for a scene's own window (Scene::wantsOverlay).
float overlayWidthPixels(const UiState& ui);

/// Where a label of `textSize` pixels anchored at `anchor` is drawn (its top-left corner): above and
/// right of the anchor by `gap` pixels, so it never covers what it labels, moved inside `[x0, x1] ×
/// [y0, y1]` (the free part of the window) when it would run off an edge.
LabelBox placeLabel(float anchorX, float anchorY, float textW, float textH, float gap, const LabelBox& area);

// Pieces of drawLabUi in lab_overlays.cpp (plots, legend, notice, banners).
namespace detail {
inline const ImVec4 kAlertRed{0.80f, 0.12f, 0.10f, 1.0f};
/// B's colour in A/B runs (captions, plot lines, metric values, differing parameters); A keeps the plot blue.
inline const ImVec4 kCompareB{0.82f, 0.40f, 0.0f, 1.0f};
inline const ImVec4 kWarnOrange{0.85f, 0.45f, 0.0f, 1.0f};
/// Draws the plot window in the lower right; returns its top [pixels] (the display height when none)
/// and its left edge in `left` (the display width when none).
float plotPanel(LabSession& session, const UiState& ui, float* left = nullptr);
/// The scene's legend, its left edge at `left` [pixels] (right of the panel), its bottom at `bottom`;
/// drawn also while Tab hides the panels.
void legendWindow(const Scene& scene, float left, float bottom);
/// The rewind timeline along the bottom of the window between `left` and `right` [pixels] (lab_timeline.cpp);
/// returns its top (the display height when there is none).
float timelineStrip(LabSession& session, UiState& ui, float left, float right);
void noticeWindow(const UiState& ui);
void banners(LabSession& session, const UiState& ui);
}  // namespace detail

}  // namespace pba::app
