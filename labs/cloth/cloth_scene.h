#pragma once
// Shared base of the cloth lab's scenes: one cloth (framework/physics/cloth), its solver switchable live,
// the common parameters of issue 14 (solver, iterations, substeps, stiffness, compliance, damping,
// thickness, resolution), colliders, mouse drag of any particle, drawing (lit two-sided cloth with smooth
// normals and a checker or woven pattern, strain colours, wireframe, springs/constraints) and the
// "cloth" metrics. A scene builds its cloth and colliders and may move pins or colliders each step.
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "app/runner/scene_registry.h"
#include "physics/cloth/solver.h"
#include "physics/cloth/tearing.h"
#include "physics/core/enum_names.h"

namespace pba::lab {

enum class Pattern { Checker, Woven, Plain };
inline constexpr auto kPatternNames =
    enumNames<Pattern>({{Pattern::Checker, "checker"}, {Pattern::Woven, "woven"}, {Pattern::Plain, "plain"}});

class ClothScene : public app::Scene {
 public:
  ClothScene();
  void reset() override;
  void step(Real dt) override;
  void draw(DebugDraw& d) const override;
  nlohmann::json metrics() const override;
  Real defaultDt() const override { return 1.0 / 60.0; }
  std::optional<std::string> nonFiniteState() const override { return cloth::describeNonFinite(cloth_); }
  std::optional<std::string> divergedState() const override;
  std::optional<Real> energy() const override {
    return cloth::clothEnergy(cloth_, env_, settings_.kind, settings_.bending);
  }
  /// Passive scenes keep the guard's slack; a driven one may also gain the kinetic energy of its cloth at twice
  /// driveSpeed() and the work of lifting it by its own size.
  std::optional<Real> energyGainBound(Real reference) const override;
  std::vector<std::string> defaultPlots() const override { return {"energy_J", "max_strain"}; }
  std::vector<app::Preset> presets() const override;
  std::optional<app::PickHit> pick(const app::Ray& ray) const override;
  void drag(int handle, const Vec3& target) override;
  void release(int handle) override;
  bool nudge(const Vec3& delta) override;
  /// A sample of free particles (about 25, spread over the particle indices) and the one being dragged:
  /// what the UI checks drag.
  std::vector<app::DragHandle> dragHandles() const override;
  std::vector<app::LegendEntry> legend() const override;

 protected:
  /// Builds the cloth (grid_ and material_ are set from the parameters) and fills colliders_.
  virtual Result<cloth::Cloth> build() = 0;
  /// Moves pins, colliders or the wind before each step (t: time at the start of the step [s]).
  virtual void beforeStep(Real /*dt*/, Real /*t*/) {}
  /// Extra drawing (rails, poles, markers) after the cloth.
  virtual void drawExtras(DebugDraw& /*d*/) const {}
  /// A horizontal square grid (GridDesc's axes) of resolution_ × resolution_ particles in the layout_
  /// parameter's springs: side [m], centre [m], pins.
  cloth::GridDesc squareGrid(Real side, const Vec3& center, cloth::GridPins pins) const;
  /// A hanging grid (rows along +x, row 0 on top: v̂ = −y) of nx × ny particles in the layout_ parameter's
  /// springs: width and height [m], centre [m], pins.
  cloth::GridDesc hangingGrid(int nx, int ny, Real width, Real height, const Vec3& center, cloth::GridPins pins) const;
  /// Declares the display toggles; scenes call it after their own parameters.
  void declareDisplayParams();
  /// Applies the live parameters (stiffness, compliance, damping, gravity, thickness) to the material,
  /// the environment and the solver settings.
  void applyParams();
  /// [m/s] How fast what drives the cloth moves (wind, moving pins, a pushing collider); 0: a passive scene.
  virtual Real driveSpeed() const { return 0.0; }
  /// Draws one cloth (its pattern, strain colours or plain), with an optional tint.
  void drawCloth(DebugDraw& d, const cloth::Cloth& c, const Color& base) const;
  void drawColliders(DebugDraw& d) const;
  /// The metrics of one cloth (comparison reports four).
  nlohmann::json clothMetrics(const cloth::Cloth& c, const cloth::ClothStepStats& stats,
                              cloth::ClothSolverKind kind) const;

  // Parameters (the common ones of every cloth scene)
  cloth::ClothSolverKind solverKind_ = cloth::ClothSolverKind::Xpbd;
  int resolution_ = 32;                                     ///< particles along the cloth's first side
  Real stiffness_ = 2000.0;                                 ///< [N/m] stretch and shear springs
  Real bendStiffness_ = 20.0;                               ///< [N/m] bend springs
  Real springDamping_ = 0.02;                               ///< [N·s/m]
  Real compliance_ = 0.0;                                   ///< [m/N] XPBD stretch and shear
  Real bendCompliance_ = 1000.0;                            ///< [1/(N·m)] XPBD isometric bending
  Real bendLinkCompliance_ = 1.0;                           ///< [m/N] XPBD distance bending
  Real damping_ = 0.1;                                      ///< [1/s] mass (velocity) damping, every solver
  Real thickness_ = 0.01;                                   ///< [m]
  Real gravity_ = kStandardGravity;                         ///< [m/s²]
  Real friction_ = 0.4;                                     ///< μ of the colliders
  cloth::SpringLayout layout_ = cloth::SpringLayout::Grid;  ///< of the grid scenes' springs
  bool stableExplicit_ = true;                              ///< explicit: substeps of at most half the stability limit
  bool longRange_ = true;                                   ///< PBD/XPBD: long range attachments to the pins
  // Display
  Pattern pattern_ = Pattern::Checker;
  bool strainColors_ = false, wireframe_ = false, showLinks_ = false;

  // State
  cloth::GridDesc grid_;
  cloth::ClothMaterial material_;
  cloth::ClothSolverSettings settings_;
  cloth::ClothEnvironment env_;
  std::vector<cloth::Collider> colliders_;
  cloth::Cloth cloth_;
  cloth::ClothSolver solver_;
  cloth::ClothStepStats stats_;
  std::string buildError_;
  Real time_ = 0.0;
  Real initialEnergy_ = 0.0;  ///< [J] at reset
  double solverMs_ = 0.0;     ///< wall time of the last solver step [ms]
  std::size_t selfIntersections_ = 0, worstSelfIntersections_ = 0;
  bool countIntersections_ = false;   ///< every step (self-collision scenes) instead of on demand
  Real worstColliderDistance_ = 0.0;  ///< [m] most negative over the run
  Color clothColor_{0.85f, 0.33f, 0.25f, 1.0f};
  int dragged_ = -1;
  std::optional<cloth::Pin> draggedWasPinned_;

 private:
  mutable particles::SpatialHash hash_;
};

/// Smooth vertex normals (area weighted) of a cloth's current shape.
void vertexNormals(const cloth::Cloth& c, std::vector<Vec3>& out);

}  // namespace pba::lab
