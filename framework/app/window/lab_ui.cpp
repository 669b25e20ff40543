#include "app/window/lab_ui.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "app/runner/resource_dir.h"
#include "app/runner/scene_registry.h"
#include "physics/exercises/not_implemented.h"

namespace pba::app {
namespace {

using detail::kAlertRed;
using detail::kCompareB;
using detail::kWarnOrange;

constexpr float kPanelWidth = 400.0f;         // [px at UI scale 1]
constexpr float kOverlayWidth = 350.0f;       // [px at UI scale 1] a scene's own right-hand column
constexpr float kWidgetWidthInFonts = 11.5f;  // slider width in font heights: leaves room for labels
constexpr float kWidgetShare = 0.56f;         // at most this share of the panel's width (lecture mode)
// Shares of the window's width the panel and the overlay column may take: in lecture mode both stay
// narrow columns, so that the scene keeps most of a 1280×720 projector image.
constexpr float kPanelShare = 0.40f, kLecturePanelShare = 0.22f;
constexpr float kStripWidthInFonts = 2.2f;  // the collapsed panel (key C)
constexpr float kOverlayShare = 0.34f, kLectureOverlayShare = 0.26f;

// Key, action: the help overlay's table (the same bindings in every lab, docs/architecture.md §3).
const char* const kKeys[][2] = {
    {"Space / P", "pause or resume"},
    {"O", "single step (hold to repeat)"},
    {",  .", "one simulation step back / forward, Shift: one second (the timeline strip scrubs)"},
    {"R", "reset the scene"},
    {"[  ]", "previous / next scene"},
    {"1 - 9", "scene presets"},
    {"F1 / H", "this help"},
    {"F12", "screenshot (PNG in the working folder)"},
    {"F9", "start / stop recording (MP4 with ffmpeg, else PNG files; 60 frames/s of simulated time)"},
    {"L", "lecture mode (large fonts, high contrast)"},
    {"Tab", "hide or show the panels"},
    {"C", "collapse the control panel to a strip / show it"},
    {"M", "hide / show the plots"},
    {"F", "frame the scene"},
    {"Arrow keys", "nudge the target (IK goal) in the view plane"},
    {"PageUp / PageDown, Shift + Up / Down", "nudge the target away from / toward the camera"},
    {"PageDown / PageUp (demo)", "next / previous step of a demo script; N shows or hides the notes"},
    {"Ctrl + nudge key", "fine nudge (one fifth of the step)"},
    {"Left drag", "pick and drag an object"},
    {"Right drag", "orbit the camera"},
    {"Middle drag, Shift + right drag", "pan"},
    {"Wheel", "zoom"},
};

/// A "(?)" whose tooltip is `text`, at the cursor.
void helpMark(const std::string& text) {
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

/// A "(?)" on the line of the item before.
void helpMarker(const std::string& text) {
  ImGui::SameLine();
  helpMark(text);
}

/// After a widget and its "(?)": records `label` in ui.clippedLabels when the row ran past the panel's
/// right edge (ImGui cuts it off there: "solver_subste").
void noteIfClipped(UiState& ui, const std::string& label) {
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (ImGui::GetItemRectMax().x > right + 0.5f) ui.clippedLabels.push_back(label);
}

/// Lecture mode puts a widget's "(?)" and its label (wrapped when longer than the panel) on a line of their
/// own above a widget as wide as the panel, so that a narrow panel never cuts a label off ("solver_subste"). Returns the widget's ImGui
/// label: `label` itself inline, hidden ("##label") under a label line. Call helpAfter after the widget.
std::string labelLine(UiState& ui, const std::string& label, const std::string& help, bool above) {
  if (!above) return label;
  helpMark(help);  // first, so that a label wrapped onto two lines keeps it in view
  ImGui::SameLine();
  ImGui::TextWrapped("%s", label.c_str());
  noteIfClipped(ui, label);
  ImGui::SetNextItemWidth(-FLT_MIN);
  return "##" + label;
}
/// The "(?)" after an inline widget (labelLine drew it already for a label line).
void helpAfter(UiState& ui, const std::string& label, const std::string& help, bool above) {
  if (above) return;
  helpMarker(help);
  noteIfClipped(ui, label);
}

void parameterWidgets(LabSession& session, UiState& ui) {
  // In an A/B run the panel edits the side chosen under Simulation; a parameter where B differs from A
  // has its name in B's colour.
  Scene& scene = session.editedRunner().scene();
  const nlohmann::json other = !session.comparing() ? nlohmann::json()
                               : session.editingB() ? session.runner().scene().params().toJson()
                                                    : session.partner()->scene().params().toJson();
  const nlohmann::json mine = session.comparing() ? scene.params().toJson() : nlohmann::json();
  bool resetNeeded = false;
  for (Param& p : scene.params().all()) {
    if (p.shown && !p.shown()) continue;
    ImGui::PushID(p.name.c_str());
    const std::string label = p.unit.empty() ? p.name : p.name + " [" + p.unit + "]";
    const bool differs = session.comparing() && other.contains(p.name) && other[p.name] != mine[p.name];
    if (differs) ImGui::PushStyleColor(ImGuiCol_Text, kCompareB);
    struct PopOnExit {
      bool on;
      ~PopOnExit() {
        if (on) ImGui::PopStyleColor();
      }
    } pop{differs};
    // A checkbox keeps its label beside it (wrapped in lecture mode, its "(?)" first).
    const bool above = ui.lecture && p.kind != ParamKind::Flag;
    const bool wrappedFlag = ui.lecture && p.kind == ParamKind::Flag;
    if (p.kind == ParamKind::Text) {
      // Applied on Enter, so that a half-typed path is never loaded.
      const std::string help = p.tooltip + "\nPress Enter to apply.";
      const std::string id = labelLine(ui, label, help, above);
      char buffer[2048];  // long enough for a list of every joint name of a character
      std::snprintf(buffer, sizeof buffer, "%s", p.getText().c_str());
      if (ImGui::InputText(id.c_str(), buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue)) {
        p.setText(buffer);
        resetNeeded = resetNeeded || p.needsReset;
      }
      helpAfter(ui, label, help, above);
      ImGui::PopID();
      continue;
    }
    const std::string help = p.tooltip + (p.needsReset ? "\nTakes effect on reset." : "");
    const std::string id = labelLine(ui, label, help, above);
    bool changed = false;
    double value = p.get();
    switch (p.kind) {
      case ParamKind::Real: {
        const ImGuiSliderFlags flags =
            (p.logarithmic ? ImGuiSliderFlags_Logarithmic : 0) | ImGuiSliderFlags_AlwaysClamp;
        changed = ImGui::SliderScalar(id.c_str(), ImGuiDataType_Double, &value, &p.min, &p.max, "%.4g", flags);
        break;
      }
      case ParamKind::Integer: {
        int v = static_cast<int>(value), lo = static_cast<int>(p.min), hi = static_cast<int>(p.max);
        changed = ImGui::SliderInt(id.c_str(), &v, lo, hi, "%d",
                                   ImGuiSliderFlags_AlwaysClamp | (p.logarithmic ? ImGuiSliderFlags_Logarithmic : 0));
        value = v;
        break;
      }
      case ParamKind::Flag: {
        bool v = value != 0.0;
        if (wrappedFlag) {
          helpMark(help);
          ImGui::SameLine();
          changed = ImGui::Checkbox(("##" + label).c_str(), &v);
          ImGui::SameLine();
          ImGui::TextWrapped("%s", label.c_str());
          noteIfClipped(ui, label);
        } else {
          changed = ImGui::Checkbox(id.c_str(), &v);
        }
        value = v ? 1.0 : 0.0;
        break;
      }
      case ParamKind::Choice: {
        int v = static_cast<int>(value);
        const std::string& current = p.choices.at(static_cast<size_t>(v));
        if (ImGui::BeginCombo(id.c_str(), current.c_str())) {
          for (size_t i = 0; i < p.choices.size(); ++i) {
            if (ImGui::Selectable(p.choices[i].c_str(), static_cast<int>(i) == v)) {
              v = static_cast<int>(i);
              changed = true;
            }
          }
          ImGui::EndCombo();
        }
        value = v;
        break;
      }
      case ParamKind::Text:
        break;  // handled above
    }
    helpAfter(ui, label, help, above || wrappedFlag);
    // Sliders clamp to the declared range, so the value is always valid: slider extremes are safe.
    if (changed) {
      p.set(std::clamp(value, p.min, p.max));
      resetNeeded = resetNeeded || p.needsReset;
    }
    ImGui::PopID();
  }
  if (resetNeeded) session.reset();
}

/// Records the last item's rectangle under `name` when it is visible (UiState::widgets).
void noteWidget(UiState& ui, const std::string& name) {
  if (!ImGui::IsItemVisible()) return;
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  ui.widgets[name] = LabelBox{a.x, a.y, b.x, b.y};
}

/// A collapsing header whose rectangle is recorded as "header:<label>".
bool header(UiState& ui, const char* label, ImGuiTreeNodeFlags flags = 0) {
  const bool open = ImGui::CollapsingHeader(label, flags);
  noteWidget(ui, std::string("header:") + label);
  return open;
}

/// Puts the next button on this line when it fits in the panel (a narrow lecture panel wraps them).
void sameLineIfFits(const char* nextLabel) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float next = ImGui::CalcTextSize(nextLabel).x + 2.0f * style.FramePadding.x;
  const float right = ImGui::GetItemRectMax().x + style.ItemSpacing.x + next;
  if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

void compareControls(LabSession& session) {
  if (!session.comparing()) {
    if (ImGui::Button("Duplicate as B")) session.duplicateAsB();
    helpMarker(
        "A/B run: a second copy of this scene beside the first, stepping with it. Change B's parameters "
        "and watch both. From the command line: --compare \"dt=0.0167\" \"dt=0.0042\".");
    return;
  }
  int side = session.editingB() ? 1 : 0;
  ImGui::TextUnformatted("A/B: edit");
  ImGui::SameLine();
  if (ImGui::RadioButton("A", &side, 0)) session.setEditingB(false);
  ImGui::SameLine();
  if (ImGui::RadioButton("B", &side, 1)) session.setEditingB(true);
  sameLineIfFits("End A/B");
  if (ImGui::Button("End A/B")) session.endCompare();
}

void simulationControls(LabSession& session, UiState& ui) {
  SceneRunner& runner = session.editedRunner();
  if (ImGui::Button(runner.paused() ? "Run (Space)" : "Pause (Space)")) session.togglePause();
  sameLineIfFits("Step (O)");
  if (ImGui::Button("Step (O)")) session.singleStep();
  sameLineIfFits("Reset (R)");
  if (ImGui::Button("Reset (R)")) session.reset();
  compareControls(session);

  double dt = runner.dt();
  const double dtMin = kMinDt * 10, dtMax = kMaxDt;
  const bool above = ui.lecture;
  const std::string dtHelp =
      "Fixed time step of the simulation. Smaller is more accurate and more stable, and costs more.";
  if (ImGui::SliderScalar(labelLine(ui, "dt [s]", dtHelp, above).c_str(), ImGuiDataType_Double, &dt, &dtMin, &dtMax,
                          "%.5f", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
    runner.setDt(dt, /*keepAcrossScenes=*/false);
  helpAfter(ui, "dt [s]", dtHelp, above);
  int substeps = runner.substeps();
  // Named apart from a solver's own "substeps" parameter (the cloth's, the ragdoll's): one name per control.
  const std::string stepsHelp =
      "The runner takes this many steps of dt / N for each step dt, for any scene (--substeps N on the command "
      "line). A solver's own substeps, where the scene has them, are a parameter of the scene below.";
  if (ImGui::SliderInt(labelLine(ui, "steps per dt", stepsHelp, above).c_str(), &substeps, 1, kMaxSubsteps, "%d",
                       ImGuiSliderFlags_AlwaysClamp))
    runner.setSubsteps(substeps);
  helpAfter(ui, "steps per dt", stepsHelp, above);
  double scale = runner.timeScale();
  const double lo = kMinTimeScale, hi = kMaxTimeScale;
  const std::string scaleHelp = "Slow motion below 1, fast forward above 1. The physics step dt does not change.";
  if (ImGui::SliderScalar(labelLine(ui, "time scale", scaleHelp, above).c_str(), ImGuiDataType_Double, &scale, &lo, &hi,
                          "%.2fx", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
    runner.setTimeScale(scale);
  helpAfter(ui, "time scale", scaleHelp, above);
  ImGui::Text("t = %.3f s   steps = %lld", runner.simTime(), static_cast<long long>(runner.steps()));
}

void metricValue(const nlohmann::json& value) {
  if (value.is_number_float())
    ImGui::Text("%.5g", value.get<double>());
  else if (value.is_string())
    ImGui::TextUnformatted(value.get<std::string>().c_str());
  else
    ImGui::TextUnformatted(value.dump().c_str());
}

void metricsTable(LabSession& session, const UiState& ui) {
  const SceneRunner& runner = session.runner();
  ImGui::Text("frame %.2f ms   physics %.3f ms", ui.frameMs, runner.frameStats().last());
  const nlohmann::json metrics = runner.scene().metrics();
  // An A/B run shows B's value beside A's, in B's colour.
  const nlohmann::json metricsB = session.comparing() ? session.partner()->scene().metrics() : nlohmann::json();
  auto& plotted = session.settings().plotted;
  if (ImGui::BeginTable("metrics", session.comparing() ? 4 : 3, ImGuiTableFlags_RowBg)) {
    // Name and value share the width; the plot box keeps a fixed column so it is never cut off.
    ImGui::TableSetupColumn("metric", ImGuiTableColumnFlags_WidthStretch, 1.3f);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    if (session.comparing()) ImGui::TableSetupColumn("B", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableSetupColumn("plot", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFrameHeight());
    for (const auto& [key, value] : metrics.items()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(key.c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (tick the box to plot it)", key.c_str());
      ImGui::TableNextColumn();
      metricValue(value);
      if (session.comparing()) {
        ImGui::TableNextColumn();
        ImGui::PushStyleColor(ImGuiCol_Text, kCompareB);
        if (metricsB.contains(key)) metricValue(metricsB[key]);
        ImGui::PopStyleColor();
      }
      ImGui::TableNextColumn();
      if (value.is_number() || value.is_boolean()) {
        bool on = std::find(plotted.begin(), plotted.end(), key) != plotted.end();
        ImGui::PushID(key.c_str());
        if (ImGui::Checkbox("##plot", &on)) {
          if (on)
            plotted.push_back(key);
          else
            plotted.erase(std::remove(plotted.begin(), plotted.end(), key), plotted.end());
        }
        ImGui::PopID();
      }
    }
    ImGui::EndTable();
  }
}

void sceneFileControls(LabSession& session, UiState& ui) {
  if (ui.scenePath[0] == '\0')
    std::snprintf(ui.scenePath, sizeof ui.scenePath, "%s/scenes/%s/%s.json", resourceDir().c_str(),
                  session.lab().c_str(), session.runner().sceneName().c_str());
  // The path takes the panel's whole width, and the full text is repeated below it (wrapped), so a long
  // path can be read without scrolling the field.
  ImGui::TextUnformatted("scene file (JSON)");
  helpMarker(
      "A JSON scene file: the scene's name and its parameters. Load replaces the scene only when the "
      "file is valid; Save writes the current parameters.");
  ImGui::SetNextItemWidth(-FLT_MIN);
  ImGui::InputText("##file", ui.scenePath, sizeof ui.scenePath);
  noteWidget(ui, "file_field");
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("%s", ui.scenePath);
  ImGui::PopTextWrapPos();
  if (ImGui::Button("Load")) session.loadSceneFile(ui.scenePath);
  noteWidget(ui, "load_button");
  ImGui::SameLine();
  if (ImGui::Button("Save")) session.saveSceneFile(ui.scenePath);
  if (!session.fileError().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kAlertRed);
    ImGui::TextWrapped("%s", session.fileError().c_str());
    ImGui::PopStyleColor();
  }
}

void exerciseStatus(LabSession& session) {
  const std::vector<std::string> stubs = exercises::notImplementedTags();
  for (const ExerciseInfo& e : session.exercises()) {
    const bool stub = std::find(stubs.begin(), stubs.end(), e.tag) != stubs.end();
    ImGui::PushStyleColor(ImGuiCol_Text, stub ? kWarnOrange : ImVec4(0.1f, 0.5f, 0.2f, 1.0f));
    ImGui::Text("%s  %s", stub ? "[stub]" : "[done]", e.tag.c_str());
    ImGui::PopStyleColor();
    ImGui::SameLine();
    ImGui::TextUnformatted(e.title.c_str());
    if (stub) helpMarker(e.hint);
  }
  ImGui::TextDisabled("[done] = implemented; ./pba grade checks it against the tests.");
}

void mainPanel(LabSession& session, UiState& ui) {
  // The panel takes its size from the mode once per change (start, lecture on or off); in between the
  // user may resize it.
  const ImGuiCond cond = ui.relayout ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
  ImGui::SetNextWindowPos(ImVec2(8, 8), cond);
  ImGui::SetNextWindowSize(ImVec2(panelWidthPixels(ui) - 8.0f, ImGui::GetIO().DisplaySize.y - 16), cond);
  const std::string title = "pba-" + session.lab() + "###panel";
  if (ui.panelCollapsed) {  // a strip at the left edge: one button brings the panel back
    ImGui::Begin(title.c_str(), nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoScrollbar |
                     ImGuiWindowFlags_NoCollapse);
    if (ImGui::ArrowButton("##expand", ImGuiDir_Right)) ui.request(UiChange::TogglePanel);
    noteWidget(ui, "expand_button");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show the control panel (C)");
    ImGui::End();
    return;
  }
  if (!ImGui::Begin(title.c_str())) {
    ImGui::End();
    return;
  }
  ImGui::PushItemWidth(
      std::min(ImGui::GetFontSize() * kWidgetWidthInFonts, kWidgetShare * ImGui::GetContentRegionAvail().x));
  const auto& list = scenes();
  const int current = session.sceneIndex();
  if (ImGui::BeginCombo("scene", session.runner().sceneName().c_str())) {
    std::string category;
    for (size_t i = 0; i < list.size(); ++i) {
      if (list[i].category != category) {
        category = list[i].category;
        ImGui::TextDisabled("%s", category.c_str());
      }
      if (ImGui::Selectable(("  " + list[i].name).c_str(), static_cast<int>(i) == current))
        session.switchScene(static_cast<int>(i));
    }
    ImGui::EndCombo();
  }
  ImGui::TextWrapped("%s", session.runner().scene().description().c_str());
  const std::vector<Preset> presets = session.runner().scene().presets();
  for (size_t i = 0; i < presets.size() && i < 9; ++i) {
    const std::string label = std::to_string(i + 1) + " " + presets[i].name;
    const ImGuiStyle& style = ImGui::GetStyle();
    // A preset name wider than the panel: its number as the button, the name wrapped beside it.
    if (ImGui::CalcTextSize(label.c_str()).x + 2.0f * style.FramePadding.x > ImGui::GetContentRegionAvail().x) {
      if (ImGui::SmallButton((std::to_string(i + 1) + "##preset").c_str())) session.applyPreset(static_cast<int>(i));
      ImGui::SameLine();
      ImGui::TextWrapped("%s", presets[i].name.c_str());
      continue;
    }
    if (i > 0) sameLineIfFits(label.c_str());
    if (ImGui::SmallButton(label.c_str())) session.applyPreset(static_cast<int>(i));
    noteIfClipped(ui, label);
  }
  if (header(ui, "Simulation", ImGuiTreeNodeFlags_DefaultOpen)) simulationControls(session, ui);
  if (header(ui, "Parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
    parameterWidgets(session, ui);
    session.runner().scene().ui();
  }
  if (header(ui, "Metrics", ImGuiTreeNodeFlags_DefaultOpen)) metricsTable(session, ui);
  if (!session.exercises().empty() && header(ui, "Exercises", ImGuiTreeNodeFlags_DefaultOpen)) exerciseStatus(session);
  if (header(ui, "Scene file")) sceneFileControls(session, ui);
  if (header(ui, "View")) {
    bool lecture = ui.lecture;  // the mode changes between frames, never inside this one
    if (ImGui::Checkbox("lecture mode (L)", &lecture)) ui.request(UiChange::ToggleLecture);
    noteWidget(ui, "lecture_checkbox");
    if (ImGui::Button("Collapse panel (C)")) ui.request(UiChange::TogglePanel);
    sameLineIfFits("Plots (M)");
    bool plots = ui.showPlots;
    if (ImGui::Checkbox("Plots (M)", &plots)) ui.request(UiChange::TogglePlots);
    if (ImGui::Button("Frame scene (F)")) ui.frameRequested = true;
    sameLineIfFits("Screenshot (F12)");
    if (ImGui::Button("Screenshot (F12)")) ui.screenshotRequested = true;
    sameLineIfFits("Help (F1)");
    if (ImGui::Button("Help (F1)")) ui.showHelp = !ui.showHelp;
    if (!kRecordingAvailable)
      ImGui::TextDisabled("Recording (F9): native build only (a page has no ffmpeg and no disk)");
    else if (ImGui::Button(ui.recording.empty() ? "Record (F9)" : "Stop recording (F9)"))
      ui.recordRequested = true;
    if (!ui.recording.empty()) {
      ImGui::SameLine();
      ImGui::TextColored(detail::kAlertRed, "%s", ui.recording.c_str());
      if (ui.recordingFraction >= 0.0)  // a recording with an end: how far it is
        ImGui::ProgressBar(static_cast<float>(ui.recordingFraction), ImVec2(-1.0f, 0.0f));
    }
  }
  if (!session.message().empty()) ImGui::TextDisabled("%s", session.message().c_str());
  ImGui::PopItemWidth();
  ImGui::End();
}

void helpOverlay(UiState& ui) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::Begin("Keys and mouse (F1 or H closes)", &ui.showHelp,
               ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    for (const auto& [key, action] : kKeys) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(key);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(action);
    }
    for (const LabKey& k : labKeys()) {  // the scenes' own keys
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("%c", k.key);
      ImGui::TableNextColumn();
      ImGui::Text("%s (scene %s)", k.action.c_str(), k.scene.c_str());
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace

float panelWidthPixels(const UiState& ui) {
  if (ui.panelCollapsed) return kStripWidthInFonts * ImGui::GetFontSize() + 8.0f;
  const float share = ui.lecture ? kLecturePanelShare : kPanelShare;
  return std::min(kPanelWidth * ImGui::GetFontSize() / 16.0f, share * ImGui::GetIO().DisplaySize.x) + 8.0f;
}
float overlayWidthPixels(const UiState& ui) {
  const float share = ui.lecture ? kLectureOverlayShare : kOverlayShare;
  return std::min(kOverlayWidth * ImGui::GetFontSize() / 16.0f, share * ImGui::GetIO().DisplaySize.x) + 8.0f;
}

void UiState::applyPending() {
  for (const UiChange change : pending) {
    switch (change) {
      case UiChange::ToggleLecture:
        lecture = !lecture;
        relayout = true;
        frameRequested = true;  // the panels' widths changed: frame the scene in what they leave
        break;
      case UiChange::ToggleHideUi:
        hideUi = !hideUi;
        break;
      case UiChange::TogglePanel:
        panelCollapsed = !panelCollapsed;
        relayout = true;
        frameRequested = true;  // the scene takes the width the panel gave up (or gives it back)
        break;
      case UiChange::TogglePlots:
        showPlots = !showPlots;
        break;
    }
  }
  pending.clear();
}

void UiState::showNotice(std::string text, double now, double seconds) {
  notice = std::move(text);
  noticeUntil = now + seconds;
  noticeFrames = kNoticeFrames;
}

LabelBox placeLabel(float anchorX, float anchorY, float textW, float textH, float gap, const LabelBox& area) {
  float x = anchorX + gap, y = anchorY - gap - textH;  // above and to the right: the anchor stays visible
  x = std::max(area.x0, std::min(x, area.x1 - textW));
  y = std::max(area.y0, std::min(y, area.y1 - textH));
  return LabelBox{x, y, x + textW, y + textH};
}

void drawLabUi(LabSession& session, UiState& ui) {
  ui.widgets.clear();
  ui.clippedLabels.clear();
  detail::banners(session, ui);
  detail::noticeWindow(ui);
  if (ui.noticeFrames > 0) --ui.noticeFrames;
  if (ui.showHelp) helpOverlay(ui);
  // Beside the scene, lecture mode uses a smaller font: the legend and the scene's own window explain
  // the picture without covering it. (Pushed and popped within this function: no mode changes here.)
  const bool side = ui.lecture && ui.sideFont;
  const float legendLeft = ui.hideUi ? 8.0f : panelWidthPixels(ui) + 8.0f;  // in the panel's font
  float plotsTop = ImGui::GetIO().DisplaySize.y, plotsLeft = ImGui::GetIO().DisplaySize.x;
  float timelineTop = plotsTop;
  // The scene's own window (IK's Jacobian, the comparison plot) takes a column at the right edge down to
  // the plots, or to the bottom when there are none: the timeline strip ends left of it.
  const float right = ImGui::GetIO().DisplaySize.x - 8.0f;
  const float columnLeft = right - overlayWidthPixels(ui) + 8.0f;
  const bool overlay = session.runner().scene().wantsOverlay();
  if (!ui.hideUi) {
    mainPanel(session, ui);
    if (ui.showPlots) plotsTop = detail::plotPanel(session, ui, &plotsLeft);
    const float timelineRight = overlay ? std::min(plotsLeft, columnLeft) : plotsLeft;
    timelineTop = detail::timelineStrip(session, ui, legendLeft, timelineRight - 8.0f);
  }
  if (side) ImGui::PushFont(ui.sideFont);
  detail::legendWindow(session.runner().scene(), legendLeft, timelineTop);
  if (side) ImGui::PopFont();
  if (!ui.hideUi) {
    Scene& scene = session.runner().scene();
    if (overlay) {
      const ScreenRect column{columnLeft, 8.0f, right, plotsTop - 8.0f};
      // The scene's window stays inside its column (it scrolls when its contents are taller).
      ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(column.x1 - column.x0, column.y1 - column.y0));
      if (side) ImGui::PushFont(ui.sideFont);
      scene.overlayUi(column);
      if (side) ImGui::PopFont();
    }
  }
  ui.relayout = false;
}

}  // namespace pba::app
