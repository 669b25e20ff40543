// Animation lab, scene "keyframes": the built-in humanoid keyframed in the app (CMU asst4's character
// editor). Drag the hips to move the character, a hand or a foot to pose its limb by IK (the law of
// cosines, or any iterative solver of the IK library: parameter "ik"); each edit keys the joints it changed at the current time (a key there is replaced). Keys
// live on the timeline: add a key of the whole pose, select one (click its tick), move it, delete it
// (Delete), play and scrub. Rotations interpolate by squad, the root's translation by Catmull-Rom.
#include <algorithm>
#include <cmath>
#include <set>

#include <imgui.h>

#include "anim_scene.h"
#include "physics/animation/builders.h"
#include "posing.h"

namespace pba::lab {
namespace {

class KeyframesScene final : public AnimScene {
 public:
  KeyframesScene() {
    params_.choiceEnum(
        "rotation", &rotationMode_, an::kRotationInterpolationNames,
        "How joint rotations interpolate between keys: squad is C¹, slerp turns at a corner at each key.");
    params_.choiceEnum("ik", &ikMethod_, pba::ik::solverNames(),
                       "How a dragged hand or foot poses its limb: analytic is the law of cosines with a pole; the "
                       "others are the IK lab's iterative solvers on the limb (ball shoulder or hip, hinge elbow or "
                       "knee). Each drag keys the solved limb at the current time.");
  }
  std::string description() const override {
    return "Keyframe the humanoid: drag the hips, hands or feet (IK) to key a pose, then play and scrub the timeline.";
  }
  void reset() override {
    skeleton_ = an::buildHumanoid();
    clip_ = an::buildWaveClip(skeleton_);
    clip_.name = "keyframes";
    applyRotationMode();
    limbs_ = {findLimb(skeleton_, "LeftArm", "LeftForeArm", "LeftHand"),
              findLimb(skeleton_, "RightArm", "RightForeArm", "RightHand"),
              findLimb(skeleton_, "LeftUpLeg", "LeftLeg", "LeftFoot"),
              findLimb(skeleton_, "RightUpLeg", "RightLeg", "RightFoot")};
    selectedKey_ = -1;
    resetClock();
  }
  void draw(DebugDraw& d) const override {
    drawCharacter(d, skeleton_, world_);
    for (const app::DragHandle& h : dragHandles()) d.sphere(h.position, 0.055, colors::kYellow);
    // The root's path over the clip.
    Vec3 last = clip_.tracks[0].translation.valueAt(0.0);
    for (int s = 1; s <= 60; ++s) {
      const Vec3 p = clip_.tracks[0].translation.valueAt(clip_.duration * s / 60.0);
      d.line(last, p, colors::kTeal);
      last = p;
    }
  }
  std::vector<app::LegendEntry> legend() const override {
    return {{colors::kYellow, "drag: hips move, hands and feet pose by IK"}, {colors::kTeal, "root path"}};
  }
  std::vector<app::DragHandle> dragHandles() const override {
    std::vector<app::DragHandle> h{{0, world_[0].position}};
    for (const Limb& l : limbs_) h.push_back({l.end, world_[static_cast<size_t>(l.end)].position});
    return h;
  }
  std::optional<app::PickHit> pick(const app::Ray& ray) const override {
    std::optional<app::PickHit> best;
    for (const app::DragHandle& h : dragHandles()) {
      const auto hit = app::pickSphere(ray, h.position, 0.08, h.handle);
      if (hit && (!best || hit->distance < best->distance)) best = hit;
    }
    return best;
  }
  void drag(int handle, const Vec3& target) override {
    const Real t = time();
    if (handle == 0) {
      setTranslationKey(0, t, target);
    } else {
      for (const Limb& l : limbs_) {
        if (l.end != handle) continue;
        const Vec3 forward = world_[0].rotation * Vec3(0, 0, 1);
        const bool leg = skeleton_.names[static_cast<size_t>(l.root)].find("Leg") != std::string::npos;
        const Vec3 pole =
            world_[static_cast<size_t>(l.mid)].position + (leg ? 0.5 : -0.5) * forward - (leg ? 0.0 : 0.3) * kUp;
        const pba::ik::SolveResult r = solveLimb(skeleton_, pose_, world_, l, target, pole, ikMethod_);
        ikResidual_ = r.positionResidual;
        ikIterations_ = r.iterations;
        setRotationKey(l.root, t);
        setRotationKey(l.mid, t);
      }
    }
    evaluate();
  }
  void refresh() override { evaluate(); }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 0.9, 0.0), 4.2, 0.5, 0.25};
  }
  std::vector<app::Preset> presets() const override {
    return {{"squad", {{"rotation", "squad"}}}, {"slerp", {{"rotation", "slerp"}}}, {"step", {{"rotation", "step"}}},
            {"ccd", {{"ik", "ccd"}}},           {"fabrik", {{"ik", "fabrik"}}},     {"dls", {{"ik", "dls"}}},
            {"slow motion", {{"speed", 0.25}}}};
  }

 protected:
  Real duration() const override { return clip_.duration; }
  std::vector<Real> keyTimes() const override {
    std::set<Real> all;
    for (const an::JointTrack& t : clip_.tracks) {
      for (Real k : t.translation.times()) all.insert(k);
      for (Real k : t.rotation.times()) all.insert(k);
    }
    return {all.begin(), all.end()};
  }
  void evaluate() override {
    applyRotationMode();
    an::samplePose(skeleton_, clip_, time(), pose_);
    world_ = an::forwardKinematics(skeleton_, pose_);
    continuity_ = continuityError(clip_.tracks[0].translation);
  }
  bool deleteKey(int index) override {
    const std::vector<Real> keys = keyTimes();
    if (index < 0 || index >= static_cast<int>(keys.size())) return false;
    for (an::JointTrack& t : clip_.tracks) {
      for (int k = t.translation.size() - 1; k >= 0; --k)
        if (std::abs(t.translation.time(k) - keys[static_cast<size_t>(index)]) < 1e-9) t.translation.remove(k);
      for (int k = t.rotation.size() - 1; k >= 0; --k)
        if (std::abs(t.rotation.time(k) - keys[static_cast<size_t>(index)]) < 1e-9) t.rotation.remove(k);
    }
    evaluate();
    return true;
  }
  void sceneUi() override {
    if (ImGui::Button("Key the whole pose")) {
      for (int j = 0; j < skeleton_.size(); ++j) setRotationKey(j, time());
      setTranslationKey(0, time(), pose_.translations[0]);
    }
    ImGui::SameLine();
    if (ImGui::Button("Delete key") && deleteKey(selectedKey_)) selectedKey_ = -1;
    const std::vector<Real> keys = keyTimes();
    if (selectedKey_ >= 0 && selectedKey_ < static_cast<int>(keys.size())) {
      float t = static_cast<float>(keys[static_cast<size_t>(selectedKey_)]);
      if (ImGui::SliderFloat("move key", &t, 0.0f, static_cast<float>(clip_.duration), "%.3f s"))
        moveKey(keys[static_cast<size_t>(selectedKey_)], t);
    }
    float d = static_cast<float>(clip_.duration);
    if (ImGui::SliderFloat("clip length", &d, 0.5f, 10.0f, "%.2f s")) clip_.duration = d;
  }
  void addMetrics(nlohmann::json& m) const override {
    m["rotation_interpolation"] = kModes[static_cast<int>(rotationMode_)];
    m["ik_method"] = pba::ik::solverName(ikMethod_);
    m["ik_residual_m"] = ikResidual_;
    m["ik_iterations"] = ikIterations_;
  }

 private:
  static constexpr const char* kModes[] = {"step", "slerp", "squad"};
  void applyRotationMode() {
    for (an::JointTrack& t : clip_.tracks) t.rotation.setMode(rotationMode_);
  }
  void setRotationKey(int joint, Real t) {
    an::RotationChannel& c = clip_.tracks[static_cast<size_t>(joint)].rotation;
    for (int k = 0; k < c.size(); ++k)
      if (std::abs(c.time(k) - t) < 1e-6) return c.setValue(k, pose_.rotations[static_cast<size_t>(joint)]);
    static_cast<void>(c.insert(t, pose_.rotations[static_cast<size_t>(joint)]));
  }
  void setTranslationKey(int joint, Real t, const Vec3& v) {
    an::Channel<Vec3>& c = clip_.tracks[static_cast<size_t>(joint)].translation;
    for (int k = 0; k < c.size(); ++k)
      if (std::abs(c.time(k) - t) < 1e-6) return c.setValue(k, v);
    static_cast<void>(c.insert(t, v));
  }
  /// Moves every key at time `from` to `to` (refused per channel where `to` is taken).
  void moveKey(Real from, Real to) {
    for (an::JointTrack& t : clip_.tracks) {
      for (int k = 0; k < t.translation.size(); ++k)
        if (std::abs(t.translation.time(k) - from) < 1e-9) static_cast<void>(t.translation.move(k, to));
      for (int k = 0; k < t.rotation.size(); ++k)
        if (std::abs(t.rotation.time(k) - from) < 1e-9) static_cast<void>(t.rotation.move(k, to));
    }
    const std::vector<Real> keys = keyTimes();
    selectedKey_ = static_cast<int>(std::lower_bound(keys.begin(), keys.end(), to - 1e-9) - keys.begin());
    evaluate();
  }

  an::Clip clip_;
  std::vector<Limb> limbs_;
  an::RotationInterpolation rotationMode_ = an::RotationInterpolation::Squad;
  pba::ik::SolverKind ikMethod_ = pba::ik::SolverKind::Analytic;
  Real ikResidual_ = 0.0;  ///< [m] the last IK pose's distance from its goal
  int ikIterations_ = 0;   ///< of the last IK pose
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Keyframing", "keyframes", pba::lab::KeyframesScene);
