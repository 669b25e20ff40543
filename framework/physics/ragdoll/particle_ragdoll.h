#pragma once
// The particle ragdoll (Ragdoll paper §3, after Jakobsen 2001, "Advanced Character Physics").
//
// State: particles with position x, the previous position x_old and inverse mass w (0: fixed), four
// per bone (tetrahedron.h: mass and inertia of the box). One step of length h:
//   1. position Verlet: x ← x + (x − x_old) + g h², x_old ← old x (velocity is implicit, so every
//      later correction of x is also a correction of the velocity);
//   2. broad phase: bone boxes (fitted frames) as AABBs fattened by this step's travel, sweep and prune
//      on x; jointed pairs and pairs of fixed bones are skipped (the paper tested every unjointed pair
//      in every iteration, a cost quadratic in the bones; docs/performance-ragdoll.md);
//   3. `iterations` times, in this order: the six sticks of every bone (relaxation) and, when asked,
//      each bone's least volume (a departure, ParticleSettings::minVolumeShare), the joints, the
//      joint limits, then the contacts with the ground and between the paired bones (projection), so
//      that a step ends out of the ground (sticks last instead left 1.1 cm penetration and 1.7 cm joint gaps);
//   4. friction: each particle of a bone that touched something gets its old position moved towards
//      its current one by `friction` of its tangential step (paper §3.3.2).
//
// Joints. The paper joins bones by sharing particles (1 shared particle: ball, 2: hinge). A bone whose
// particles carry the box's inertia cannot have particles at its joints, so here a joint point is
// embedded in both tetrahedra by barycentric coordinates (tetrahedron.h) and the two copies are held
// together by a zero-length stick between embedded points: the paper's alternative of zero-length sticks,
// which keeps per-particle masses and allows severing limbs. A ball holds one point, a hinge two points
// on its axis. Limits: a reference point of B, turned back onto the limit (hinge: its half-plane, ball:
// the cone) while bone A is pushed the other way at the same point (the paper's "Newton's third law").
//
// The sticks, limits and contacts are the exercises RAG-1..4 (exercises.h), which every step calls; the
// joint points and the mouse are one projection of a constraint along its gradient (kernels.h, PBD form).
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "physics/collision/ray.h"
#include "physics/collision/shapes.h"
#include "physics/collision/transform.h"
#include "physics/core/debug_draw.h"
#include "physics/ragdoll/contact_fast_path.h"
#include "physics/ragdoll/kernels.h"
#include "physics/ragdoll/ragdoll_desc.h"
#include "physics/ragdoll/stick_fast_path.h"
#include "physics/ragdoll/tetrahedron.h"

