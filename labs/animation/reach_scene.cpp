// Animation lab, scene "reach-while-walking": IK layered over a playing clip (Workbook §2.7, advanced:
// "drive it with IK: reaching, walking"). The humanoid's walk cycle plays in place on a ramp; after
// sampling the clip, (1) the hips drop by the ramp height under the lower foot, (2) each leg is solved
// by the law of cosines (ik::twoBoneGeometry) so its foot lies as far above the ramp as it was above
// flat ground in the clip, and (3) the right arm reaches for the draggable goal, blended with the
// clip's arm by the reach weight (slerp of the two poses).
#include <algorithm>
#include <cmath>

#include "anim_scene.h"
#include "physics/animation/builders.h"
#include "posing.h"

namespace pba::lab {
namespace {

class ReachScene final : public AnimScene {
 public:
  ReachScene() {
    params_.angle("slope", &slope_, -20.0, 20.0,
                  "Ramp angle: the ground rises this much toward +z (the walking direction). Typical 12 deg.");
    params_.real(
        "reach", &reach_, 0.0, 1.0, "",
        "Weight of the reaching arm over the clip's arm (slerp of the two poses). 1: the hand goes to the goal.");
    params_.flag("feet_ik", &feetIk_, "Solve the legs so the feet follow the ramp; off, they pass through it.");
    params_.flag("moving_goal", &movingGoal_,
                 "Move the goal on a circle in front of the character (dragging it stops the motion).");
  }
  std::string description() const override {
    return "A walk cycle with IK on top: the right hand reaches for the draggable goal while the legs keep the feet on "
           "the ramp.";
  }
  void reset() override {
    skeleton_ = an::buildHumanoid();
    clip_ = an::buildGaitClip(skeleton_, {}, "walk");
    arm_ = findLimb(skeleton_, "RightArm", "RightForeArm", "RightHand");
    legs_ = {findLimb(skeleton_, "LeftUpLeg", "LeftLeg", "LeftFoot"),
             findLimb(skeleton_, "RightUpLeg", "RightLeg", "RightFoot")};
    goal_ = goalCentre();
    dragged_ = false;
    resetClock();
  }
  void draw(DebugDraw& d) const override {
    drawCharacter(d, skeleton_, world_);
    const Real c = std::cos(slope_);
    d.box(Vec3(0.0, -0.03 / c, 0.0), Vec3(0.7, 0.03, 1.4), glm::angleAxis(-slope_, Vec3(1, 0, 0)),
          Color{0.62f, 0.64f, 0.68f, 1.0f});
    d.sphere(goal_, 0.06, colors::kRed);
    d.line(world_[static_cast<size_t>(arm_.end)].position, goal_, colors::kRed);
  }
  std::vector<app::LegendEntry> legend() const override {
    return {{colors::kRed, "goal of the right hand (drag it)"},
            {Color{0.62f, 0.64f, 0.68f, 1.0f}, "ramp: the feet follow it by IK"}};
  }
  std::optional<app::PickHit> pick(const app::Ray& ray) const override { return app::pickSphere(ray, goal_, 0.1, 0); }
  void drag(int, const Vec3& target) override {
    goal_ = target;
    dragged_ = true;
  }
  void refresh() override { evaluate(); }
  std::vector<app::DragHandle> dragHandles() const override { return {{0, goal_}}; }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 0.7, 0.0), 4.5, 0.9, 0.25};
  }
  std::vector<app::Preset> presets() const override {
    return {{"reach", {{"reach", 1.0}}},
            {"clip only", {{"reach", 0.0}, {"feet_ik", false}}},
            {"half reach", {{"reach", 0.5}}},
            {"downhill", {{"slope", -12.0}}},
            {"still goal", {{"moving_goal", false}}}};
  }

 protected:
  Real duration() const override { return clip_.duration; }
  std::vector<Real> keyTimes() const override { return clip_.tracks[1].rotation.times(); }
  void evaluate() override {
    if (movingGoal_ && !dragged_) {
      const Real a = 2.0 * kPi * time() / clip_.duration;
      goal_ = goalCentre() + Vec3(0.15 * std::cos(a), 0.15 * std::sin(a), 0.0);
    }
    an::playPose(skeleton_, clip_, time(), {true, an::RootMotion::InPlace}, pose_);
    world_ = an::forwardKinematics(skeleton_, pose_);
    if (feetIk_)
      placeFeet();
    else
      footError_ = clipFootError();
    reachForGoal();
    continuity_ = continuityError(clip_.tracks[0].translation);
    reachError_ = glm::length(world_[static_cast<size_t>(arm_.end)].position - goal_);
  }
  void addMetrics(nlohmann::json& m) const override {
    m["reach_error_m"] = reachError_;
    m["foot_height_error_m"] = footError_;
  }

 private:
  Real groundHeight(const Vec3& p) const { return std::tan(slope_) * p.z; }
  Vec3 goalCentre() const { return Vec3(-0.3, 1.25, 0.45); }

  // Foot IK off: how far the clip's feet are from their targets on the ramp, the error the IK removes.
  Real clipFootError() const {
    Real worst = 0.0;
    for (const Limb& leg : legs_)
      worst = std::max(worst, std::abs(groundHeight(world_[static_cast<size_t>(leg.end)].position)));
    return worst;
  }

  void placeFeet() {
    // Foot targets: the clip's height above flat ground, now above the ramp.
    Vec3 target[2];
    Real drop = 0.0;
    for (int k = 0; k < 2; ++k) {
      const Vec3 foot = world_[static_cast<size_t>(legs_[static_cast<size_t>(k)].end)].position;
      target[k] = foot + Vec3(0.0, groundHeight(foot), 0.0);
      drop = std::min(drop, groundHeight(foot));
    }
    pose_.translations[0].y += drop;  // the hips follow the lower foot so the legs can reach
    world_ = an::forwardKinematics(skeleton_, pose_);
    footError_ = 0.0;
    const Vec3 forward = world_[0].rotation * Vec3(0, 0, 1);
    for (int k = 0; k < 2; ++k) {
      const Limb& leg = legs_[static_cast<size_t>(k)];
      reachWithLimb(skeleton_, pose_, world_, leg, target[k],
                    world_[static_cast<size_t>(leg.mid)].position + 0.5 * forward);
      footError_ = std::max(footError_, glm::length(world_[static_cast<size_t>(leg.end)].position - target[k]));
    }
  }
  void reachForGoal() {
    if (reach_ <= 0.0) return;
    const an::Pose clipPose = pose_;
    const Vec3 back = world_[0].rotation * Vec3(0, 0, -1);
    reachWithLimb(skeleton_, pose_, world_, arm_, goal_,
                  world_[static_cast<size_t>(arm_.mid)].position + 0.4 * back - 0.3 * kUp);
    if (reach_ < 1.0) {
      for (int j : {arm_.root, arm_.mid})
        pose_.rotations[static_cast<size_t>(j)] =
            an::slerp(clipPose.rotations[static_cast<size_t>(j)], pose_.rotations[static_cast<size_t>(j)], reach_);
      world_ = an::forwardKinematics(skeleton_, pose_);
    }
  }

  an::Clip clip_;
  Limb arm_;
  std::vector<Limb> legs_;
  Vec3 goal_{0.0};
  bool dragged_ = false;
  Real slope_ = degToRad(12.0);
  Real reach_ = 1.0;
  bool feetIk_ = true;
  bool movingGoal_ = true;
  Real reachError_ = 0.0;  ///< [m] hand to goal
  Real footError_ = 0.0;   ///< [m] worst foot to its ramp target
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Walking", "reach-while-walking", pba::lab::ReachScene);
