#pragma once
// The base of the rigid lab's scenes: a rigid::World, every solver knob of rigid::WorldSettings as a
// parameter, picking and dragging bodies (a soft mouse constraint), shooting a ball from the camera
// (click where no body is), contact debug draw and the metrics every scene reports under "rigid".
// Scenes add their bodies in build() and their own measurements in extraMetrics().
#include <optional>
#include <string>

#include "app/runner/scene.h"
#include "physics/rigid/builders.h"
#include "physics/rigid/world.h"

namespace pba::lab {

class WorldScene : public app::Scene {
 public:
  void reset() override;
  void step(Real dt) override;
  void draw(DebugDraw& d) const override;
  nlohmann::json metrics() const override;
  std::optional<std::string> nonFiniteState() const override { return world_.nonFiniteState(); }
  std::optional<Real> energy() const override;
  Real defaultDt() const override { return 1.0 / 60.0; }
  std::vector<std::string> defaultPlots() const override { return {"kinetic_energy_J", "contacts"}; }
  std::optional<app::PickHit> pick(const Ray& ray) const override;
  void drag(int handle, const Vec3& target) override;
  void release(int handle) override;
  /// Paused: the dragged body is placed under the cursor at once (running, the mouse spring pulls it).
  void refresh() override { world_.placeDragged(); }
  /// The highest dynamic bodies (those least likely hidden behind others) and the dragged one.
  std::vector<app::DragHandle> dragHandles() const override;

 protected:
  /// Declares the shared parameters; call from the scene's constructor after setting defaults in
  /// settings_ (e.g. gyroscopic mode) and before the scene's own parameters.
  explicit WorldScene(bool withShooting = true);
  virtual void build(rigid::World& world) = 0;
  virtual void afterStep(Real /*dt*/) {}
  virtual void extraMetrics(nlohmann::json& /*j*/) const {}
  virtual void drawExtra(DebugDraw& /*d*/) const {}

  rigid::WorldSettings settings_;
  rigid::WorldDrawOptions drawOptions_;
  rigid::World world_;
  Real gravity_ = kStandardGravity;  ///< [m/s²] downwards

 private:
  static constexpr int kShootHandle = -2;
  bool shooting_ = true;
  Real shotSpeed_ = 15.0;  ///< [m/s]
  mutable std::optional<Ray> pendingShot_;
  bool dragStarted_ = false;
};

}  // namespace pba::lab
