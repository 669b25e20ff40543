// IK lab, scene "character": any skeleton Assimp loads (BVH, FBX, COLLADA, glTF), converted into
// ball joints (character_rig.h), with hands and feet reaching for moving goals. The default is the
// project's own humanoid, resources/models/humanoid.bvh (made by tools/make_humanoid_bvh.py):
//   pba-ik --skeleton resources/models/mocap/01_01.bvh --effectors lHand,rHand
#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "app/assets/character_rig.h"
#include "ik_scene.h"

// --skeleton and --effectors pick the character scene over the batch-only flags (--solver, --links,
// …) but not over --targets (priority 1 < 2): "--skeleton F --solver ccd" solves the character with
// CCD; "--effectors LeftHand" alone loads the default humanoid with that effector.
PBA_REGISTER_LAB_FLAG("skeleton", "skeleton", "skeleton file Assimp reads (BVH, FBX, COLLADA, glTF)", "character", 1);
PBA_REGISTER_LAB_FLAG("effectors", "effectors",
                      "comma-separated joint names of the effectors (default: hands and feet)", "character", 1);

namespace pba::lab {

using namespace pba::ik;

using app::CharacterSkin;
using app::poseSkin;
using app::SkinSurface;

namespace {

class CharacterScene final : public IkScene {
 public:
  CharacterScene() {
    options_.solver = SolverKind::DampedLeastSquares;
    options_.maxIterations = 30;
    options_.tolerance = 1e-3;
    options_.damping = 0.03;
    showLimits_ = false;  // ±limit on three Euler angles: cones would hide the body
    declareSolverParams();
    params_
        .text("skeleton", &desc_.skeleton,
              "Skeleton file (BVH, FBX, COLLADA, glTF: anything Assimp reads). Relative paths are also tried from the "
              "repository root. Default: the project's humanoid, resources/models/humanoid.bvh.")
        .needsReset();
    params_
        .text("effectors", &desc_.effectors,
              "Comma-separated joint names that reach for goals, e.g. LeftHand,RightFoot. Empty: the joints named "
              "hand or foot (else the leaves).")
        .needsReset();
    params_
        .real("height", &desc_.height, 0.2, 5.0, "m",
              "The skeleton is scaled so its rest pose is this tall. Typical 1.7 m.")
        .needsReset();
    params_
        .angle("limit", &desc_.limit, 10.0, 180.0,
               "Every ball joint's three Euler angles stay in ±limit. Typical 100 deg.")
        .needsReset();
    params_.flag("skin", &showSkin_,
                 "Draw the file's meshes (skinned by the solved pose) over the skeleton, when it has any.");
  }
  std::string description() const override {
    return "An imported skeleton (any Assimp file): hands and feet reach for their goals; load your own with "
           "--skeleton.";
  }
  Status validate() override {
    const Result<Rig> r = app::loadCharacterRig(desc_);
    return r ? Status::success() : Status(Error{r.error()});
  }
  void ui() override {
    if (!error_.empty())
      ImGui::TextColored(ImVec4(0.86f, 0.2f, 0.18f, 1.0f), "%s (previous skeleton kept)", error_.c_str());
    effectorPicker();
    IkScene::ui();
  }
  void draw(DebugDraw& d) const override {
    if (showSkin_ && skin_.model) {
      // Translucent, so the bones, axes and goals inside stay visible.
      const std::vector<SkinSurface> surfaces = poseSkin(skin_, forwardKinematics(rig_.skeleton, pose_));
      for (const SkinSurface& s : surfaces)
        d.triangles(s.positions, s.normals, s.indices, Color{0.93f, 0.76f, 0.62f, 0.55f});
    }
    IkScene::draw(d);
  }
  nlohmann::json metrics() const override {
    nlohmann::json m = IkScene::metrics();
    m["joints"] = rig_.skeleton.jointCount();
    m["meshes"] = app::meshCount(skin_);
    m["effectors"] = rig_.effectors.size();
    return m;
  }
  std::vector<app::Preset> presets() const override {
    return {{"dls", {{"solver", "dls"}}},
            {"sdls", {{"solver", "sdls"}}},
            {"ccd", {{"solver", "ccd"}}},
            {"fabrik", {{"solver", "fabrik"}}},
            // A skinned file shipped in resources/models (from Assimp's test models): the mesh follows the IK.
            {"skinned wuson", {{"skeleton", "resources/models/Testwuson.X"}, {"effectors", ""}}}};
  }

