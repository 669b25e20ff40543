#pragma once
// The hello lab's physics: one ball under gravity and linear air drag, bouncing on a ground plane,
// or hanging from a damped spring. Chapter 0 of the workbook (docs/workbook/00-getting-started.md).
//
// Equations of motion (Lobb notes, "Particle" and "Damping"):
//   m dv/dt = m g − c v            linear (viscous) air drag, c [N·s/m]
// The ground contact is the particles lab's contact model (particles/collision.h): approach speed at the
// contact time, resting contact below a resting speed, HELLO-2 as the bounce. The spring ball is a
// preview of the particles lab: the damped spring force of PART-4 (springs/spring_network.h) stepped by
// PART-2's symplectic Euler (ode/integrators.h).
#include <optional>
#include <string>

#include "physics/core/result.h"
#include "physics/core/types.h"
#include "physics/ode/ode_system.h"

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

/// Total force on the spring ball: the damped spring of PART-4 (springs::dampedSpringForce, the anchor at
/// rest) + gravity + drag [N].
Vec3 springBallForce(const SpringDesc& desc, const BallState& state);

/// The spring ball as a second-order system (3 coordinates), so that the ODE layer's integrators step it:
/// the scene uses symplectic Euler (PART-2, Lobb's "simple loop"), stable for the spring at the lab's
/// step sizes, unlike explicit Euler.
class SpringBallSystem final : public ode::OwnedStateSystem {
 public:
  explicit SpringBallSystem(const SpringDesc& desc = {}, const BallState& state = {});
  const SpringDesc& desc() const { return desc_; }
  /// Changes the spring or the ball (the scene's sliders, between steps); the state stays.
  void setDesc(const SpringDesc& desc);
  BallState ball() const;
  void setBall(const BallState& state);
  void force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const override;

 private:
  SpringDesc desc_;
};

/// Extension |d| − L [m] and total energy (kinetic + spring + gravity, gravity measured from the anchor) [J].
Real springExtension(const SpringDesc& desc, const BallState& state);
Real springEnergy(const SpringDesc& desc, const BallState& state);

/// Static equilibrium: the ball hanging straight below the anchor at rest.
BallState springEquilibrium(const SpringDesc& desc);

}  // namespace pba::hello
