// Animation lab, scene "secondary": the keyframed humanoid (walk or run cycle) with a tail and two
// antennae (chains of spring joints) and a ponytail (a chain of pendulum joints) reacting to its
// motion (CMU asst4, "Pendulum joints", ANIM-4). The pivot accelerations come from the clip itself:
// the second central difference of the pivot's world position under forward kinematics, i.e. the root
// translation's acceleration plus what the keyframed ancestors' rotations add. A grey ghost of each
// chain runs without the reaction term, to show what it adds. Option "ponytail": coupled replaces the
// ponytail's one-way chain by the coupled n-link pendulum (coupled_pendulum.h), whose rods pull on both
// ends; it always feels the pivot's motion, so it has no ghost.
#include <algorithm>
#include <cmath>
#include <utility>

#include "anim_scene.h"
#include "physics/animation/builders.h"
#include "physics/animation/coupled_pendulum.h"
#include "physics/animation/pendulum.h"

namespace pba::lab {
namespace {

enum class Gait { Walk, Run };
constexpr auto kGaitNames = enumNames<Gait>({{Gait::Walk, "walk"}, {Gait::Run, "run"}});
enum class Ponytail { OneWay, Coupled };
constexpr auto kPonytailNames = enumNames<Ponytail>({{Ponytail::OneWay, "one-way"}, {Ponytail::Coupled, "coupled"}});

struct Appendage {
  int joint = -1;
  Vec3 pivotLocal{0.0};  ///< [m] pivot in the joint's frame
  Vec3 restLocal{0.0};   ///< unit rest direction in the joint's frame (spring joints pull toward it)
  an::PendulumChain chain, ghost;
  bool coupled = false;       ///< the coupled pendulum below replaces chain (no ghost)
  an::CoupledPendulum links;  ///< when coupled
  Color color;
};

class SecondaryScene final : public AnimScene {
 public:
  SecondaryScene() {
    params_.choiceEnum("gait", &gait_, kGaitNames, "The keyframed clip that drives the character.").needsReset();
    params_.flag("reaction", &reaction_,
                 "Include the reaction term (the pivot's acceleration) in the pendulum equation; off, only gravity and "
                 "the pivot's position act.");
    params_.flag("ghosts", &ghosts_, "Draw grey ghosts of the chains stepped without the reaction term.");
    params_
        .real("damping", &damping_, 0.0, 5.0, "1/s",
              "c in ω ← ω exp(−c dt) for every link (spring links at least their natural frequency √(k/I), see the "
              "code). Typical 0.8.")
        .needsReset();
    params_
        .real("stiffness", &stiffness_, 0.0, 2.0, "N m/rad",
              "Angular stiffness of the antennae's spring joints (the tail's is 6 times it). Typical 0.15.")
        .needsReset();
    params_.integer("tail_links", &tailLinks_, 1, 8, "", "Links of the tail chain. Typical 4.").needsReset();
    params_
        .choiceEnum("ponytail", &ponytail_, kPonytailNames,
                    "one-way: each link a pendulum joint driven by the one above, which it never pushes back "
                    "(ANIM-4). coupled: the full n-link pendulum, masses on rigid rods that pull both ways "
                    "(RATTLE); the reaction switch does not apply to it.")
        .needsReset();
  }
  std::string description() const override {
    return "A walking character with a spring tail and antennae and a pendulum ponytail driven by its keyframed "
           "motion; grey ghosts ignore the reaction term.";
  }
  Real defaultDt() const override { return 1.0 / 240.0; }
  void reset() override {
    skeleton_ = an::buildHumanoid();
    clip_ = gait_ == Gait::Walk ? an::buildGaitClip(skeleton_, {}, "walk")
                                : an::buildGaitClip(skeleton_, an::runGait(), "run");
    parts_.clear();
    // A stiff tail and antennae (spring joints), a ponytail (pendulum joints: gravity only).
    addPart("Hips", Vec3(0, 0.02, -0.12), glm::normalize(Vec3(0, -0.3, -1)), tailLinks_, 6.0 * stiffness_, 0.12,
            colors::kGreen);
    addPart("Head", Vec3(0.05, 0.17, 0.02), glm::normalize(Vec3(0.35, 1, 0.15)), 2, stiffness_, 0.14, colors::kPurple);
    addPart("Head", Vec3(-0.05, 0.17, 0.02), glm::normalize(Vec3(-0.35, 1, 0.15)), 2, stiffness_, 0.14,
            colors::kPurple);
    addPart("Head", Vec3(0.0, 0.12, -0.1), glm::normalize(Vec3(0, -1, -0.3)), 4, 0.0, 0.09, colors::kPink);
    if (ponytail_ == Ponytail::Coupled) {
      Appendage& tail = parts_.back();
      tail.coupled = true;
      for (const an::PendulumDesc& d : tail.chain.links) {
        tail.links.masses.push_back(d.mass);
        tail.links.lengths.push_back(d.length);
      }
      tail.links.damping = damping_;  // no resonance to tame: the links act on each other
    }
    resetClock();
    for (Appendage& a : parts_) {
      const an::JointWorld& j = world_[static_cast<size_t>(a.joint)];
      a.chain.rest(toWorld(j, a.pivotLocal), j.rotation * a.restLocal);
      a.ghost = a.chain;
      if (a.coupled) {
        a.links.rest(toWorld(j, a.pivotLocal), j.rotation * a.restLocal);
        a.links.pivotVelocity = speed_ * pivotMotion(a).first;
      }
    }
  }
  void draw(DebugDraw& d) const override {
    drawCharacter(d, skeleton_, world_);
    for (const Appendage& a : parts_) {
      const Vec3 pivot = toWorld(world_[static_cast<size_t>(a.joint)], a.pivotLocal);
      if (a.coupled) {
        drawChain(d, pivot, a.links.positions, a.color);
        continue;
      }
      if (ghosts_) drawChain(d, pivot, a.ghost.tips, Color{0.55f, 0.57f, 0.60f, 0.45f});
      drawChain(d, pivot, a.chain.tips, a.color);
    }
  }
  std::vector<app::LegendEntry> legend() const override {
    return {
        {colors::kGreen, "tail: spring joints"},
        {colors::kPurple, "antennae: spring joints"},
        {colors::kPink, ponytail_ == Ponytail::Coupled ? "ponytail: coupled pendulum" : "ponytail: pendulum joints"},
        {colors::kGrey, "ghosts: no reaction term"}};
  }
  // From behind and left: the tail and the ponytail in view.
  // From behind and left: the tail and the ponytail in view.
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 1.0, 0.0), 3.6, 2.3, 0.2};
  }
  std::optional<Real> energy() const override { return std::nullopt; }
  std::vector<std::string> defaultPlots() const override { return {"pendulum_energy_J"}; }
  std::vector<app::Preset> presets() const override {
    return {{"walk", {{"gait", "walk"}}},           {"run", {{"gait", "run"}}},
            {"no reaction", {{"reaction", false}}}, {"floppy", {{"damping", 0.1}, {"stiffness", 0.03}}},
            {"long tail", {{"tail_links", 8}}},     {"coupled ponytail", {{"ponytail", "coupled"}}}};
  }

 protected:
  Real duration() const override { return clip_.duration; }
  std::vector<Real> keyTimes() const override { return clip_.tracks[1].rotation.times(); }
  void evaluate() override {
    an::playPose(skeleton_, clip_, time(), kInPlace, pose_);
    world_ = an::forwardKinematics(skeleton_, pose_);
    continuity_ = continuityError(clip_.tracks[0].translation);
  }
  void simulate(Real dt) override {
    pendulumEnergy_ = 0.0;
    maxPivotAcceleration_ = 0.0;
    for (Appendage& a : parts_) {
      const an::JointWorld& j = world_[static_cast<size_t>(a.joint)];
      const Vec3 pivot = toWorld(j, a.pivotLocal);
      const auto [velocity, acceleration] = pivotMotion(a);
      if (a.coupled) {
        a.links.step(pivot, speed_ * velocity, Vec3(0.0, -kStandardGravity, 0.0), dt);  // d/dt of x(speed · t)
        pendulumEnergy_ += a.links.energy(Vec3(0.0, -kStandardGravity, 0.0));
        maxPivotAcceleration_ = std::max(maxPivotAcceleration_, speed_ * speed_ * glm::length(acceleration));
        continue;
      }
      an::PendulumDrive drive;
      drive.pivotAcceleration = speed_ * speed_ * acceleration;  // d²/dt² of x(speed · t)
      maxPivotAcceleration_ = std::max(maxPivotAcceleration_, glm::length(drive.pivotAcceleration));
      drive.restDirection = j.rotation * a.restLocal;
      drive.reaction = reaction_;
      a.chain.step(pivot, drive, dt);
      drive.reaction = false;
      a.ghost.step(pivot, drive, dt);
      pendulumEnergy_ += a.chain.energy(pivot, drive);
    }
  }
  void addMetrics(nlohmann::json& m) const override { m["max_pivot_acceleration_m_s2"] = maxPivotAcceleration_; }
  std::optional<std::string> nonFiniteState() const override {
    for (const Appendage& a : parts_) {
      for (const an::PendulumState& s : a.chain.states)
        if (!isFinite(s.direction) || !isFinite(s.omega)) return "pendulum chain state is not finite";
      for (size_t k = 0; k < a.links.positions.size(); ++k)
        if (!isFinite(a.links.positions[k]) || !isFinite(a.links.velocities[k]))
          return "coupled pendulum state is not finite";
    }
    return AnimScene::nonFiniteState();
  }

 private:
  static constexpr an::Playback kInPlace{true, an::RootMotion::InPlace};
  static constexpr Real kDifference = 2e-3;  // [s] clip-time step of the central difference

  void addPart(const char* joint, const Vec3& pivot, const Vec3& rest, int links, Real stiffness, Real length,
               const Color& c) {
    Appendage a;
    a.joint = skeleton_.find(joint);
    a.pivotLocal = pivot;
    a.restLocal = rest;
    a.color = c;
    for (int k = 0; k < links; ++k) {
      an::PendulumDesc d;
      d.mass = 0.05;
      d.length = length;
      d.stiffness = stiffness;
      // A chain of equal links driven one way (pendulum.h) amplifies each link's motion by its quality
      // factor Q = ω0/c at resonance: every link gets c ≥ 0.7 ω0 (Q ≤ 1.4), with ω0 = √((k + m g L)/I)
      // its small-swing frequency, so the chain stays calm.
      const Real omega0 = std::sqrt((stiffness + d.mass * kStandardGravity * d.length) / d.momentOfInertia());
      d.damping = std::max(damping_, 0.7 * omega0);
      a.chain.links.push_back(d);
    }
    parts_.push_back(a);
  }
  /// First and second central differences of the pivot's world position over clip time [m/s, m/s²].
  std::pair<Vec3, Vec3> pivotMotion(const Appendage& a) const {
    Vec3 p[3];
    an::Pose pose;
    for (int k = 0; k < 3; ++k) {
      an::playPose(skeleton_, clip_, time() + (k - 1) * kDifference, kInPlace, pose);
      p[k] = toWorld(an::forwardKinematics(skeleton_, pose)[static_cast<size_t>(a.joint)], a.pivotLocal);
    }
    return {(p[2] - p[0]) / (2.0 * kDifference), (p[2] - 2.0 * p[1] + p[0]) / (kDifference * kDifference)};
  }
  static void drawChain(DebugDraw& d, const Vec3& pivot, const std::vector<Vec3>& tips, const Color& color) {
    Vec3 from = pivot;
    for (const Vec3& tip : tips) {
      d.capsule(from, tip, 0.018, color);
      from = tip;
    }
    if (!tips.empty()) d.sphere(tips.back(), 0.035, color);
  }

  an::Clip clip_;
  std::vector<Appendage> parts_;
  Gait gait_ = Gait::Walk;
  bool reaction_ = true;
  bool ghosts_ = true;
  Real damping_ = 0.8;
  Real stiffness_ = 0.15;
  int tailLinks_ = 4;
  Ponytail ponytail_ = Ponytail::OneWay;
  Real maxPivotAcceleration_ = 0.0;  ///< [m/s²] largest pivot acceleration of the last step
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Secondary", "secondary", pba::lab::SecondaryScene);
