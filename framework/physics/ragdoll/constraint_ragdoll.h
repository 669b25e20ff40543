#pragma once
// The constraint ragdoll (Ragdoll paper §4) on the rigid module: one box body per bone in a rigid::World,
// ball joints (cone-twist joints with the cone as swing limit and a free twist, when limited) and hinges
// with limits, solved by the world's soft step (substeps with soft constraints and relaxation, Box2D v3).
// The paper's failures — ball-joint limits that crashed its engine and heavy boxes sinking into the floor —
// do not occur here: the swing limit is one angular row along the swing axis (no Euler-angle singularity),
// and soft contacts with substeps hold an 8× box (tests/physics/ragdoll).
#include <optional>
#include <string>
#include <vector>

#include "physics/ragdoll/ragdoll_desc.h"
#include "physics/rigid/world.h"

namespace pba::ragdoll {

/// The world's settings for ragdolls: the rigid lab's soft step (4 substeps × 1 iteration) with 60 Hz
/// contacts and joints and an 8 cm speculative margin. Measured on the paper's scenes: the rigid lab's
/// 120 Hz joints made a spider's legs flail on their cone limits without coming to rest (stiffness at half
/// the substep rate), and a 2 cm margin let the corner of a spinning limb sink 2–3 cm for a step.
rigid::WorldSettings ragdollWorldSettings();
/// The same for ragdolls from skeleton files (skeleton_ragdoll.h), with a 2 cm speculative margin: with
/// 8 cm, the light foot and toe boxes of every BVH figure lying on the ground kept jittering and never came
/// to rest (tests/labs/ragdoll_bvh_rest_test.cpp); a figure dropped whole has no fast-spinning limbs, the
/// reason for 8 cm.
rigid::WorldSettings skeletonRagdollWorldSettings();

struct ConstraintSettings {
  rigid::WorldSettings world = ragdollWorldSettings();  ///< gravity, substeps, iterations, sleeping, …
  bool ground = true;                                   ///< a static plane y = 0
};

struct ConstraintStats {
  int bones = 0, constraints = 0, contacts = 0;
  Real kineticEnergy = 0.0;      ///< [J]
  Real potentialEnergy = 0.0;    ///< [J]
  Real maxJointError = 0.0;      ///< [m]
  Real maxLimitViolation = 0.0;  ///< [rad]
  Real maxPenetration = 0.0;     ///< [m] deepest box corner below y = 0
  int sleeping = 0;
};

class ConstraintRagdoll {
 public:
  ConstraintRagdoll() = default;
  static Result<ConstraintRagdoll> build(const RagdollDesc& desc, const ConstraintSettings& settings = {});
  /// Adds the ragdoll's bodies and joints to an existing world (several ragdolls in one world).
  static Result<ConstraintRagdoll> addTo(rigid::World& world, const RagdollDesc& desc);

  void step(Real dt) { world_.step(dt); }
  rigid::World& world() { return world_; }
  const rigid::World& world() const { return world_; }
  int boneCount() const { return static_cast<int>(bodies_.size()); }
  int bodyOf(int bone) const { return bodies_[bone]; }
  /// Hinge angle of B about the axis, or the swing angle of a ball joint [rad].
  Real jointAngle(int joint) const;
  ConstraintStats stats() const;
  /// Bytes held by the world's bodies, joints and contacts and this object's arrays (the paper's
  /// memory test; the broad phase's tree is not counted).
  std::size_t memoryBytes() const;
  /// Joint points (yellow) and hinge axes (orange), drawn like the particle ragdoll's.
  void drawJoints(DebugDraw& d) const;

 private:
  /// jointAngle with the bodies' poses given (poses of every body: built once per query of all joints).
  Real angleAt(int joint, const std::vector<rigid::SolverBody>& poses) const;

  rigid::World world_;
  std::vector<int> bodies_;  // per bone
  std::vector<int> joints_;  // per desc joint, the world joint
  std::vector<JointDesc> desc_;
};

/// A rigid::JointDesc for a ragdoll joint between the given bodies.
rigid::JointDesc rigidJoint(const JointDesc& j, int bodyA, int bodyB);

}  // namespace pba::ragdoll
