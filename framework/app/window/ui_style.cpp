#include "app/window/ui_style.h"

#include <filesystem>

#include <imgui.h>

#include "app/runner/resource_dir.h"

namespace pba::app {
namespace {

constexpr float kRegularPixels = 16.0f;
// Lecture mode: large enough to read from the back of a hall at 1280×720, small enough that the
// panel stays a narrow column beside the scene (the scene is what the hall looks at).
constexpr float kLecturePixels = 24.0f;
constexpr float kLectureSidePixels = 19.0f;  // legends and a scene's own windows beside the scene
// A window at least this tall [px] (1920×1080) gets the large lecture fonts: on the same projector
// the text then takes the same share of the picture as at 1280×720.
constexpr float kLargeLectureHeight = 960.0f;
constexpr float kLargeLectureFactor = 4.0f / 3.0f;
// DejaVu Sans, shipped in resources/fonts (its licence beside it). Without it ImGui's built-in font is used.
constexpr const char* kFontFile = "fonts/DejaVuSans.ttf";
// The glyphs the labs' texts use, all in DejaVu Sans: ImGui loads only Latin-1 by default, and every
// ω, μ_s, θ, ψ, − (minus), ≈, ≤, √, ₀, → in a description or tooltip showed as '?'. (Pairs of first
// and last code point; zero-terminated; must outlive the font atlas.)
constexpr ImWchar kGlyphRanges[] = {
    0x0020, 0x00FF,  // Basic Latin + Latin-1 (², ·, ×, ±, °)
    0x0370, 0x03FF,  // Greek (ω, μ, θ, ψ, φ, Δ)
    0x1E00, 0x1EFF,  // Latin Extended Additional (ẍ)
    0x2000, 0x209F,  // General Punctuation (– — …), superscripts and subscripts (⁻¹, ₀)
    0x2190, 0x22FF,  // Arrows (→ ← ⇒) and Mathematical Operators (− ≈ ≤ √ ∞)
    0x25A0, 0x25CF,  // Geometric Shapes (■ ● ▲: legend swatches)
    0,
};

ImGuiStyle makeStyle(float scale, bool lecture) {
  ImGuiStyle style;
  ImGui::StyleColorsLight(&style);
  style.WindowRounding = 6.0f;
  style.FrameRounding = 4.0f;
  style.GrabRounding = 4.0f;
  style.WindowBorderSize = 1.0f;
  style.Colors[ImGuiCol_WindowBg] = ImVec4(0.97f, 0.97f, 0.98f, 0.94f);
  style.Colors[ImGuiCol_PlotLines] = ImVec4(0.16f, 0.42f, 0.86f, 1.0f);
  if (lecture) {
    // High contrast: opaque white panels, black text, strong frames.
    style.Colors[ImGuiCol_Text] = ImVec4(0.0f, 0.0f, 0.0f, 1.0f);
    style.Colors[ImGuiCol_WindowBg] = ImVec4(1.0f, 1.0f, 1.0f, 1.0f);
    style.Colors[ImGuiCol_Border] = ImVec4(0.0f, 0.0f, 0.0f, 0.6f);
    style.Colors[ImGuiCol_FrameBg] = ImVec4(0.86f, 0.88f, 0.92f, 1.0f);
    style.Colors[ImGuiCol_SliderGrab] = ImVec4(0.10f, 0.30f, 0.75f, 1.0f);
    style.FrameBorderSize = 1.0f;
    style.WindowBorderSize = 2.0f;
  }
  style.ScaleAllSizes(scale);
  return style;
}

}  // namespace

UiFonts loadUiFonts(float contentScale) {
  UiFonts fonts;
  fonts.contentScale = contentScale > 0.0f ? contentScale : 1.0f;
  ImGuiIO& io = ImGui::GetIO();
  const float k = fonts.contentScale, large = kLargeLectureFactor;
  const std::string fontPath = (std::filesystem::path(resourceDir()) / kFontFile).string();
  if (std::filesystem::exists(fontPath)) {
    auto add = [&](float pixels) {
      return io.Fonts->AddFontFromFileTTF(fontPath.c_str(), pixels * k, nullptr, kGlyphRanges);
    };
    fonts.regular = add(kRegularPixels);
    fonts.lecture = {add(kLecturePixels), add(kLectureSidePixels)};
    fonts.lectureLarge = {add(kLecturePixels * large), add(kLectureSidePixels * large)};
  }
  if (!fonts.regular) {
    auto add = [&](float pixels) {
      ImFontConfig config;
      config.SizePixels = pixels * k;
      return io.Fonts->AddFontDefault(&config);
    };
    fonts.regular = add(13.0f);
    fonts.lecture = {add(20.0f), add(16.0f)};
    fonts.lectureLarge = {add(20.0f * large), add(16.0f * large)};
  }
  return fonts;
}

ImFont* applyUiStyle(UiFonts& fonts, bool lecture, float windowHeight) {
  const bool large = lecture && windowHeight >= kLargeLectureHeight;
  const LectureFonts& chosen = large ? fonts.lectureLarge : fonts.lecture;
  const int wanted = lecture ? (large ? 2 : 1) : 0;
  if (fonts.appliedStyle != wanted) {
    // Paddings and spacings grow less than the font in lecture mode: the panel stays narrow.
    const float scale = fonts.contentScale * (lecture ? 1.2f * (large ? kLargeLectureFactor : 1.0f) : 1.0f);
    ImGui::GetStyle() = makeStyle(scale, lecture);
    ImGui::GetIO().FontDefault = lecture && chosen.panel ? chosen.panel : fonts.regular;
    fonts.appliedStyle = wanted;
  }
  return lecture ? chosen.side : nullptr;
}

}  // namespace pba::app
