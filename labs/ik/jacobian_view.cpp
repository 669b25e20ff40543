#include "jacobian_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "physics/ik/linalg.h"

namespace pba::lab {

using namespace pba::ik;

namespace {

const ImVec4 kPositive(0.84f, 0.24f, 0.18f, 1.0f);  // red: the effector moves along +row
const ImVec4 kNegative(0.18f, 0.40f, 0.84f, 1.0f);  // blue
const ImVec4 kZero(1.0f, 1.0f, 1.0f, 1.0f);
const ImVec4 kBar(0.26f, 0.52f, 0.86f, 1.0f);
const ImVec4 kMarker(0.93f, 0.55f, 0.10f, 1.0f);

ImU32 heat(Real t) {  // t in [−1, 1]
  const float a = static_cast<float>(std::min(1.0, std::abs(t)));
  const ImVec4& end = t >= 0.0 ? kPositive : kNegative;
  return ImGui::GetColorU32(
      ImVec4(kZero.x + (end.x - kZero.x) * a, kZero.y + (end.y - kZero.y) * a, kZero.z + (end.z - kZero.z) * a, 1.0f));
}

const char* methodCaption(SolverKind kind) {
  switch (kind) {
    case SolverKind::JacobianTranspose:
      return "Jacobian transpose: the step along each singular direction grows with σ, so "
             "directions with small σ move slowly.";
    case SolverKind::PseudoInverse:
      return "Pseudo-inverse: gain 1/σ per direction; σ below the cut-off (orange) are dropped, "
             "otherwise near-singular poses give huge steps.";
    case SolverKind::DampedLeastSquares:
      return "Damped least squares: gain σ/(σ² + λ²); directions with σ well below λ "
             "(orange) are damped, the rest behave like the pseudo-inverse.";
    case SolverKind::SelectivelyDamped:
      return "Selectively damped least squares: each singular direction gets its own "
             "clamp on the joint change it may cause (Buss & Kim 2005).";
    case SolverKind::GradientDescent:
      return "Gradient descent: the direction J^T r, like the transpose; along each singular "
             "direction the gain is σ times the step length, chosen by the line search.";
    case SolverKind::Lbfgs:
      return "L-BFGS: the gradient J^T r bent by an inverse-Hessian estimate built from the last "
             "steps, so directions with small σ catch up (a quasi-Newton method).";
    default:
      return "";
  }
}

// Rows of the heat map: labels per row when they fit, else one per effector.
void heatMap(const JacobianView& v) {
  const Matrix& J = v.J;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float font = ImGui::GetFontSize();
  const float labelWidth = ImGui::CalcTextSize("rz00").x + 0.4f * font;
  const float mapWidth = std::max(ImGui::GetContentRegionAvail().x - labelWidth, 4.0f * font);
  const int bins = std::max(1, std::min(J.cols, static_cast<int>(mapWidth / 4.0f)));  // ≥ 4 px per cell
  const float cellWidth = mapWidth / static_cast<float>(bins);
  const float cellHeight = std::clamp(9.0f * font / static_cast<float>(std::max(J.rows, 1)), 0.3f * font, 0.95f * font);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  Real maxAbs = 0.0;
  for (Real x : J.data) maxAbs = std::max(maxAbs, std::abs(x));
  const bool rowLabels = cellHeight >= 0.8f * font;
  for (int r = 0; r < J.rows; ++r) {
    const float y = origin.y + static_cast<float>(r) * cellHeight;
    const std::string& label = v.rowLabels[static_cast<size_t>(r)];
    if (rowLabels || (label[0] == 'x' && J.rows >= 3)) {  // per row, or one label per effector (its x row)
      char effector[24];
      std::snprintf(effector, sizeof effector, "e%s", label.c_str() + 1);
      draw->AddText(ImVec2(origin.x, y + (rowLabels ? 0.5f * (cellHeight - font) : 0.0f)),
                    ImGui::GetColorU32(ImGuiCol_Text), rowLabels ? label.c_str() : effector);
    }
    for (int b = 0; b < bins; ++b) {
      // A cell covering several columns shows the entry of largest magnitude among them.
      const int c0 = b * J.cols / bins, c1 = std::max(c0 + 1, (b + 1) * J.cols / bins);
      Real value = 0.0;
      for (int c = c0; c < c1; ++c)
        if (std::abs(J(r, c)) > std::abs(value)) value = J(r, c);
      const float x = origin.x + labelWidth + static_cast<float>(b) * cellWidth;
      draw->AddRectFilled(ImVec2(x, y), ImVec2(x + cellWidth, y + cellHeight),
                          heat(maxAbs > 0.0 ? value / maxAbs : 0.0));
    }
  }
  const float bottom = origin.y + static_cast<float>(J.rows) * cellHeight;
  const ImU32 grid = ImGui::GetColorU32(ImVec4(0.35f, 0.35f, 0.38f, 0.8f));
  if (bins == J.cols)  // joint boundaries
    for (int c = 1; c < J.cols; ++c)
      if (v.jointOfColumn[static_cast<size_t>(c)] != v.jointOfColumn[static_cast<size_t>(c - 1)]) {
        const float x = origin.x + labelWidth + static_cast<float>(c) * cellWidth;
        draw->AddLine(ImVec2(x, origin.y), ImVec2(x, bottom), grid);
      }
  draw->AddRect(ImVec2(origin.x + labelWidth, origin.y), ImVec2(origin.x + labelWidth + mapWidth, bottom), grid);
  ImGui::Dummy(ImVec2(labelWidth + mapWidth, static_cast<float>(J.rows) * cellHeight + 2.0f));
  ImGui::TextDisabled("%d × %d, max |J| = %.3g; blue < 0 < red", J.rows, J.cols, maxAbs);
  if (bins < J.cols) ImGui::TextDisabled("a cell shows the largest of %d columns", (J.cols + bins - 1) / bins);
}

// Singular values as bars on a common scale, with λ (DLS) or the cut-off (pseudo-inverse) marked.
void singularValues(const JacobianView& v, const SolveOptions& o) {
  if (v.sigma.empty()) return;
  const Real top = v.sigma.front();
  const Real low = v.sigma.back();
  if (low > 0.0)
    ImGui::Text("Singular values: condition σ1/σ%zu = %.3g", v.sigma.size(), top / low);
  else
    ImGui::Text("Singular values: σ%zu = 0, singular pose", v.sigma.size());
  Real marker = -1.0;
  const char* markerName = "";
  if (o.solver == SolverKind::DampedLeastSquares) marker = o.damping, markerName = "λ";
  if (o.solver == SolverKind::PseudoInverse) marker = o.singularCutoff * top, markerName = "cut-off";
  const Real scale = std::max(top, marker) > 0.0 ? std::max(top, marker) : 1.0;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float font = ImGui::GetFontSize();
  const float textWidth = ImGui::CalcTextSize("σ00 = 0.000e+00").x + 0.5f * font;
  const float barArea = std::max(ImGui::GetContentRegionAvail().x - textWidth, 4.0f * font);
  // At most 12 bars: the 6 largest and the 6 smallest (those decide how near singular the pose is).
  std::vector<size_t> index;
  for (size_t i = 0; i < v.sigma.size(); ++i)
    if (v.sigma.size() <= 12 || i < 6 || i + 6 >= v.sigma.size()) index.push_back(i);
  const size_t shown = index.size();
  const float rowHeight = shown > 6 ? 0.75f * font : font;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  for (size_t row = 0; row < shown; ++row) {
    const size_t i = index[row];
    const float y = origin.y + static_cast<float>(row) * rowHeight;
    char label[48];
    std::snprintf(label, sizeof label, "σ%zu = %.3g", i + 1, v.sigma[i]);
    // Compressed rows: label every other one, always the first and the last (the smallest σ).
    if (shown <= 6 || row + 1 == shown || (row % 2 == 0 && row + 2 != shown))
      draw->AddText(ImVec2(origin.x, y + 0.5f * (rowHeight - font)), ImGui::GetColorU32(ImGuiCol_Text), label);
    const float w = static_cast<float>(v.sigma[i] / scale) * barArea;
    draw->AddRectFilled(ImVec2(origin.x + textWidth, y + 0.15f * rowHeight),
                        ImVec2(origin.x + textWidth + std::max(w, 1.0f), y + 0.85f * rowHeight),
                        ImGui::GetColorU32(kBar));
  }
  const float bottom = origin.y + static_cast<float>(shown) * rowHeight;
  if (marker >= 0.0) {
    const float x = origin.x + textWidth + static_cast<float>(marker / scale) * barArea;
    draw->AddLine(ImVec2(x, origin.y), ImVec2(x, bottom), ImGui::GetColorU32(kMarker), 2.0f);
    draw->AddText(
        ImVec2(std::min(x + 3.0f, origin.x + textWidth + barArea - ImGui::CalcTextSize(markerName).x), bottom),
        ImGui::GetColorU32(kMarker), markerName);
  }
  ImGui::Dummy(ImVec2(textWidth + barArea, static_cast<float>(shown) * rowHeight + (marker >= 0.0 ? font : 0.0f)));
  if (shown < v.sigma.size()) ImGui::TextDisabled("(σ7 … σ%zu not shown)", v.sigma.size() - 6);
}

}  // namespace

bool usesJacobian(SolverKind kind) {
  return kind == SolverKind::JacobianTranspose || kind == SolverKind::PseudoInverse ||
         kind == SolverKind::DampedLeastSquares || kind == SolverKind::SelectivelyDamped ||
         kind == SolverKind::GradientDescent || kind == SolverKind::Lbfgs;
}

JacobianView computeJacobianView(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
                                 const SolveOptions& options) {
  JacobianView v;
  const std::vector<Frame> frames = forwardKinematics(s, pose);
  const Real scale = resolvedOrientationScale(s, effectors, options);
  const JacobianLayout layout = planJacobian(s, pose, effectors, frames, scale);
  v.J = options.jacobian == JacobianSource::Analytic
            ? jacobian(s, pose, effectors, frames, layout, scale)
            : numericalJacobian(s, pose, effectors, layout, scale, kJacobianStep);
  v.sigma = svd(v.J).sigma;
  v.rowLabels.resize(static_cast<size_t>(v.J.rows));
  for (size_t k = 0; k < effectors.size(); ++k) {
    const int first = layout.rowOfEffector[k];
    const int count = effectors[k].kind == EffectorKind::PositionOrientation ? 6 : 3;
    for (int i = 0; i < count; ++i) {
      char label[24];  // snprintf: GCC 12 -O3 misreports -Wrestrict on short string concatenations
      std::snprintf(label, sizeof label, "%s%c%zu", i < 3 ? "" : "r", "xyz"[i % 3], k);
      v.rowLabels[static_cast<size_t>(first + i)] = label;
    }
  }
  for (int c = 0; c < v.J.cols; ++c)
    v.jointOfColumn.push_back(c < s.dofCount() ? s.dofJoint(c)
                                               : layout.freeJoints[static_cast<size_t>(c - s.dofCount())]);
  return v;
}

void drawJacobianWindow(const JacobianView& view, const SolveOptions& options, const app::ScreenRect& column) {
  const float width = column.x1 - column.x0;
  ImGui::SetNextWindowPos(ImVec2(column.x1, column.y1), ImGuiCond_Always, ImVec2(1.0f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);  // height 0: fit the contents
  const std::string title = std::string("Jacobian J (") + solverName(options.solver) + ")";
  ImGui::Begin(title.c_str(), nullptr,
               ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  if (view.J.rows == 0 || view.J.cols == 0) {
    ImGui::TextUnformatted("no effector below a movable joint");
  } else {
    heatMap(view);
    ImGui::Separator();
    singularValues(view, options);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", methodCaption(options.solver));
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

}  // namespace pba::lab
