// The rewind timeline strip along the bottom of the view (docs/architecture.md §3, "Rewind"): a slider
// over the frames of the rewind history, the time shown, and the history's length and memory against
// its bounds, and how long it holds for this scene. Dragging it scrubs (LabSession::scrubTo); keys , and .
// step one simulation step (LabSession::stepBy).
#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "app/window/lab_ui.h"

namespace pba::app::detail {

float timelineStrip(LabSession& session, UiState& ui, float left, float right) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const RewindHistory& history = session.history();
  if (history.empty() || right - left < 12.0f * ImGui::GetFontSize()) return display.y;
  const float margin = 8.0f;
  ImGui::SetNextWindowPos(ImVec2(left, display.y - margin), ImGuiCond_Always, ImVec2(0, 1));
  ImGui::SetNextWindowSize(ImVec2(right - left, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("##timeline", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_AlwaysAutoResize);
  const SceneRunner& runner = session.runner();
  char info[160];
  // What the strip holds for this scene when full (a large state holds less: the bound is in bytes).
  std::snprintf(info, sizeof info, "%.1f of %.1f s, %.0f of %.0f MB", history.seconds(), history.capacitySeconds(),
                static_cast<double>(history.bytes()) / (1 << 20), static_cast<double>(history.maxBytes()) / (1 << 20));
  const float infoWidth = ImGui::CalcTextSize(info).x + ImGui::GetStyle().ItemSpacing.x;
  int index = static_cast<int>(history.cursor());
  const int last = static_cast<int>(history.size()) - 1;
  char label[64];
  std::snprintf(label, sizeof label, history.atNewest() ? "t = %.2f s (live)" : "t = %.2f s", runner.simTime());
  ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - infoWidth, 4.0f * ImGui::GetFontSize()));
  if (ImGui::SliderInt("##scrub", &index, 0, std::max(last, 1), label, ImGuiSliderFlags_AlwaysClamp) && last > 0)
    session.scrubTo(static_cast<std::size_t>(std::min(index, last)));
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  ui.widgets["timeline"] = LabelBox{lo.x, lo.y, hi.x, hi.y};
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Rewind: drag to go back in time (keys , and . step one simulation step, Shift one second). Space runs\n"
        "on from the state shown; the later frames are then discarded. The history keeps the last %zu frames or\n"
        "%.0f MB, whichever is less: %.1f s of this scene.",
        history.maxFrames(), static_cast<double>(history.maxBytes()) / (1 << 20), history.capacitySeconds());
  ImGui::SameLine();
  ImGui::TextDisabled("%s", info);
  const float top = ImGui::GetWindowPos().y;
  ImGui::End();
  return top;
}

}  // namespace pba::app::detail