namespace pba::ragdoll {

struct ParticleSettings {
  Vec3 gravity{0.0, -kStandardGravity, 0.0};  ///< [m/s²]
  int iterations = 20;                        ///< relaxation + projection passes per step (paper test 3: 2, 5, 20)
  /// Sweeps over the sticks in each pass (Jakobsen: 1). More sweeps keep the bones' shape while joints
  /// pull on them (the ragdoll tests check the bones within 1 % of their shape).
  int stickSweeps = 3;
  /// Share [0, 1] of a contacting particle's tangential step removed each step (the paper moves the old
  /// position towards the current one by a fixed fraction). Typical 0.5.
  Real friction = 0.5;
  Real groundHeight = 0.0;  ///< [m] the ground plane y = groundHeight
  bool ground = true;
  bool boneCollisions = true;  ///< bone–bone boxes (unjointed pairs)
  bool broadPhase = true;      ///< off: every unjointed pair, as the paper did
  /// Smallest share of its rest volume a bone's tetrahedron keeps, in every pass after the sticks
  /// (kernels.h, keepMinimumVolume); 0: off, as in the paper, whose sticks let a thin bone struck hard
  /// turn inside out and stay so. A named departure, on for ragdolls from skeleton files
  /// (skeletonParticleSettings()). Typical 0.5.
  Real minVolumeShare = 0.0;
  /// Removed share of each step's motion per second [1/s] (x − x_old scaled by 1 − damping·h). 0 in
  /// the paper; a small value lets a figure settle (named departure, off by default).
  Real damping = 0.0;
};

struct ParticleStats {
  int bones = 0, particles = 0, constraints = 0;  ///< constraints: sticks + joint points + limits
  int contacts = 0;                               ///< contacts resolved in the last step's final pass
  int pairs = 0;                                  ///< bone pairs from the broad phase in the last step
  Real kineticEnergy = 0.0;                       ///< [J] Σ ½ m |(x − x_old)/h|²
  Real potentialEnergy = 0.0;                     ///< [J] −Σ m g·x
  Real maxJointError = 0.0;                       ///< [m] largest gap between the two copies of a joint point
  Real maxLimitViolation = 0.0;                   ///< [rad] largest angle beyond a limit
  Real maxPenetration = 0.0;                      ///< [m] deepest box corner below the ground
  Real maxStickStrain = 0.0;  ///< largest |length − rest| / rest of a stick at the end of the step
  /// The same right after the last relaxation pass (before that pass's joints, limits and contacts).
  Real maxStickStrainAfterRelaxation = 0.0;
};

struct ParticleDrawOptions {
  bool boxes = true;
  bool particles = false;  ///< particles and sticks
  bool joints = true;      ///< joint points, hinge axes, limit planes and cones
  bool contacts = false;
};

/// The settings for ragdolls from skeleton files (skeleton_ragdoll.h): minVolumeShare 0.5. Their long thin
/// bones make flat tetrahedra; without it, limbs of every BVH figure turned inside out on landing
/// (tests/labs/ragdoll_bvh_rest_test.cpp).
ParticleSettings skeletonParticleSettings();

class ParticleRagdoll {
 public:
  ParticleRagdoll() = default;
  /// Errors as validate(desc).
  static Result<ParticleRagdoll> build(const RagdollDesc& desc, const ParticleSettings& settings = {});

  ParticleSettings& settings() { return settings_; }
  const ParticleSettings& settings() const { return settings_; }
  void step(Real dt);

  int boneCount() const { return static_cast<int>(bones_.size()); }
  int particleCount() const { return static_cast<int>(x_.size()); }
  const std::vector<Vec3>& positions() const { return x_; }
  const std::vector<Vec3>& previousPositions() const { return xOld_; }
  /// The bone's box pose fitted to its tetrahedron.
  collision::Transform boneFrame(int bone) const;
  Vec3 halfExtents(int bone) const { return bones_[bone].halfExtents; }
  Real boneMass(int bone) const { return bones_[bone].mass; }
  bool isFixed(int bone) const { return bones_[bone].fixed; }
  /// Angle of hinge or cone joint j [rad]: the hinge angle of B about the axis, or the angle of B's
  /// axis from the cone axis (0 for a ball without limit).
  Real jointAngle(int joint) const;
  ParticleStats stats() const;
  /// Bytes held by the ragdoll's arrays (the paper's memory test).
  std::size_t memoryBytes() const;
  std::optional<std::string> nonFiniteState() const;
  void draw(DebugDraw& d, const ParticleDrawOptions& options, const Color& color) const;

  /// The first bone the ray hits, and where.
  std::optional<std::pair<int, Real>> rayCast(const Ray& ray, Real maxT) const;
  /// Mouse drag: the bone point under `worldPoint` is pulled to the target in every iteration.
  void beginDrag(int bone, const Vec3& worldPoint);
  void dragTo(const Vec3& target) { dragTarget_ = target; }
  void endDrag() { dragBone_ = -1; }
  /// Moves the dragged bone at once (paused scenes) so its grabbed point is on the target, at rest.
  void placeDragged();
  int draggedBone() const { return dragBone_; }

