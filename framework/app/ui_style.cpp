#include "app/ui_style.h"

#include <filesystem>

#include <imgui.h>

namespace pba::app {
namespace {

constexpr float kRegularPixels = 16.0f;
constexpr float kLecturePixels = 28.0f;
// Debian's fonts-dejavu-core; ./pba installs it. Without it ImGui's built-in font is used.
constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

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
    // Latin-1, Greek (σ, λ, ω, θ in labels and tooltips) and the math signs the panels use; the
    // builder's storage must outlive the atlas build, hence static.
    static ImVector<ImWchar> ranges;
    if (ranges.empty()) {
      ImFontGlyphRangesBuilder builder;
      builder.AddRanges(io.Fonts->GetGlyphRangesDefault());
      static const ImWchar kGreek[] = {0x0370, 0x03FF, 0};  // ImGui 1.86 has no Greek preset
      builder.AddRanges(kGreek);
      builder.AddText("−–—·×÷²³⁻¹√∞≈≠≤≥→←↑↓±°…‖∥⊥∑∂∆ΔΣλ■●▲");
      builder.BuildRanges(&ranges);
    }
    fonts.regular = io.Fonts->AddFontFromFileTTF(kFontPath, kRegularPixels * fonts.contentScale, nullptr, ranges.Data);
    fonts.lecture = io.Fonts->AddFontFromFileTTF(kFontPath, kLecturePixels * fonts.contentScale, nullptr, ranges.Data);
  }
  if (!fonts.regular) {
    ImFontConfig config;
    config.SizePixels = 13.0f * fonts.contentScale;
    fonts.regular = io.Fonts->AddFontDefault(&config);
    config.SizePixels = 24.0f * fonts.contentScale;
    fonts.lecture = io.Fonts->AddFontDefault(&config);
  }
  return fonts;
}

void applyUiStyle(UiFonts& fonts, bool lecture) {
  const int wanted = lecture ? 1 : 0;
  if (fonts.appliedStyle == wanted) return;
  const float scale = fonts.contentScale * (lecture ? kLecturePixels / kRegularPixels : 1.0f);
  ImGui::GetStyle() = makeStyle(scale, lecture);
  fonts.appliedStyle = wanted;
}

}  // namespace pba::app
