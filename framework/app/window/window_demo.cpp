#include "app/window/window_demo.h"

#include <algorithm>
#include <fstream>
#include <iostream>

#include <imgui.h>

#include "app/lab.h"

namespace pba::app {

Status WindowDemo::open(const std::string& lab, const std::string& path, long step, std::string nextPath) {
  Result<DemoScript> loaded = loadDemoScript(path);
  if (!loaded) return Error{loaded.error()};
  script_ = std::move(loaded.value());
  lab_ = lab;
  nextPath_ = std::move(nextPath);
  index_ = static_cast<std::size_t>(step - 1);
  cameraPending_ = true;
  return Status::success();
}

WindowDemo::Move WindowDemo::move(int delta, LabSession& session) {
  const long target = static_cast<long>(index_) + delta;
  if (target < 0) {
    session.setMessage("Demo: this is the first step");
    return Move::None;
  }
  if (target >= static_cast<long>(script_.steps.size()) ||
      script_.steps[static_cast<std::size_t>(target)].lab != lab_) {
    // Past the end, or another lab's step: ./pba demo goes on from the number left here (none: the end).
    if (!nextPath_.empty() && target < static_cast<long>(script_.steps.size())) {
      std::ofstream out(nextPath_, std::ios::trunc);
      out << target + 1 << '\n';
    }
    return Move::Leave;
  }
  const std::size_t next = static_cast<std::size_t>(target);
  Result<std::unique_ptr<Scene>> scene = demoStepScene(script_, next, 1);
  if (!scene) {
    session.setMessage(scene.error());
    return Move::None;
  }
  index_ = next;
  SceneRunner& runner = session.runner();
  const DemoStep& s = step();
  session.adoptScene(std::move(scene.value()), s.scene);
  if (s.dt) runner.setDt(*s.dt, /*keepAcrossScenes=*/false);
  runner.reset();
  runner.setPaused(s.paused);
  session.reset();
  session.setMessage("Demo step " + std::to_string(index_ + 1) + " of " + std::to_string(script_.steps.size()) +
                     (s.title.empty() ? "" : ": " + s.title));
  cameraPending_ = true;
  return Move::Shown;
}

void WindowDemo::printNotes() const {
  const DemoStep& s = step();
  std::cout << "\n[demo] step " << index_ + 1 << " of " << script_.steps.size() << " (" << s.lab << " / " << s.scene
            << ")" << (s.title.empty() ? "" : ": " + s.title) << "\n"
            << s.notes << "\n";
  if (index_ + 1 < script_.steps.size()) {
    const DemoStep& n = script_.steps[index_ + 1];
    std::cout << "[demo] next (PageDown): " << (n.title.empty() ? n.lab + " / " + n.scene : n.title) << "\n";
  }
  std::cout.flush();
}

float WindowDemo::notesWidth() const {
  return std::min(ImGui::GetIO().DisplaySize.x * 0.3f, 28.0f * ImGui::GetFontSize());
}

void WindowDemo::notesWindow(const UiState& ui, float right) const {
  if (!ui.showNotes) return;
  // In the side font of lecture mode: the notes are for the speaker, the scene is for the room.
  if (ui.lecture && ui.sideFont) ImGui::PushFont(ui.sideFont);
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float width = notesWidth();
  ImGui::SetNextWindowPos(ImVec2(right - 8.0f, 8.0f), ImGuiCond_Always, ImVec2(1, 0));
  // As tall as the notes need (a cap clipped the last line of long notes), within the window.
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, display.y - 16.0f));
  ImGui::SetNextWindowBgAlpha(0.9f);
  const std::string title =
      "Step " + std::to_string(index_ + 1) + " of " + std::to_string(script_.steps.size()) + "##notes";
  ImGui::Begin(title.c_str(), nullptr,
               ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
  const DemoStep& s = step();
  if (!s.title.empty()) ImGui::TextWrapped("%s", s.title.c_str());
  ImGui::Separator();
  ImGui::TextWrapped("%s", s.notes.c_str());
  ImGui::Separator();
  ImGui::TextDisabled("PageDown next, PageUp back, N hides the notes");
  ImGui::End();
  if (ui.lecture && ui.sideFont) ImGui::PopFont();
}

std::optional<CameraView> WindowDemo::takeCamera() {
  if (!cameraPending_) return std::nullopt;
  cameraPending_ = false;
  return step().camera;
}

}  // namespace pba::app
