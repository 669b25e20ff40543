// The windows of drawLabUi that are not the control panel: live plots (lower right), the scene's
// legend (lower left of the free area above the timeline, kept while Tab hides the panels), short notices (top centre)
// and the banners of the instability guard and of exercise stubs.
#include <algorithm>
#include <cfloat>
#include <cstdio>

#include <imgui.h>

#include "app/runner/exercise_catalog.h"
#include "app/window/lab_ui.h"
#include "physics/exercises/not_implemented.h"

namespace pba::app::detail {
namespace {

constexpr float kMargin = 8.0f;           // [px] between windows and the window's edge
constexpr float kMinCaptionScale = 0.6f;  // a plot caption is never drawn smaller than this share of the font

/// A line plot of `series` filling `size`, 2 px wide (3 in lecture mode): ImGui's PlotLines draws 1 px,
/// which a projector loses. The caption (plotCaption) says what the vertical range is.
void plotSeries(const std::string& name, const std::vector<double>& series, const std::vector<double>& seriesB,
                ImVec2 size, bool lecture) {
  // A and B of an A/B run share one scale.
  std::vector<double> both = series;
  both.insert(both.end(), seriesB.begin(), seriesB.end());
  const PlotScale scale = plotScale(both);
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(o, ImVec2(o.x + size.x, o.y + size.y), ImGui::GetColorU32(ImGuiCol_FrameBg),
                      ImGui::GetStyle().FrameRounding);
  const float pad = 0.2f * ImGui::GetFontSize();
  const std::size_t samples = std::max(series.size(), seriesB.size());
  const double n = static_cast<double>(std::max<size_t>(samples - 1, 1));
  auto line = [&](const std::vector<double>& values, ImU32 colour) {
    std::vector<ImVec2> points;
    points.reserve(values.size());
    for (size_t i = 0; i < values.size(); ++i) {
      const double y = (values[i] - scale.offset - scale.lo) / (scale.hi - scale.lo);
      points.emplace_back(
          o.x + pad + (size.x - 2.0f * pad) * static_cast<float>(static_cast<double>(i) / n),
          o.y + size.y - pad -
              (size.y - 2.0f * pad - 1.8f * ImGui::GetFontSize()) * static_cast<float>(std::clamp(y, 0.0, 1.0)));
    }
    if (points.size() >= 2)
      draw->AddPolyline(points.data(), static_cast<int>(points.size()), colour, 0, lecture ? 3.0f : 2.0f);
  };
  line(seriesB, ImGui::ColorConvertFloat4ToU32(kCompareB));
  line(series, ImGui::GetColorU32(ImGuiCol_PlotLines));
  // The caption on two lines, so a narrow (lecture) plot never cuts the range off: "name = value" on
  // top, the range (and the mean of a deviation plot) below it in a smaller size.
  std::string caption = plotCaption(name, both, scale);
  if (!seriesB.empty() && !series.empty()) {  // "name = A's last | B's last  [range]"
    const std::string rest = caption.substr(std::min(caption.find("  "), caption.size()));
    char values[96];
    std::snprintf(values, sizeof values, "%s = %.4g | B %.4g", name.c_str(), series.back(), seriesB.back());
    caption = values + rest;
  }
  const size_t split = caption.find("  ");
  const float font = ImGui::GetFontSize();
  const std::string top = caption.substr(0, split);
  const std::string range = split != std::string::npos ? caption.substr(split + 2) : std::string();
  // A caption wider than the plot ("particle_kinetic_energy_J = 1.512e-05" in a lecture plot) is drawn
  // smaller until it fits, both lines alike, never cut at the window's edge.
  const float room = size.x - 2.0f * pad;
  const float widest = std::max(ImGui::CalcTextSize(top.c_str()).x, 0.8f * ImGui::CalcTextSize(range.c_str()).x);
  const float fit = widest > room ? std::max(room / widest, kMinCaptionScale) : 1.0f;
  draw->AddText(ImGui::GetFont(), fit * font, ImVec2(o.x + pad, o.y + 0.5f * pad), ImGui::GetColorU32(ImGuiCol_Text),
                top.c_str());
  if (!range.empty())
    // The range in the text colour in lecture mode: the disabled grey was too faint on a projector.
    draw->AddText(ImGui::GetFont(), 0.8f * fit * font, ImVec2(o.x + pad, o.y + 0.5f * pad + fit * font),
                  ImGui::GetColorU32(lecture ? ImGuiCol_Text : ImGuiCol_TextDisabled), range.c_str());
  ImGui::Dummy(size);
}

}  // namespace

float plotPanel(LabSession& session, const UiState& ui, float* left) {
  // Only the chosen metrics this scene has (a plotted metric of another scene is kept, not shown).
  std::vector<std::pair<std::string, std::vector<double>>> shown;
  for (const std::string& name : session.settings().plotted) {
    std::vector<double> series = session.plots().series(name);
    if (!series.empty()) shown.emplace_back(name, std::move(series));
  }
  std::vector<std::vector<double>> shownB;
  for (const auto& [name, series] : shown) {
    shownB.push_back(session.comparing() ? session.partnerPlots().series(name) : std::vector<double>());
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  if (left) *left = display.x;
  if (shown.empty()) return display.y;
  // Lecture mode: lower and narrower plots, the scene keeps the room.
  const float height = std::min(ImGui::GetFontSize() * (ui.lecture ? 3.6f : 5.0f), display.y * 0.16f);
  ImGui::SetNextWindowPos(ImVec2(display.x - kMargin, display.y - kMargin), ImGuiCond_Always, ImVec2(1, 1));
  // An explicit size: an auto-fitted axis set every frame would hide the window's contents.
  const ImGuiStyle& style = ImGui::GetStyle();
  const float windowHeight = static_cast<float>(shown.size()) * (height + style.ItemSpacing.y) +
                             ImGui::GetFrameHeight() + 2.0f * style.WindowPadding.y;
  const float width = display.x * (ui.lecture ? 0.28f : 0.38f);
  if (left) *left = display.x - kMargin - width;
  ImGui::SetNextWindowSize(ImVec2(width, windowHeight), ImGuiCond_Always);
  ImGui::Begin("Plots", nullptr, ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse);
  for (std::size_t i = 0; i < shown.size(); ++i)
    plotSeries(shown[i].first, shown[i].second, shownB[i], ImVec2(ImGui::GetContentRegionAvail().x, height),
               ui.lecture);
  ImGui::End();
  return display.y - kMargin - windowHeight;
}

void legendWindow(const Scene& scene, float left, float bottom) {
  const std::vector<LegendEntry> entries = scene.legend();
  if (entries.empty()) return;
  ImGui::SetNextWindowPos(ImVec2(left, bottom - kMargin), ImGuiCond_Always, ImVec2(0, 1));
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("##legend", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  for (const LegendEntry& e : entries) {
    ImGui::TextColored(ImVec4(e.color.r, e.color.g, e.color.b, 1.0f), "■");
    ImGui::SameLine();
    ImGui::TextUnformatted(e.text.c_str());
  }
  ImGui::End();
}

void noticeWindow(const UiState& ui) {
  if (!ui.noticeVisible(ImGui::GetTime())) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, display.y * 0.12f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.92f);
  ImGui::Begin("##notice", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  ImGui::TextUnformatted(ui.notice.c_str());
  ImGui::End();
}

void banners(LabSession& session, const UiState& ui) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  std::string text;
  ImVec4 colour = kAlertRed;
  if (const auto& guard = session.runner().guardMessage()) {
    text = *guard;
  } else if (!session.exercises().empty()) {
    text = stubBannerText(stubbedExercises(session.exercises(), exercises::notImplementedTags()));
    colour = kWarnOrange;
  }
  if (text.empty()) return;
  // In the free area right of the panel (as the legend), centred there and never under the panel: the
  // guard's message must be read whole.
  const float left = ui.hideUi ? 8.0f : panelWidthPixels(ui) + 8.0f;
  const float width = std::min(display.x - left - 8.0f, 900.0f);
  ImGui::SetNextWindowPos(ImVec2(left + 0.5f * (display.x - left - 8.0f - width), 10), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, 0), ImGuiCond_Always);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, colour);
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 1, 1, 1));
  ImGui::Begin("##banner", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::End();
  ImGui::PopStyleColor(2);
}

}  // namespace pba::app::detail
