#pragma once
// Coursework 3, a ragdoll down the stairs (docs/course/coursework-3-ragdoll-down-stairs.md): the paper's
// human stands on the top step of a flight of stairs under kinematic control (a scripted stumble: the
// whole figure tips forward about the step's nosing and drifts forward), then control switches to the
// constraint ragdoll (Ragdoll paper §4 on the rigid module: box bodies, ball joints and hinges with the
// human's limits, test scene 8), which tumbles down the stairs until it comes to rest.
// The two tasks are the two ends of the fall: the hand-over, which must start the ragdoll with the
// velocities the controlled figure had (a jump in velocity is a visible jerk at the switch), and the
// detection of rest, which ends the measurement.
#include <vector>

#include "physics/core/result.h"
#include "physics/ragdoll/constraint_ragdoll.h"

namespace pba::coursework {

/// The pose of one bone under kinematic control [SI]: the centre and orientation of its box.
struct BonePose {
  Vec3 center{0.0};              ///< [m] world
  Quat orientation{1, 0, 0, 0};  ///< box → world, unit
};

/// The velocity of one bone [SI].
struct BoneMotion {
  Vec3 velocity{0.0};         ///< [m/s] of the box's centre, world
  Vec3 angularVelocity{0.0};  ///< [rad/s] world
};

// ***** CW3-1: the hand-over velocities of one bone (Ragdoll paper §2 and §4; workbook §6, IK to ragdoll) *****
// Inputs: the bone's pose at the last three frames of kinematic control, `twoBefore` (t − 2h), `before`
// (t − h) and `now` (t), and the frame step h [s] > 0. Return the bone's velocity and angular velocity
// at t (world frame, m/s and rad/s), for the ragdoll to start with.
// (1) The centre: a one-sided difference over the three frames that is exact for a centre moving with
//     constant acceleration (a first-order difference lags by half a step of acceleration, a visible
//     jerk at the switch).
// (2) The orientation: the rotation from one frame to the next is the relative quaternion of the two
//     frames, in world axes. Take the shorter of its two signs (q and −q are the same rotation) and turn
//     it into a rotation vector (axis times angle; the library has the conversion).
// (3) Combine the two per-frame rotation vectors with the weights of step (1)'s difference, so that a
//     steady spin is exact and a spin about a fixed axis with constant angular acceleration is too.
// Check: a bone at rest gets zero; a centre on a parabola and a spin θ(t) = ½ α t² about a fixed axis
// give their exact derivatives at t; a pose whose quaternion changes sign between frames changes
// nothing. For h ≤ 0 return zero.
// *****
BoneMotion handOverMotion(const BonePose& twoBefore, const BonePose& before, const BonePose& now, Real h);

/// The tolerances of rest (Box2D v3's sleep test, b2_linearSleepTolerance, b2_timeToSleep).
struct RestSettings {
  Real linearSpeed = 0.05;   ///< [m/s] every bone's centre slower than this
  Real angularSpeed = 0.25;  ///< [rad/s] every bone turning slower than this
  Real quietTime = 0.5;      ///< [s] for at least this long
};

/// The detector's state.
struct RestDetector {
  RestSettings settings;
  Real quiet = 0.0;     ///< [s] how long every bone has been slow, up to the last update
  bool atRest = false;  ///< quiet for at least settings.quietTime
  Real restTime = 0.0;  ///< [s] when the figure came to rest (the start of the quiet stretch), when atRest
};

// ***** CW3-2: has the figure come to rest? (Box2D v3 island sleep; Lobb notes, resting contact) *****
// Called once after each simulation step of length h [s] that ended at time `time` [s], with every
// bone's motion at that time. A figure is quiet while every bone is slower than both tolerances of the
// settings; it is at rest once it has been quiet for at least `quietTime` without a break.
// (1) Decide whether this step was quiet: check every bone against both tolerances. An empty figure is
//     quiet.
// (2) A quiet step extends the quiet stretch by h; any other step ends the stretch, and a figure that
//     moves again is no longer at rest (the fall was not over).
// (3) When the stretch first reaches `quietTime` (allow for the rounding of a sum of many steps: a
//     billionth of a second), the figure is at rest: record the rest time as the time the stretch began,
//     not when it was noticed.
// Check: a figure whose speed decays as v₀ e^(−t/τ) comes to rest when v₀ e^(−t/τ) falls below the
// tolerance, to within one step, and is declared so `quietTime` later; a bounce in the quiet stretch
// restarts it; a slow spin keeps a still figure moving; h ≤ 0 changes nothing.
// *****
void updateRest(RestDetector& detector, const std::vector<BoneMotion>& bones, Real time, Real h);

/// The scene: stairs, the figure on the top step, its scripted stumble, and the switch.
struct StairsFallDesc {
  int steps = 6;               ///< ≥ 1
  Real rise = 0.18;            ///< [m] height of a step, > 0
  Real run = 0.30;             ///< [m] depth of a step, > 0
  Real width = 2.0;            ///< [m] across the stairs, > 0
  Real figureMass = 75.0;      ///< [kg] > 0, the human's (shared by volume)
  Real figureScale = 1.0;      ///< > 0; 1: 1.83 m tall
  Real tipAcceleration = 3.0;  ///< [rad/s²] ≥ 0, of the forward tip about the nosing while controlled
  Real driftSpeed = 0.4;       ///< [m/s] forward speed of the controlled figure
  Real switchAt = 0.45;        ///< [s] ≥ 0: control passes to the ragdoll at this time
  unsigned seed = 0;           ///< turns the figure by up to ±15° about the vertical (0: square to the stairs)
  Real jointFriction = 30.0;   ///< [N·m] ≥ 0, the largest torque each hinge of the ragdoll resists
  RestSettings rest;
};

struct StairsFall {
  ragdoll::RagdollDesc stairs;      ///< fixed boxes; the stairs descend along +x to the ground y = 0 at x = 0
  ragdoll::RagdollDesc figure;      ///< the human on the top step at t = 0, feet behind the nosing
  Vec3 pivot{0.0};                  ///< [m] on the top step's nosing, under the figure at t = 0
  Vec3 tipAxis{0.0, 0.0, -1.0};     ///< unit, the tip turns +y towards +x
  Real tipAcceleration = 3.0;       ///< [rad/s²]
  Real driftSpeed = 0.4;            ///< [m/s] along +x
  Real switchAt = 0.45;             ///< [s]
  Real jointFriction = 30.0;        ///< [N·m]
  Real time = 0.0;                  ///< [s]
  Real h = 0.0;                     ///< [s] the step of the last frames under control (0 before the first)
  std::vector<BonePose> frames[3];  ///< the figure's poses at t − 2h, t − h, t while controlled
  bool controlled = true;
  Real switchedAt = -1.0;              ///< [s]
  std::vector<BoneMotion> handedOver;  ///< the velocities the ragdoll started with
  ragdoll::ConstraintRagdoll ragdoll;  ///< stairs first, then the figure's bones
  RestDetector rest;
};

/// Builds the scene; errors name the field ("rise: must be positive").
Result<StairsFall> buildStairsFall(const StairsFallDesc& desc);
/// The controlled figure's bone poses at time t [s] (the script: a rigid tip and drift of the t = 0 pose).
std::vector<BonePose> scriptedPose(const StairsFall& scene, Real t);
/// The script's exact bone velocities at time t (for checking the hand-over).
std::vector<BoneMotion> scriptedMotion(const StairsFall& scene, Real t);
/// One step of length h [s]: the script until the switch (then the hand-over through CW3-1), the ragdoll
/// after it, each ragdoll step followed by the rest test (CW3-2).
void stepStairsFall(StairsFall& scene, Real h);
/// The figure's bones' current motion (the script's while controlled, the ragdoll's after).
std::vector<BoneMotion> figureMotion(const StairsFall& scene);
/// The figure's centre of mass [m] (the ragdoll's bodies after the switch).
Vec3 figureCenterOfMass(const StairsFall& scene);

}  // namespace pba::coursework
