#pragma once
// The hello lab's physics: one ball under gravity and linear air drag, bouncing on a ground plane,
// or hanging from a damped spring. Chapter 0 of the workbook (docs/workbook/00-getting-started.md).
//
// Equations of motion (Lobb notes, "Particle" and "Damping"):
//   m dv/dt = m g − c v            linear (viscous) air drag, c [N·s/m]
// The ground contact is the particles lab's contact model (particles/collision.h): approach speed at the
// contact time, resting contact below a resting speed, HELLO-2 as the bounce. The spring ball runs on
// chapter 0 alone: its force is HELLO-3, its frame of stable symplectic Euler substeps HELLO-4 and its
// energy HELLO-5.
#include <functional>
#include <optional>
#include <string>

#include "physics/core/result.h"
#include "physics/core/types.h"

namespace pba::hello {

/// Position and velocity of the ball's centre.
struct BallState {
  Vec3 position{0.0, 1.0, 0.0};  ///< [m] world, typical 0–10
  Vec3 velocity{0.0, 0.0, 0.0};  ///< [m/s] world
};

/// What the user edits: the ball, the air and the ground. Defaults give a lively, readable drop.
struct BallDesc {
  Real mass = 1.0;                  ///< [kg], > 0; typical 0.1–10
  Real radius = 0.25;               ///< [m], > 0; typical 0.05–1
  Real restitution = 0.8;           ///< [1] in [0, 1]: share of normal speed kept by a bounce
  Real drag = 0.1;                  ///< [N·s/m] ≥ 0: linear air drag coefficient c
  Real gravity = kStandardGravity;  ///< [m/s²] ≥ 0, acting along −y
  Real dropHeight = 3.0;            ///< [m] ≥ 0: initial height of the ball's lowest point above the ground
  Real groundHeight = 0.0;          ///< [m] world y of the ground plane
  Real restingSpeed = 0.1;  ///< [m/s] ≥ 0: slower impacts are resting contact, not bounces (particles lab's default)
};

/// Checks every field; the message names the field ("mass: must be ...").
Status validate(const BallDesc& desc);

/// Empty when position and velocity are finite; otherwise says which is not (instability guard).
std::optional<std::string> nonFiniteState(const BallState& state);

/// The ball at rest at its drop height.
BallState initialState(const BallDesc& desc);

/// Acceleration from gravity and linear drag at velocity v: a = −g ŷ − (c/m) v.
Vec3 acceleration(const BallDesc& desc, const Vec3& velocity);

/// Kinetic + gravitational potential energy [J], potential measured from the ball resting on the ground.
Real energy(const BallDesc& desc, const BallState& state);

/// Height of the ball's lowest point above the ground [m].
Real heightAboveGround(const BallDesc& desc, const BallState& state);

// ***** HELLO-1: the explicit Euler step (Lobb notes, "ODE view": Euler) *****
// Inputs: the ball's state at time t (position [m], velocity [m/s]), the acceleration a(t) [m/s²] and the
// step h [s]. Output: the state at t + h.
// (1) Explicit Euler takes every derivative at the START of the step: which velocity moves the position,
//     and which acceleration changes the velocity?
// (2) Update both and return the new state. (Using the velocity of the END of the step to move would
//     be symplectic Euler: not this one.)
// Check: with constant a, after n steps your positions equal chapter 0's summed recurrence; they lag the
// exact parabola by an error proportional to h.
// *****
BallState eulerStep(const BallState& state, const Vec3& acceleration, Real h);

/// Outcome of a ground contact test.
struct BounceResult {
  BallState state;       ///< state after the bounce (unchanged when there was no contact)
  bool bounced = false;  ///< true when the ball touched the plane moving into it
};

// ***** HELLO-2: the ground bounce (Lobb notes, "particle/plane collisions") *****
// Inputs: the ball (centre [m], velocity [m/s], radius [m]), the ground plane (a point P of it and its
// unit normal N pointing out of the ground) and the restitution e between 0 and 1. Output: the ball after
// the contact.
// (1) When does the ball touch the plane? Think of the centre's signed height above the plane and the
//     radius.
// (2) When should it bounce at all? Only a ball heading INTO the plane: which sign of which product
//     tells you?
// (3) The ground acts on the velocity's normal part only (no friction here): how much of it comes back,
//     and in which direction? The tangential part is kept.
// (4) Put the ball back on the surface so that it does not stay inside the ground.
// Check: a ball dropped with e = 1 returns to its height; e = 0 stops the normal motion; a ball rolling
// along the ground keeps its speed; a ball leaving the ground is untouched.
// *****
BounceResult bounceOffPlane(const BallState& state, Real radius, Real restitution, const Vec3& planePoint,
                            const Vec3& planeNormal);

/// The ground contact after a flight step of h [s] that ended in `moved`: the particles lab's contact model
/// (particles/collision.h, steps 3–4) decides between an impact and resting contact. An impact bounces
/// through HELLO-2 at the normal speed the ball had at the contact time; resting contact (no faster than
/// restingSpeed + g h) is HELLO-2 with restitution 0, and is not a bounce. Last, a safety net that also
/// holds the ball while HELLO-2 is a stub: the ball never ends below the ground, nor moving into it while
/// touching it. `bounced` is true for real bounces only (an impact that HELLO-2 reflected).
BounceResult groundContact(const BallDesc& desc, const BallState& moved, Real h);

/// One full step of the drop scene: HELLO-1 under gravity and drag, then groundContact().
BounceResult stepDrop(const BallDesc& desc, const BallState& state, Real h);

/// A ball hanging from a damped spring whose anchor the user can drag.
struct SpringDesc {
  Real mass = 1.0;                  ///< [kg] > 0
  Real stiffness = 40.0;            ///< [N/m] > 0, k
  Real restLength = 1.5;            ///< [m] > 0, L
  Real damping = 0.6;               ///< [N·s/m] ≥ 0, c_s along the spring
  Real drag = 0.05;                 ///< [N·s/m] ≥ 0, linear air drag
  Real gravity = kStandardGravity;  ///< [m/s²] ≥ 0
  Vec3 anchor{0.0, 3.5, 0.0};       ///< [m] world position of the fixed end
};

Status validate(const SpringDesc& desc);

// ***** HELLO-3: the forces on the spring ball (Lobb notes, "Damped spring"; Workbook §6.5) *****
// Inputs: the spring and the ball (SpringDesc: anchor [m], stiffness k [N/m], rest length L [m], damping
// along the spring [N·s/m], air drag [N·s/m], mass [kg], gravity [m/s²] along −y) and the ball's state
// (centre [m], velocity [m/s], world frame; the anchor does not move). Output: the total force on the
// ball [N], world frame.
// (1) Find the spring's current length and the unit direction along it. Which way does a stretched
//     spring pull the ball: towards the anchor or away from it? What must happen when the ball sits on
//     the anchor and the direction is undefined?
// (2) The elastic part is proportional to how far the length is from the rest length.
// (3) The spring's damping resists only the rate at which the length changes: which part of the
//     velocity is that? Motion across the spring must not be damped by it.
// (4) Add the weight and the air drag (it opposes the whole velocity).
// Check: at the equilibrium of springEquilibrium() at rest the total force is zero; without spring
// damping the force is minus the gradient of the spring and gravity potentials, minus the drag.
// *****
Vec3 springBallForce(const SpringDesc& desc, const BallState& state);

/// The force on the ball [N, world] at a given state: what stepSpringBall() integrates. The scene passes
/// HELLO-3's springBallForce for its own desc; a test can pass any force it knows in closed form.
using SpringBallForce = std::function<Vec3(const BallState&)>;

/// The largest rate × substep that stepSpringBall() allows [1]: for the angular frequency ω [rad/s] and
/// for the damping rate [1/s] alike. Symplectic Euler is stable on a spring only while ω h < 2 (Workbook
/// §6.6), and its energy wobbles in a band of relative width of order ω h: a fortieth of the limit keeps
/// that band within a few percent, inside the runner's 5 % allowance for a passive scene's energy.
inline constexpr Real kMaxRateTimesSubstep = 0.05;
/// Cap on the substeps of one call [1]: an absurd dt or stiffness costs at most this many force calls.
inline constexpr int kMaxSpringSubsteps = 1000;

// ***** HELLO-4: one frame of the spring ball in stable substeps (Workbook §6.6, HELLO-4) *****
// Inputs: the spring (SpringDesc: stiffness k [N/m], spring damping [N·s/m], air drag [N·s/m], mass
// [kg]), the ball's state at time t (centre [m], velocity [m/s], world frame), the frame's length dt [s]
// and the force on the ball as a function of its state (force(state) [N], world frame). Output: the state
// at t + dt.
// (1) Work out the two rates [1/s] that limit the step: the spring's natural angular frequency for this
//     mass, and how fast damping and drag together would slow the ball.
// (2) Choose the fewest equal substeps such that each rate times the substep stays at or below
//     kMaxRateTimesSubstep: at least one, at most kMaxSpringSubsteps.
// (3) Take the substeps with symplectic Euler (§6.6): the force at the substep's start state gives the
//     acceleration; which of velocity and position changes first, and which velocity then moves the ball?
// (4) Return the state at the end of the frame.
// Check: at the scene's default spring and dt one substep is enough; a spring with ω dt = 3, which one
// symplectic Euler step would make explode, stays on its level modified-energy curve; under a constant
// force the frame's end matches the summed recurrence of its substeps.
// *****
BallState stepSpringBall(const SpringDesc& desc, const BallState& state, Real dt, const SpringBallForce& force);

/// Extension |d| − L [m]: the spring's length minus its rest length.
Real springExtension(const SpringDesc& desc, const BallState& state);

// ***** HELLO-5: the spring ball's energy (Workbook §6.5, §6.6) *****
// Inputs: the spring (SpringDesc) and the ball's state (centre [m], velocity [m/s], world frame). Output:
// the total mechanical energy [J].
// (1) The energy of motion of the ball.
// (2) The energy stored in the spring: it depends only on how far the length is from the rest length,
//     and is the same for a stretch and a compression of the same size (springExtension helps).
// (3) The gravitational energy, measured from the anchor's height (so it is negative below the anchor).
// (4) Their sum. Damping and drag store no energy: they only take it away.
// Check: the energy's gradient with respect to the position is minus the spring and gravity force; on
// an exact undamped oscillation the energy stays constant.
// *****
Real springEnergy(const SpringDesc& desc, const BallState& state);

/// Static equilibrium: the ball hanging straight below the anchor at rest.
BallState springEquilibrium(const SpringDesc& desc);

}  // namespace pba::hello
