#pragma once
// The rigid-body world: bodies, joints, contacts and one step (Box2D v3's b2World, in 3-D).
//
// One step of length dt (Box2D v3 "soft step", Catto "Solver2D" 2024):
//   1. broad phase (tree, sweep and prune or brute force) → pairs; narrow phase → manifolds, matched to
//      last step's contacts by feature id so impulses carry over (warm starting);
//   2. islands (bodies linked by touching contacts and joints); islands whose bodies were all slow for
//      timeToSleep go to sleep and are skipped until something touches them;
//   3. prepare contacts and joints once, then per substep h = dt/substeps: integrate velocities
//      (gravity, damping, gyroscopic term), warm start, solve with bias, integrate positions, relax
//      without bias; then restitution;
//   4. continuous collision for fast bodies (moved more than half their smallest extent; every step for
//      `bullet` bodies): time of impact against static bodies by conservative advancement; a body that
//      would pass through is moved back to its first contact (Box2D v3's b2SolveContinuous).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "physics/collision/broad_phase.h"
#include "physics/collision/narrow_phase.h"
#include "physics/collision/raycast.h"
#include "physics/collision/toi.h"
#include "physics/core/debug_draw.h"
#include "physics/rigid/body.h"
#include "physics/rigid/contact_solver.h"
#include "physics/rigid/joint.h"
#include "physics/rigid/settings.h"

namespace pba::rigid {

struct WorldRayHit {
  int body = -1;
  collision::RayHit hit;
};

/// Live measurements of the world (the lab's metrics under "rigid").
struct WorldStats {
  int bodies = 0, dynamicBodies = 0, sleeping = 0;
  int contacts = 0;  ///< contact points in touching manifolds
  int manifolds = 0;
  Real kineticEnergy = 0.0;    ///< [J]
  Real potentialEnergy = 0.0;  ///< [J] −Σ m g·x
  Vec3 momentum{0.0};          ///< [kg·m/s] Σ m v
  Vec3 angularMomentum{0.0};   ///< [kg·m²/s] about the world origin: Σ x × m v + I ω
  Real maxPenetration = 0.0;   ///< [m] deepest contact point at the start of the last step
  Real maxJointError = 0.0;    ///< [m] largest anchor separation of any joint after the last step
  int solverIterations = 0;    ///< velocity iterations per step, relax included
  int ccdHits = 0;             ///< bodies moved back to their time of impact in the last step
};

struct WorldDrawOptions {
  bool shapes = true;
  bool contacts = true;   ///< points (red: touching, grey: speculative) and normals
  bool impulses = false;  ///< normal impulses as arrows (scaled)
  bool aabbTree = false;
  bool frames = false;  ///< body frames
  bool joints = true;   ///< anchors, axes, limits
  bool greySleeping = true;
  Real impulseScale = 0.05;  ///< [m per N·s] arrow length of the impulses
  Real normalLength = 0.15;  ///< [m]
};

class World {
 public:
  explicit World(const WorldSettings& settings = {});

  WorldSettings& settings() { return settings_; }
  const WorldSettings& settings() const { return settings_; }

  /// Adds a body; errors name `field` (see makeBody). Returns the body index.
  Result<int> addBody(const BodyDesc& desc, const std::string& field = "body");
  /// Adds a joint between existing bodies (anchors in world coordinates at their current poses).
  Result<int> addJoint(const JointDesc& desc, const std::string& field = "joint");

  int bodyCount() const { return static_cast<int>(bodies_.size()); }
  const Body& body(int i) const { return bodies_[i]; }
  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<Joint>& joints() const { return joints_; }
  /// A joint's settings, editable between steps (motor speed and torque, limits, spring).
  JointDesc& jointDesc(int joint) { return joints_[joint].desc; }
  const std::vector<ContactConstraint>& contacts() const { return contacts_; }
  /// Sets a body's velocities (wakes the body and its island).
  void setVelocity(int body, const Vec3& linear, const Vec3& angular);
  void wake(int body);

  void step(Real dt);
  Real time() const { return time_; }

  /// First hit of the ray (skips static bodies when dynamicOnly) and every hit in order of distance.
  std::optional<WorldRayHit> rayCast(const Ray& ray, Real maxT, bool dynamicOnly = false) const;
  std::vector<WorldRayHit> rayCastAll(const Ray& ray, Real maxT) const;

  /// Mouse drag: a soft point constraint pulling the body point under `worldPoint` to the target.
  void beginDrag(int body, const Vec3& worldPoint);
  void dragTo(const Vec3& target);
  void endDrag();
  /// Places the dragged body so that its grabbed point sits on the drag target at once, at rest (a
  /// paused world shows the drag; the mouse spring needs steps to pull). Nothing when nothing is dragged.
  void placeDragged();
  int draggedBody() const { return drag_; }

  const collision::BroadPhase& broadPhase() const { return broadPhase_; }
  WorldStats stats() const;
  /// Names the first body or joint whose state is not finite ("body 'box 12' position is NaN").
  std::optional<std::string> nonFiniteState() const;
  void draw(DebugDraw& d, const WorldDrawOptions& options) const;

 private:
  void updateBroadPhase();
  void collide();
  void updateIslandsAndSleep();
  void solve(Real dt);
  void solveContinuous(Real dt);
  void updateSleepTimers(Real dt);
  /// Sizes the solver's copies to the bodies plus the world (last, static); keeps what they hold.
  void fitSolverBodies();
  /// The solver's copy of body i (pose, velocities, inverse mass and world inertia when awake).
  void loadSolverBody(std::size_t i);
  void loadSolverBodies();
  void rebuildBroadPhase();
  bool jointConnected(int a, int b) const;
  void collectJointedPairs();
  bool reuseContacts(int a, int b, std::size_t cursor, const collision::Transform& relative,
                     std::vector<ContactConstraint>& next) const;
  int bodyOfJointSide(int i) const { return i < 0 ? static_cast<int>(bodies_.size()) : i; }

  WorldSettings settings_;
  std::vector<Body> bodies_;
  std::vector<Joint> joints_;
  std::vector<ContactConstraint> contacts_;        // sorted by (bodyA, bodyB, key)
  std::vector<ContactConstraint> nextContacts_;    // the next step's, built by collide() and swapped in
  std::vector<std::pair<int, int>> jointedPairs_;  // collide(): body pairs a joint keeps from colliding
  std::vector<int> activeContacts_;                // solve(): indices into contacts_ of the awake manifolds
  std::vector<SolverContact> solverContacts_;      // solve(): their solver data (first activeContacts_.size())
  std::vector<SolverBody> solverBodies_;           // bodies_ + the world (last)
  std::vector<char> awake_;                        // per body: dynamic and not sleeping this step
  collision::BroadPhase broadPhase_;
  std::vector<std::pair<int, int>> pairs_;
  std::vector<collision::Manifold> pairManifolds_;          // collide(): one pair's manifolds
  collision::NarrowPhaseScratch narrowScratch_;             // collide(): the narrow phase's buffers
  std::vector<collision::Sweep> sweeps_;                    // per body, this step (continuous collision)
  std::vector<Vec3> startVelocity_, startAngularVelocity_;  // per body, at the start of the step
  std::vector<int> islandOf_;                               // per body: union-find root this step (−1: not dynamic)
  std::optional<Joint> mouse_;                              // the drag constraint
  int drag_ = -1;
  Real time_ = 0.0;
  int ccdHits_ = 0;
  Real maxJointError_ = 0.0;
};

}  // namespace pba::rigid