 private:
  struct Bone {
    int first = 0;  // its particles are first .. first + 3
    Vec3 halfExtents{0.1};
    Real mass = 1.0;
    bool fixed = false;
    std::array<Vec3, 4> rest{};  // particle offsets in the box frame
    Mat3 restInverse{1.0};
    Real restSixVolume = 0.0;          // [m³] sixVolume(rest), negative (kernels.h)
    std::array<Weights, 8> corners{};  // barycentric weights of the box corners
    // The same by particle (cornerWeights[k][i] = corners[i][k]): the ground test sums them corner by
    // corner in packed pairs.
    std::array<std::array<Real, 8>, 4> cornerWeights{};
    collision::Shape shape;  // the box, for the narrow phase
  };
  // A stick is RAG-1's input (stick_fast_path.h).
  using Stick = ragdoll::Stick;
  struct PointPair {  // one joint point, embedded in both bones
    Weights inA{}, inB{};
  };
  struct Joint {
    JointKind kind = JointKind::Ball;
    int a = 0, b = 0;
    std::vector<PointPair> points;  // ball 1, hinge 2 (on the axis)
    bool limited = false;
    Real lower = 0.0, upper = 0.0, cone = 0.0;
    Weights origin{}, axisEnd{}, zero{};  // in A: the joint, a point along the axis, the hinge's angle 0
    Weights reference{};                  // in B: the reference point (hinge: at angle 0; ball: on B's axis)
  };
  struct Contact {  // for drawing
    Vec3 point{0.0}, normal{0.0};
  };

  std::array<Vec3, 4> particlesOf(int bone) const {
    const int f = bones_[bone].first;
    return {x_[f], x_[f + 1], x_[f + 2], x_[f + 3]};
  }
  Vec3 pointOf(int bone, const Weights& c) const { return embedded(particlesOf(bone), c); }
  Weights weightsOf(int bone, const Vec3& worldPoint) const { return barycentric(particlesOf(bone), worldPoint); }
  void integrate(Real dt);
  void findPairs(Real dt);
  void relax();
  void keepVolumes();
  void solveJoints();
  void solveLimits();
  void solveContacts(bool record);
  void solveGround(bool record);
  /// Whether the bone is below the ground; if so its contact goes to groundContacts_ (and, when
  /// `record`, to contacts_).
  bool groundContact(int bone, bool record);
  void solveBonePair(int a, int b, bool record);
  void solveDrag();
  /// Moves bone B's point (weights inB) by +Δ and bone A's (weights inA) by −Δ, shared by their
  /// inverse masses (the generic projection of kernels.h).
  void pushApart(int a, const Weights& inA, int b, const Weights& inB, const Vec3& delta);
  void applyFriction();
  /// The statistics of the current state with step length dt (computed when asked: nothing in the
  /// step reads them).
  ParticleStats measure(Real dt) const;
  Real stickStrain() const;
  /// The hinge frame of joint j seen from bone A and B's reference point.
  std::pair<HingeFrame, Vec3> hingeMeasure(const Joint& j) const;

  ParticleSettings settings_;
  std::vector<Vec3> x_, xOld_;
  std::vector<Real> w_, m_;
  std::vector<Vec3> startVelocity_;  // applied at the first step (needs h)
  bool started_ = false;
  std::vector<Bone> bones_;
  std::vector<Stick> sticks_;
  std::vector<Joint> joints_;
  std::vector<std::pair<int, int>> pairs_;
  std::vector<std::vector<int>> jointedWith_;
  std::vector<char> touched_;      // per bone, this step
  std::vector<Vec3> touchNormal_;  // per bone, the last contact normal of this step
  std::vector<Contact> contacts_;
  std::vector<GroundContact> groundContacts_;  // this round's pushes out of the ground (RAG-4's fast path)
  std::vector<int> groundBones_;               // their bones
  int dragBone_ = -1;
  Weights dragWeights_{};
  Vec3 dragTarget_{0.0};
  Real lastDt_ = 1.0 / 60.0;
  Real strainAfterRelaxation_ = 0.0;
};

}  // namespace pba::ragdoll
