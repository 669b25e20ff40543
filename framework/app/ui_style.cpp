#include "app/ui_style.h"

#include <filesystem>

#include <imgui.h>

namespace pba::app {
namespace {

constexpr float kRegularPixels = 16.0f;
// Lecture mode: large enough to read from the back of a hall at 1280×720, small enough that the
// panel stays a narrow column beside the scene (the scene is what the hall looks at).
constexpr float kLecturePixels = 24.0f;
constexpr float kLectureSidePixels = 19.0f;  // legends and a scene's own windows beside the scene
// Debian's fonts-dejavu-core; ./pba installs it. Without it ImGui's built-in font is used.
constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
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
  if (std::filesystem::exists(kFontPath)) {
    fonts.regular = io.Fonts->AddFontFromFileTTF(kFontPath, kRegularPixels * fonts.contentScale, nullptr, kGlyphRanges);
    fonts.lecture = io.Fonts->AddFontFromFileTTF(kFontPath, kLecturePixels * fonts.contentScale, nullptr, kGlyphRanges);
    fonts.lectureSide = io.Fonts->AddFontFromFileTTF(kFontPath, kLectureSidePixels * fonts.contentScale, nullptr, kGlyphRanges);
  }
  if (!fonts.regular) {
    ImFontConfig config;
    config.SizePixels = 13.0f * fonts.contentScale;
    fonts.regular = io.Fonts->AddFontDefault(&config);
    config.SizePixels = 20.0f * fonts.contentScale;
    fonts.lecture = io.Fonts->AddFontDefault(&config);
    config.SizePixels = 16.0f * fonts.contentScale;
    fonts.lectureSide = io.Fonts->AddFontDefault(&config);
  }
  return fonts;
}

void applyUiStyle(UiFonts& fonts, bool lecture) {
  const int wanted = lecture ? 1 : 0;
  if (fonts.appliedStyle == wanted) return;
  // Paddings and spacings grow less than the font in lecture mode: the panel stays narrow.
  const float scale = fonts.contentScale * (lecture ? 1.2f : 1.0f);
  ImGui::GetStyle() = makeStyle(scale, lecture);
  ImGui::GetIO().FontDefault = lecture && fonts.lecture ? fonts.lecture : fonts.regular;
  fonts.appliedStyle = wanted;
}

}  // namespace pba::app
