// IkScene's panel: display toggles, the goal the arrow keys move, and per-DOF angle bars with limits
// (issue "per-joint angle bars with limits"): every DOF of the skeleton in a scrollable child window,
// labelled "joint.axis" (ball joints: .x .y .z, the XYZ Euler DOFs; hinges: the joint's name; free
// joints: their rotation angle against maxRotation), the bar spanning [lo, hi], orange at a limit.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "ik_scene.h"

namespace pba::lab {

using namespace pba::ik;

namespace {
constexpr Real kAtLimit = 1e-3;   // [rad or m] a DOF this close to a limit shows as "at the limit"
constexpr int kVisibleBars = 12;  // rows of the scrollable list before it scrolls

struct BarRow {
  int joint = 0;
  int dof = -1;  ///< index in Pose::dofs, −1 for a free joint's rotation angle
  int axis = 0;  ///< 0–2 within a ball joint
};

std::vector<BarRow> barRows(const Skeleton& s) {
  std::vector<BarRow> rows;
  for (int j = 0; j < s.jointCount(); ++j) {
    const Joint& joint = s.joint(j);
    if (joint.type == JointType::Free) rows.push_back({j, -1, 0});
    for (int k = 0; k < dofCount(joint.type); ++k) rows.push_back({j, joint.firstDof + k, k});
  }
  return rows;
}
}  // namespace

void IkScene::ui() {
  ImGui::Checkbox("show limits", &showLimits_);
  ImGui::SameLine();
  ImGui::Checkbox("show effector path", &showPath_);
  ImGui::Checkbox("show ball joint axes", &showBallAxes_);
  if (usesJacobian(options_.solver)) {
    ImGui::SameLine();
    ImGui::Checkbox("show Jacobian", &showJacobian_);
  }
  if (rig_.effectors.size() > 1) {
    // The goal the arrow keys nudge (also chosen by picking a goal with the mouse).
    const std::string current =
        rig_.skeleton.joint(rig_.effectors[std::min(selected_, rig_.effectors.size() - 1)].joint).name;
    if (ImGui::BeginCombo("goal for the keys", current.c_str())) {
      for (size_t k = 0; k < rig_.effectors.size(); ++k)
        if (ImGui::Selectable(rig_.skeleton.joint(rig_.effectors[k].joint).name.c_str(), k == selected_)) selected_ = k;
      ImGui::EndCombo();
    }
  }
  ImGui::TextDisabled("Arrows, PageUp/PageDown: nudge the goal (Ctrl: fine)");
  if (!last_.message.empty()) ImGui::TextWrapped("%s", last_.message.c_str());
  angleBars();
}

void IkScene::angleBars() const {
  const std::vector<BarRow> rows = barRows(rig_.skeleton);
  if (rows.empty()) return;
  ImGui::Text("Joint angles (%zu DOFs; bar = [lower, upper] limit)", rows.size());
  const float rowHeight = ImGui::GetFrameHeightWithSpacing();
  const float height = rowHeight * static_cast<float>(std::min<size_t>(rows.size(), kVisibleBars)) +
                       ImGui::GetStyle().WindowPadding.y * 2.0f;
  ImGui::BeginChild("angle bars", ImVec2(0.0f, height), true);
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(rows.size()), rowHeight);
  static const char* const kAxis[3] = {".x", ".y", ".z"};
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const BarRow& row = rows[static_cast<size_t>(i)];
      const Joint& joint = rig_.skeleton.joint(row.joint);
      Real v = 0.0, lo = 0.0, hi = 0.0;
      const bool linear = joint.type == JointType::Prismatic;
      std::string label = joint.name;
      if (row.dof < 0) {  // free joint: its rotation angle away from rest, limited by maxRotation
        const Quat q = pose_.rotations[static_cast<size_t>(row.joint)];
        v = 2.0 * std::atan2(glm::length(Vec3(q.x, q.y, q.z)), std::abs(q.w));
        hi = joint.maxRotation;
        label += " (angle)";
      } else {
        v = pose_.dofs[static_cast<size_t>(row.dof)];
        lo = joint.lo[row.axis];
        hi = joint.hi[row.axis];
        if (joint.type == JointType::Ball) label += kAxis[row.axis];
      }
      const float fraction = hi > lo ? static_cast<float>(std::clamp((v - lo) / (hi - lo), 0.0, 1.0)) : 0.5f;
      const bool atLimit = (v - lo < kAtLimit && row.dof >= 0) || hi - v < kAtLimit;
      char overlay[160];
      if (linear)
        std::snprintf(overlay, sizeof overlay, "%s  %.3f m  [%.2f, %.2f]", label.c_str(), v, lo, hi);
      else
        std::snprintf(overlay, sizeof overlay, "%s  %.1f°  [%.0f, %.0f]", label.c_str(), radToDeg(v), radToDeg(lo),
                      radToDeg(hi));
      if (atLimit) ImGui::PushStyleColor(ImGuiCol_PlotHistogram, ImVec4(0.95f, 0.55f, 0.12f, 1.0f));
      ImGui::ProgressBar(fraction, ImVec2(-1.0f, 0.0f), overlay);
      if (atLimit) ImGui::PopStyleColor();
    }
  }
  ImGui::EndChild();
}

}  // namespace pba::lab
