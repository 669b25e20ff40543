// Animation lab, scene "mocap": plays a motion-capture clip imported through Assimp (default: the
// CMU 01_01.bvh shipped in resources/models/mocap; any BVH/FBX/glTF with an animation through --skeleton,
// e.g. the project's humanoid, resources/models/humanoid.bvh), with the trajectory of one joint drawn
// over the whole clip, and the file's meshes skinned by the played pose when it has any (e.g. the
// Wuson, X/Testwuson.X; app/assets/character_skin.h, the IK lab's character skin) (Workbook §2.7, advanced: "load an animated skeleton").
#include <imgui.h>

#include <memory>

#include "anim_scene.h"
#include "clip_import.h"

PBA_REGISTER_LAB_FLAG("skeleton", "skeleton", "motion file Assimp reads (BVH, FBX, COLLADA, glTF) with an animation",
                      "mocap", 1);

namespace pba::lab {
namespace {

class MocapScene final : public AnimScene {
 public:
  MocapScene() {
    params_
        .text("skeleton", &file_,
              "Motion file with an animation (BVH, FBX, glTF, …). Relative paths are also tried from the repository "
              "root.")
        .needsReset();
    params_
        .real("height", &height_, 0.2, 5.0, "m",
              "The character is scaled so its rest pose is this tall. Typical 1.7 m.")
        .needsReset();
    params_
        .text("trail_joint", &trailJoint_, "Joint whose path over the clip is drawn (empty: none). Typical LeftHand.")
        .needsReset();
    params_.choiceEnum("rotation", &rotationMode_, an::kRotationInterpolationNames,
                       "Interpolation of the rotations between the file's frames.");
    params_.flag("skin", &showSkin_,
                 "Draw the file's meshes, skinned by the played pose (linear blend skinning), when it has any.");
  }
  std::string description() const override {
    return "A motion-capture clip played on its own skeleton; the teal line is one joint's path over the whole clip.";
  }
  Status validate() override {
    const Result<ImportedClip> r = importClip(file_, height_);
    return r ? Status::success() : Status(Error{r.error()});
  }
  void reset() override {
    Result<ImportedClip> r = importClip(file_, height_);
    // The clip is shared, read-only, by the rewind history's copies of the scene
    // (docs/decisions/2026-12-02-rewind-by-copying-scenes-and-checking-determinism.md: a copy per frame of CMU
    // 01_01's 2,752 frames filled the history in a second): a change is a new clip.
    ImportedClip loaded;
    if (r) {
      loaded = std::move(r).value();
      error_.clear();
    } else {
      error_ = r.error();  // the window keeps the clip it has
      loaded = *data_;
    }
    for (an::JointTrack& t : loaded.clip.tracks) t.rotation.setMode(rotationMode_);
    data_ = std::make_shared<const ImportedClip>(std::move(loaded));
    skeleton_ = data_->skeleton;
    clipFrames_ = data_->clip.frames;
    trail_.clear();
    const int j = skeleton_.find(trailJoint_);
    if (j >= 0 && data_->clip.duration > 0.0) {
      an::Pose p;
      for (int s = 0; s <= kTrailSamples; ++s) {
        an::samplePose(skeleton_, data_->clip, data_->clip.duration * s / kTrailSamples, p);
        trail_.push_back(an::forwardKinematics(skeleton_, p)[static_cast<size_t>(j)].position);
      }
    }
    resetClock();
  }
  void draw(DebugDraw& d) const override {
    if (world_.empty()) return;
    const bool skinned = showSkin_ && data_->skin.model;
    if (skinned) {
      // Translucent, so the bones inside stay visible.
      for (const app::SkinSurface& surface : app::poseSkin(data_->skin, world_))
        d.triangles(surface.positions, surface.normals, surface.indices, Color{0.93f, 0.76f, 0.62f, 0.6f});
    }
    drawCharacter(d, skeleton_, world_, skinned ? 0.8f : 1.0f);
    for (size_t s = 1; s < trail_.size(); ++s) d.line(trail_[s - 1], trail_[s], colors::kTeal);
    const int j = skeleton_.find(trailJoint_);
    if (j >= 0) d.sphere(world_[static_cast<size_t>(j)].position, 0.05, colors::kTeal);
  }
  std::vector<app::LegendEntry> legend() const override {
    std::vector<app::LegendEntry> entries{{colors::kBlue, "left side"}, {colors::kOrange, "right side"}};
    if (!trail_.empty()) entries.push_back({colors::kTeal, "path of " + trailJoint_});
    if (showSkin_ && data_->skin.model)
      entries.push_back({Color{0.93f, 0.76f, 0.62f, 1.0f}, "the file's mesh, skinned"});
    return entries;
  }
  void ui() override {
    if (!error_.empty())
      ImGui::TextColored(ImVec4(0.86f, 0.2f, 0.18f, 1.0f), "%s (previous clip kept)", error_.c_str());
    ImGui::Text("%s: %d frames, %.2f s, %d joints", data_->path.c_str(), clipFrames_, data_->clip.duration,
                skeleton_.size());
    AnimScene::ui();
  }
  std::vector<app::Preset> presets() const override {
    return {
        {"humanoid", {{"skeleton", "resources/models/humanoid.bvh"}}},
        {"cmu 01_01", {{"skeleton", "resources/models/mocap/01_01.bvh"}, {"trail_joint", "LeftHand"}}},
        {"boxing", {{"skeleton", "resources/models/mocap/Boxing_Toes.bvh"}, {"trail_joint", ""}}},
        // A skinned, animated file shipped in resources/models (from Assimp's test models): the mesh follows the clip.
        {"skinned wuson", {{"skeleton", "resources/models/Testwuson.X"}, {"trail_joint", ""}}},
        {"step", {{"rotation", "step"}}},
        {"squad", {{"rotation", "squad"}}}};
  }

 protected:
  Real duration() const override { return data_->clip.duration; }
  std::vector<Real> keyTimes() const override {
    // One marker per frame would fill the bar: the keys of the busiest channel, at most 200.
    std::vector<Real> keys;
    for (const an::JointTrack& t : data_->clip.tracks)
      if (t.rotation.times().size() > keys.size()) keys = t.rotation.times();
    if (keys.size() > 200) keys.clear();
    return keys;
  }
  void evaluate() override {
    if (skeleton_.size() == 0) return;
    an::samplePose(skeleton_, data_->clip, time(), pose_);
    world_ = an::forwardKinematics(skeleton_, pose_);
    continuity_ = 0.0;  // a captured clip is only C⁰ (linear/slerp between frames)
  }
  void addMetrics(nlohmann::json& m) const override {
    m["file"] = data_->path;
    m["meshes"] = app::meshCount(data_->skin);
  }

 private:
  static constexpr int kTrailSamples = 240;
  std::string file_ = "resources/models/mocap/01_01.bvh";  // CMU 01_01: 2,752 frames (23 s) of a walk and jumps
  Real height_ = 1.7;
  std::string trailJoint_ = "LeftHand";
  an::RotationInterpolation rotationMode_ = an::RotationInterpolation::Slerp;
  bool showSkin_ = true;
  std::shared_ptr<const ImportedClip> data_ = std::make_shared<const ImportedClip>();
  std::string error_;
  std::vector<Vec3> trail_;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Motion", "mocap", pba::lab::MocapScene);
