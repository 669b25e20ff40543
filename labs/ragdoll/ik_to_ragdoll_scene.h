#pragma once
// Ragdoll lab, scene "ik-to-ragdoll": a character posed by IK (physics/ik: damped least squares; the right
// hand follows a goal on a scripted path, or dragged with the mouse; hands and feet are effectors) whose
// control switches to the ragdoll on key G, at a scripted time (`switch_at`) or when a thrown box reaches it
// (`throw_at`). Both ragdolls start in the IK pose with the velocities of the last two IK frames (finite
// differences: v = (c_n − c_{n−1}) / h, ω from q_n q_{n−1}⁻¹), so the figure carries on moving as it was and
// then falls; a box in flight joins both ragdolls as a free bone with its velocity.
//
// Joints at the switch: anchors move with the bones; a hinge's limits are shifted by its IK angle θ (the
// range stays the anatomical one: lower − θ … upper − θ); a ball's cone is centred on the switch pose
// (the rigid module's cone-twist joint measures swing from the pose at creation).
#include <string>
#include <vector>

#include "app/assets/character_rig.h"
#include "physics/ik/solver.h"
#include "ragdoll_scene.h"

namespace pba::lab {

class IkToRagdollScene final : public RagdollScene {
 public:
  struct BonePose {
    Vec3 center{0.0};  ///< [m] world, the figure centred at x = 0 (before the side offsets)
    Quat orientation{1, 0, 0, 0};
  };

  IkToRagdollScene();
  std::string description() const override;
  Status validate() override;
  void reset() override;
  void step(Real dt) override;
  void draw(DebugDraw& d) const override;
  bool keyPressed(char key) override;
  std::vector<app::Preset> presets() const override;
  std::vector<app::LegendEntry> legend() const override;
  std::optional<app::PickHit> pick(const Ray& ray) const override;
  void drag(int handle, const Vec3& target) override;
  void release(int handle) override;
  void refresh() override {}
  std::vector<app::DragHandle> dragHandles() const override;
  std::optional<app::CameraView> preferredView() const override;

  /// Hands control to the ragdolls now (key G); `reason` goes to the metrics ("key", "time", "hit").
  void switchToRagdoll(const std::string& reason);
  bool posing() const { return posing_; }
  /// The IK-posed bones of the last step, in the order of the description's bones.
  const std::vector<BonePose>& posedBones() const { return current_; }
  /// The description the ragdolls were built from at the switch (centred at x = 0), else empty.
  const ragdoll::RagdollDesc& switchDescription() const { return switched_; }
  /// x offset [m] of the constraint copy (the particle copy is at −offset).
  Real sideOffset() const { return halfSeparation(rest_); }
  const pba::ik::Rig& rig() const { return rig_; }
  const pba::ik::Pose& pose() const { return pose_; }
  /// The skeleton joint each bone starts at (bones are made for joints with children).
  const std::vector<int>& boneJoints() const { return boneJoint_; }
  int boneCount() const { return static_cast<int>(rest_.bones.size()); }
  using RagdollScene::constraint;
  using RagdollScene::particle;

 protected:
  ragdoll::RagdollDesc build() const override { return rest_; }
  void extraMetrics(nlohmann::json& j) const override;

 private:
  Status load();
  void solveIk(Real dt);
  std::vector<BonePose> bonePoses() const;
  Vec3 projectilePosition(Real t) const;
  Vec3 projectileVelocity(Real t) const;
  bool projectileFlying() const;
  bool projectileReaches(Real dt) const;

  app::CharacterDesc character_;
  pba::ik::SolveOptions options_;
  pba::ik::SolveWorkspace workspace_;  // reused by every solve of the scene
  pba::ik::Rig rig_;
  pba::ik::Pose pose_;
  std::vector<pba::ik::Frame> restFrames_;
  ragdoll::RagdollDesc rest_;   // the figure in the rest pose, feet on the ground, centred at x = 0
  std::vector<int> boneJoint_;  // per bone, its skeleton joint
  int goalEffector_ = 0;        // the right hand's effector
  Vec3 goalRest_{0.0};          // [m] its rest target
  std::vector<BonePose> previous_, current_;
  Real previousDt_ = 1.0 / 60.0;  // [s] between previous_ and current_
  Real time_ = 0.0;               // [s] since reset
  bool posing_ = true;
  bool dragged_ = false;  // the goal follows the mouse (the script stops)
  Vec3 dragGoal_{0.0};
  Real switchedAt_ = -1.0;  // [s]
  std::string switchReason_;
  ragdoll::RagdollDesc switched_;
  Real residual_ = 0.0;  // [m] IK position residual of the last solve
  // Parameters.
  Real pathHertz_ = 0.4;        // [Hz]
  Real switchAt_ = -1.0;        // [s] scripted switch; < 0 never
  Real throwAt_ = 2.0;          // [s] < 0 never
  Real throwSpeed_ = 9.0;       // [m/s]
  Real projectileMass_ = 4.0;   // [kg]
  Real projectileHalf_ = 0.08;  // [m]
  Vec3 projectileStart_{0.0}, projectileAim_{0.0}, projectileVelocity0_{0.0};
};

}  // namespace pba::lab