 protected:
  Rig build() const override {
    CharacterSkin skin;
    Result<Rig> r = app::loadCharacterRig(desc_, &skin);
    if (r) {
      skin_ = std::move(skin);
      error_.clear();
      return std::move(r).value();
    }
    error_ = r.error();  // the window keeps the running skeleton (the command line exits 2 in validate)
    return rig_.skeleton.jointCount() > 0 ? rig_ : buildSingleJoint().value();
  }
  Real pathRadius() const override { return 0.1 * desc_.height; }
  Real groundClearance() const override { return 0.0; }  // feet on the ground; their paths never go below it
  /// Hands draw circles in front of the body; feet step forward and up (never below the ground).
  Vec3 pathOffset(size_t k, Real phase) const override {
    const Real r = pathRadius();
    if (path_ != TargetPath::Circle || k >= centers_.size()) return IkScene::pathOffset(k, phase);
    if (centers_[k].y < 0.25 * desc_.height) return r * Vec3(0.0, 0.5 * (1.0 - std::cos(phase)), 0.8 * std::sin(phase));
    return r * Vec3(0.5 * std::sin(phase), std::sin(phase), 0.8 + 0.8 * std::cos(phase));
  }

 private:
  /// The skeleton's joint names as checkboxes (with a filter for long lists): ticking one makes it an
  /// effector. Edits the "effectors" text parameter, so scene files and --effectors see the same list.
  void effectorPicker() {
    if (!ImGui::CollapsingHeader("Effectors (joints that reach for goals)")) return;
    static ImGuiTextFilter filter;  // one picker is shown at a time
    filter.Draw("filter##joints");
    std::vector<std::string> chosen;
    for (const Effector& e : rig_.effectors) chosen.push_back(rig_.skeleton.joint(e.joint).name);
    bool changed = false;
    const float rows = static_cast<float>(std::min(rig_.skeleton.jointCount(), kPickerRows));
    ImGui::BeginChild("joint names", ImVec2(0.0f, rows * ImGui::GetFrameHeightWithSpacing()), true);
    for (int j = 1; j < rig_.skeleton.jointCount(); ++j) {  // the root is pinned: never an effector
      const std::string& name = rig_.skeleton.joint(j).name;
      if (!filter.PassFilter(name.c_str())) continue;
      const auto it = std::find(chosen.begin(), chosen.end(), name);
      bool on = it != chosen.end();
      ImGui::PushID(j);  // names may repeat in a file
      const bool clicked = ImGui::Checkbox(name.c_str(), &on);
      ImGui::PopID();
      if (clicked) {
        if (on)
          chosen.push_back(name);
        else
          chosen.erase(it);
        changed = true;
      }
    }
    ImGui::EndChild();
    if (ImGui::Button("hands and feet")) {
      chosen.clear();
      changed = true;
    }
    ImGui::SameLine();
    ImGui::TextDisabled("%zu effectors", rig_.effectors.size());
    if (!changed) return;
    std::string list;
    for (const std::string& n : chosen) list += (list.empty() ? "" : ",") + n;
    desc_.effectors = list;  // empty: the automatic hands and feet
    reset();
  }

  static constexpr int kPickerRows = 8;  // joint names shown before the list scrolls
  app::CharacterDesc desc_;
  mutable std::string error_;
  mutable CharacterSkin skin_;  // set by build() with the rig
  bool showSkin_ = true;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Characters", "character", pba::lab::CharacterScene);
