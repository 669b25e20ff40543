#pragma once
// The base of the ragdoll lab's scenes (Ragdoll paper §5): one RagdollDesc built twice, side by side — the
// particle ragdoll in blue on the left, the constraint ragdoll on the rigid module in purple on the right
// (`show` draws one of them) — with every solver knob of both as parameters, picking and dragging bones,
// debug draw (particles and sticks, joint points, hinge axes and limit arcs, cones, contacts) and the
// metrics under "ragdoll" with particle_ and constraint_ prefixes. Scenes only build their description.
#include <optional>
#include <string>
#include <vector>

#include "app/runner/scene.h"
#include "physics/core/enum_names.h"
#include "physics/ragdoll/constraint_ragdoll.h"
#include "physics/ragdoll/particle_ragdoll.h"

namespace pba::lab {

class RagdollScene : public app::Scene {
 public:
  enum class Shown { Both, Particle, Constraint };
  static constexpr auto kShownNames =
      enumNames<Shown>({{Shown::Both, "both"}, {Shown::Particle, "particle"}, {Shown::Constraint, "constraint"}});

  void reset() override;
  void step(Real dt) override;
  void draw(DebugDraw& d) const override;
  nlohmann::json metrics() const override;
  std::optional<std::string> nonFiniteState() const override;
  std::optional<Real> energy() const override;
  /// Passive from the last start (reset, or the IK scene's switch, which brings the IK motion's energy):
  /// the guard's slack over the larger of the energy then and at the user's last input.
  std::optional<Real> energyGainBound(Real reference) const override;
  Real defaultDt() const override { return 1.0 / 60.0; }
  std::vector<std::string> defaultPlots() const override {
    return {"particle_kinetic_energy_J", "constraint_kinetic_energy_J"};
  }
  std::vector<app::Preset> presets() const override;
  std::vector<app::LegendEntry> legend() const override;
  std::optional<app::PickHit> pick(const Ray& ray) const override;
  void drag(int handle, const Vec3& target) override;
  void release(int handle) override;
  void refresh() override;
  std::vector<app::DragHandle> dragHandles() const override;
  /// From the front (both copies side by side across the screen), framing both copies' start boxes.
  std::optional<app::CameraView> preferredView() const override;

 protected:
  RagdollScene();
  /// The scene's ragdolls, centred about x = 0 (the base class moves the two copies apart).
  virtual ragdoll::RagdollDesc build() const = 0;
  /// Half the distance between the two copies [m]; default: the description's width plus a gap.
  virtual Real halfSeparation(const ragdoll::RagdollDesc& desc) const;
  /// Extra measurements (after the shared ones).
  virtual void extraMetrics(nlohmann::json& /*j*/) const {}

  /// Builds both ragdolls from `desc` (centred about x = 0) side by side, as reset() does with build(), at
  /// ±`half` [m] (negative: halfSeparation(desc)).
  void start(const ragdoll::RagdollDesc& desc, Real half = -1.0);
  /// Declares the figure's start as two parameters that reset the scene: "drop_height" [m], of its lowest
  /// point above the ground, and "tilt", forward (90°: lying face down); the help gives the values they
  /// hold now as the typical ones.
  void declareStartParams(Real& dropHeight, Real& tilt);
  Shown shown() const { return shown_; }
  /// Height [m] of the lowest box corner of a description (figures are lifted so that it is above y = 0).
  static Real lowestCorner(const ragdoll::RagdollDesc& desc);
  static const Color& particleColor();
  static const Color& constraintColor();

  const ragdoll::ParticleRagdoll& particle() const { return particle_; }
  const ragdoll::ConstraintRagdoll& constraint() const { return constraint_; }

  ragdoll::ParticleSettings particleSettings_;
  ragdoll::ConstraintSettings constraintSettings_;
  Real friction_ = 0.5;  ///< Coulomb μ of the constraint ragdoll

 private:
  static constexpr int kConstraintHandle = 100000;  // handles of constraint bodies start here
  struct Rest {
    Real quietFor = 0.0;  ///< [s] kinetic energy below the bound this long
    bool resting() const { return quietFor >= 1.0; }
  };
  void updateRest(Rest& rest, Real kinetic, Real dt) const;

  ragdoll::ParticleRagdoll particle_;
  ragdoll::ConstraintRagdoll constraint_;
  Shown shown_ = Shown::Both;
  Real gravity_ = kStandardGravity;  ///< [m/s²]
  ragdoll::ParticleDrawOptions draw_;
  Real restBound_ = 0.0;  ///< [J] ½ M (5 cm/s)²
  Rest particleRest_, constraintRest_;
  Real particleMs_ = 0.0, constraintMs_ = 0.0;
  bool dragStarted_ = false;
  bool stepped_ = false;    ///< a step since start() (the particle ragdoll's velocities exist only then)
  Real startEnergy_ = 0.0;  ///< [J] energy() at start()
};

}  // namespace pba::lab
