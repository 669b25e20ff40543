// Animation lab, scene "blend": a cross-fade between two clips of the same skeleton, the built-in
// humanoid's walk and run, blended at the same phase of their cycles by exercise ANIM-6 (blendAtPhase).
// The faint walk and run beside it are the two inputs at that phase. The weight follows a timeline
// (walk, fade, run, fade back) or the slider.
#include "anim_scene.h"
#include "physics/animation/builders.h"

namespace pba::lab {
namespace {

enum class WeightSource { Timeline, Slider };
constexpr auto kWeightSourceNames =
    enumNames<WeightSource>({{WeightSource::Timeline, "timeline"}, {WeightSource::Slider, "slider"}});

class BlendScene final : public AnimScene {
 public:
  BlendScene() {
    params_.choiceEnum("weight_from", &source_, kWeightSourceNames,
                       "Where the blend weight comes from: the weight timeline (walk 2 s, fade 2 s, run 2 s, fade back "
                       "2 s) or the slider below.");
    params_.real("weight", &manualWeight_, 0.0, 1.0, "", "Blend weight w of the run (slider mode): 0 walk, 1 run.");
    params_.real("fade", &fade_, 0.1, 4.0, "s", "Length of each cross-fade on the timeline. Typical 2 s.");
  }
  std::string description() const override {
    return "Walk and run cross-faded at the same phase of their cycles: weights (1 − w, w), lerp translations, slerp "
           "rotations.";
  }
  void reset() override {
    skeleton_ = an::buildHumanoid();
    walk_ = an::buildGaitClip(skeleton_, {}, "walk");
    run_ = an::buildGaitClip(skeleton_, an::runGait(), "run");
    phase_ = 0.0;
    pose_ = an::restPose(skeleton_);  // what a stubbed ANIM-6 leaves
    resetClock();
  }
  void draw(DebugDraw& d) const override {
    drawCharacter(d, skeleton_, world_);
    // The two inputs, faint, beside the blend.
    drawCharacter(d, skeleton_, shifted(walkWorld_, Vec3(-1.2, 0, 0)), 0.35f);
    drawCharacter(d, skeleton_, shifted(runWorld_, Vec3(1.2, 0, 0)), 0.35f);
    d.text(Vec3(-1.2, 2.0, 0), std::string("walk ") + std::to_string(weights_.first).substr(0, 4), colors::kDark);
    d.text(Vec3(1.2, 2.0, 0), std::string("run ") + std::to_string(weights_.second).substr(0, 4), colors::kDark);
  }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 0.9, 0.0), 5.5, 0.9, 0.2};
  }
  std::vector<std::string> defaultPlots() const override { return {"blend_weight"}; }
  std::vector<app::Preset> presets() const override {
    return {{"timeline", {{"weight_from", "timeline"}}},
            {"walk", {{"weight_from", "slider"}, {"weight", 0.0}}},
            {"half", {{"weight_from", "slider"}, {"weight", 0.5}}},
            {"run", {{"weight_from", "slider"}, {"weight", 1.0}}},
            {"fast fades", {{"fade", 0.5}}}};
  }

 protected:
  Real duration() const override { return 4.0 + 2.0 * fade_; }
  std::vector<Real> keyTimes() const override { return {0.0, 2.0, 2.0 + fade_, 4.0 + fade_, 4.0 + 2.0 * fade_}; }
  void evaluate() override {
    const Real t = time();
    if (source_ == WeightSource::Slider) {
      weights_ = {1.0 - manualWeight_, manualWeight_};
    } else {
      const an::BlendWeights up = an::crossFadeWeights(t, 2.0, fade_);
      const an::BlendWeights down = an::crossFadeWeights(t, 4.0 + fade_, fade_);
      weights_ = {1.0 - up.second * down.first, up.second * down.first};
    }
    // ANIM-6 at this phase: the blend, and its two inputs (weights 0 and 1 give each clip alone).
    an::Pose a = an::restPose(skeleton_), b = a;
    an::blendAtPhase(skeleton_, walk_, run_, 0.0, phase_, 0.0, a);
    an::blendAtPhase(skeleton_, walk_, run_, 1.0, phase_, 0.0, b);
    an::blendAtPhase(skeleton_, walk_, run_, weights_.second, phase_, 0.0, pose_);
    walkWorld_ = an::forwardKinematics(skeleton_, a);
    runWorld_ = an::forwardKinematics(skeleton_, b);
    world_ = an::forwardKinematics(skeleton_, pose_);
    continuity_ = continuityError(walk_.tracks[0].translation);
  }
  void simulate(Real dt) override {
    an::Pose next;  // the pose at the new phase is evaluate()'s, next frame
    phase_ = an::blendAtPhase(skeleton_, walk_, run_, weights_.second, phase_, speed_ * dt, next);  // ANIM-6
  }
  void addMetrics(nlohmann::json& m) const override {
    m["blend_weight"] = weights_.second;
    m["weight_sum"] = weights_.first + weights_.second;
    m["phase"] = phase_;
  }

 private:
  static std::vector<an::JointWorld> shifted(std::vector<an::JointWorld> w, const Vec3& by) {
    for (an::JointWorld& j : w) j.position += by;
    return w;
  }
  an::Clip walk_, run_;
  WeightSource source_ = WeightSource::Timeline;
  Real manualWeight_ = 0.5;
  Real fade_ = 2.0;
  Real phase_ = 0.0;  ///< [1] position in the gait cycle, shared by both clips
  an::BlendWeights weights_;
  std::vector<an::JointWorld> walkWorld_, runWorld_;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Motion", "blend", pba::lab::BlendScene);
