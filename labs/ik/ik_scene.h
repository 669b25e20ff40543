#pragma once
// Shared base of the IK lab's interactive scenes: a rig (skeleton + effectors) solved every step
// toward goals that the user drags with the mouse or that follow a scripted path (circle, figure-8,
// random jumps) for lectures. Draws bones as capsules, joints, hinge axes, limits, goals and the
// effector's path over the iterations of the last solve; reports the "ik" metrics.
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "app/scene_registry.h"
#include "jacobian_view.h"
#include "physics/ik/builders.h"
#include "physics/ik/solver.h"

namespace pba::labs::ik {

using namespace pba::ik;

enum class TargetPath { Mouse, Circle, Figure8, RandomJumps };

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

 protected:
  /// Builds the rig from the scene's parameters (goals at rest positions).
  virtual Rig build() const = 0;
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

  Rig rig_;
  Pose pose_;
  SolveOptions options_;
  SolveResult last_;
  TargetPath path_ = TargetPath::Circle;
  Real pathSpeed_ = 0.5;   // [Hz] laps per second of the scripted path
  bool showLimits_ = true;
  bool showPath_ = true;
  bool showJacobian_ = true;
  std::vector<Vec3> centers_;  // rest goals: centres of the scripted paths
  Real time_ = 0.0;
  bool dragging_ = false;
  Real boneRadius_ = 0.03;
  std::mt19937_64 rng_;
  Real nextJump_ = 0.0;
};

}  // namespace pba::labs::ik
