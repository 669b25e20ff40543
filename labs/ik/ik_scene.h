#pragma once
// Shared base of the IK lab's interactive scenes: a rig (skeleton + effectors) solved every step
// toward goals that the user drags with the mouse or that follow a scripted path (circle, figure-8,
// random jumps) for lectures, or nudged with the arrow keys (app/window/target_nudge.h: the goal last
// picked moves). Draws bones as capsules, joints, rotation axes (hinges; ball joints on request),
// limits as arcs and cones from the per-DOF ranges, goals and the effector's path over the
// iterations of the last solve (ik_scene_draw.cpp); shows per-DOF angle bars with their limits
// (ik_scene_ui.cpp); reports the "ik" metrics.
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "app/runner/scene_registry.h"
#include "jacobian_view.h"
#include "physics/core/enum_names.h"
#include "physics/ik/builders.h"
#include "physics/ik/solver.h"

namespace pba::lab {

enum class TargetPath { Mouse, Circle, Figure8, RandomJumps };
inline constexpr auto kTargetPathNames = enumNames<TargetPath>({{TargetPath::Mouse, "mouse"},
                                                                {TargetPath::Circle, "circle"},
                                                                {TargetPath::Figure8, "figure8"},
                                                                {TargetPath::RandomJumps, "random"}});

inline constexpr Real kTargetRadiusFactor = 2.2;  // goal sphere radius in bone radii

/// Declares the options that depart from the methods as published (step clamp, line search of the
/// Jacobian methods, stall-recovery restarts; SolveOptions) and the Jacobian's source, once for every
/// IK scene. Their defaults are the published methods. With `jacobianOnly`, the Jacobian options
/// show only while `options` selects a Jacobian-family method (they always load, save and parse).
void declareMethodOptions(app::Params& params, ik::SolveOptions& options, bool jacobianOnly);

class IkScene : public app::Scene {
 public:
  IkScene();
  void reset() override;
  void step(Real dt) override;
  void draw(DebugDraw& d) const override;
  nlohmann::json metrics() const override;
  void ui() override;
  bool wantsOverlay() const override { return showJacobian_ && usesJacobian(options_.solver); }
  void overlayUi(const app::ScreenRect& column) override;
  std::optional<std::string> nonFiniteState() const override;
  std::vector<std::string> defaultPlots() const override { return {"residual", "iterations"}; }
  std::optional<app::PickHit> pick(const app::Ray& ray) const override;
  void drag(int handle, const Vec3& target) override;
  void release(int) override { dragging_ = false; }
  /// Moves the selected goal (the one last picked) by delta [m]; the goal then stays put (path: mouse).
  /// Like a drag, it is solved by the next step, or at once by refresh() when the scene is paused.
  bool nudge(const Vec3& delta) override;
  /// Solves toward the goals as they are now (the runner calls it after a drag or nudge while paused).
  void refresh() override { solveNow(); }
  std::vector<app::DragHandle> dragHandles() const override;
  std::vector<app::LegendEntry> legend() const override;
  /// The solved pose's joints by name, and each effector point that sits off its joint as
  /// "<joint>.effector" (a chain's tip) (--pose-json).
  std::vector<app::NamedPoint> jointPositions() const override;
  /// Each effector's goal, by the name of its point in jointPositions() (--pose-json).
  std::vector<app::NamedPoint> goalPositions() const override;
  /// A tenth of the scripted path's radius: ~20 key presses across the path.
  Real nudgeStep() const override { return 0.1 * pathRadius(); }

 protected:
  /// Builds the rig from the scene's parameters (goals at rest positions).
  virtual ik::Rig build() const = 0;
  /// Radius [m] of the scripted path around each effector's rest position.
  virtual Real pathRadius() const { return 0.4; }
  /// Offset [m] of effector k's goal from its rest position on the scripted circle or figure-8 at
  /// `phase` [rad] (the path_ member says which).
  virtual Vec3 pathOffset(size_t k, Real phase) const;
  /// Height [m] above the ground of the rig's lowest point at rest (see liftAboveGround()).
  virtual Real groundClearance() const { return 1.5 * pathRadius(); }
  void declareSolverParams(bool withPath = true);
  void liftAboveGround();
  void solveNow();
  Real boneRadius() const { return boneRadius_; }
  /// Rotation axes and limits of joint j (ik_scene_draw.cpp).
  void drawJointAxesAndLimits(DebugDraw& d, int j, const std::vector<ik::Frame>& f) const;
  /// The bone that leaves joint j in its own frame [m] (first child's offset, else an effector's
  /// local offset, else +x): the direction whose range a limit cone or arc shows.
  Vec3 boneOf(int j) const;
  /// Per-DOF angle bars labelled "joint.axis", scrollable, with limits (ik_scene_ui.cpp).
  void angleBars() const;

  ik::Rig rig_;
  ik::Pose pose_;
  ik::SolveOptions options_;
  ik::SolveWorkspace workspace_;  // reused by every solve of the scene
  ik::SolveResult last_;
  TargetPath path_ = TargetPath::Circle;
  Real pathSpeed_ = 0.5;  // [Hz] laps per second of the scripted path
  bool showLimits_ = true;
  bool showPath_ = true;
  bool showJacobian_ = true;
  bool showBallAxes_ = false;  // the three Euler axes of every ball joint (red x, green y, blue z)
  size_t selected_ = 0;        // the goal the arrow keys move: the one last picked
  std::vector<Vec3> centers_;  // rest goals: centres of the scripted paths
  Real time_ = 0.0;
  bool dragging_ = false;
  Real boneRadius_ = 0.03;
  std::mt19937_64 rng_;
  Real nextJump_ = 0.0;
};

}  // namespace pba::lab
