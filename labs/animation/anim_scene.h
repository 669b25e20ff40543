#pragma once
// The animation lab's common scene: a clock that plays, loops and scrubs (the timeline panel), a
// character (skeleton, pose, world frames) drawn as bones, the metrics of the issue under
// "animation", and the joints for --pose-json. Each scene file adds what it animates.
//
// Timeline keys (CMU asst4's keys mapped onto the common ones): Space play/pause (the runner's pause),
// ←/→ one frame, Shift+←/→ ten frames, Alt+←/→ the previous/next key, Home/End the start/end,
// Delete removes the selected key; the timeline slider scrubs. [ and ] stay previous/next scene.
#include <optional>
#include <string>
#include <vector>

#include "app/runner/scene.h"
#include "app/runner/scene_registry.h"
#include "physics/animation/channel.h"
#include "physics/animation/skeleton.h"

namespace pba::lab {

namespace an = pba::animation;

inline constexpr Real kTimelineFrameRate = 30.0;  ///< [1/s] one ←/→ step of the timeline

class AnimScene : public app::Scene {
 public:
  AnimScene();

  void step(Real dt) override;
  nlohmann::json metrics() const override;
  std::optional<std::string> nonFiniteState() const override;
  void ui() override;
  bool nudge(const Vec3&) override { return true; }  // the arrows belong to the timeline (ui())
  std::vector<std::string> defaultPlots() const override { return {"max_velocity_m_s"}; }
  /// The character's joints by name (--pose-json).
  std::vector<app::NamedPoint> jointPositions() const override;

 protected:
  /// The clip's length [s] (the timeline's range) and the times of its keys (markers, Alt jumps).
  virtual Real duration() const = 0;
  virtual std::vector<Real> keyTimes() const { return {}; }
  /// Recomputes everything that follows from time_ (pose_, world_, curves, ...).
  virtual void evaluate() = 0;
  /// Advances what has dynamics of its own (pendulums) by dt after evaluate(); default nothing.
  virtual void simulate(Real /*dt*/) {}
  /// Removes the selected key (Delete); false when the scene has no editable keys.
  virtual bool deleteKey(int /*index*/) { return false; }
  /// Extra widgets under the timeline.
  virtual void sceneUi() {}
  /// Scene-specific metrics merged into the common ones.
  virtual void addMetrics(nlohmann::json& /*m*/) const {}

  /// Clears the clock and the measurements, then evaluates at t = 0.
  void resetClock();
  /// Moves the clock (scrubbing, frame steps) and re-evaluates; velocities are not measured across it.
  void seek(Real t);
  Real time() const { return time_; }
  /// Draws the character's bones (capsules parent → child), joints and head.
  void drawCharacter(DebugDraw& d, const an::Skeleton& s, const std::vector<an::JointWorld>& world,
                     float alpha = 1.0f) const;
  /// Largest jump of value and velocity across the interior keys of a channel (0 for a C¹ curve).
  static Real continuityError(const an::Channel<Vec3>& c);
  /// Drag handles and picking on the joints of world_ (handle = joint index).
  std::optional<app::PickHit> pickJoint(const app::Ray& ray, Real radius) const;

  an::Skeleton skeleton_;
  an::Pose pose_;
  std::vector<an::JointWorld> world_;
  int clipFrames_ = 0;         ///< samples of a captured clip
  Real continuity_ = 0.0;      ///< see continuityError
  Real pendulumEnergy_ = 0.0;  ///< [J]
  Real speed_ = 1.0;           ///< [1] playback speed
  bool loop_ = true;
  int selectedKey_ = -1;

 private:
  void measureVelocity(Real dt);
  void timelineKeys();
  void timelineBar();
  Real time_ = 0.0;             ///< [s] clip time
  std::vector<Vec3> previous_;  ///< world joint positions at the last step
  Real maxVelocity_ = 0.0;      ///< [m/s] fastest joint at the last step
};

}  // namespace pba::lab
