#pragma once
// The course's rigid-body assessment as one small solver: a cuboid dropped corner-first on the ground,
// with vertex–plane detection and the single-impulse response (Baraff & Witkin 2001, "Rigid Body
// Dynamics II" §8; Mirtich 1996 §3). It is built only from the exercises RIGID-1 (inertia), RIGID-2
// (orientation), RIGID-3 (collision impulse) and RIGID-4 (friction impulse), so the `tumble` scene shows
// the students' own code at work. The general solver is world.h.
//
// One step of length h:
//   1. v += h g;  I_world = R I_body Rᵀ (RIGID-1), inverted;
//   2. each corner below the ground (y < 1 mm) is a contact with normal +y (from the ground toward the box);
//   3. a few sweeps over the contacts: the collision impulse j (RIGID-3, restitution 0 below a resting
//      speed so that a box at rest does not jitter), then the friction impulse (RIGID-4) bounded by μ j;
//   4. the box is lifted out of the ground by the deepest penetration (projection);
//   5. x += h v;  q ← RIGID-2(q, ω, h).
#include <vector>

#include "physics/rigid/exercises.h"

namespace pba::rigid {

struct TumbleBox {
  Vec3 halfExtents{0.4, 0.2, 0.3};  ///< [m]
  Real mass = 1.0;                  ///< [kg]
  Vec3 position{0.0, 1.5, 0.0};     ///< [m] centre of mass
  Quat orientation{1, 0, 0, 0};
  Vec3 velocity{0.0};         ///< [m/s]
  Vec3 angularVelocity{0.0};  ///< [rad/s] world
};

struct TumbleSettings {
  Vec3 gravity{0.0, -kStandardGravity, 0.0};  ///< [m/s²]
  Real restitution = 0.4;
  Real friction = 0.5;
  Real restingSpeed = 0.2;  ///< [m/s] slower impacts get restitution 0
  int sweeps = 8;           ///< passes over the contacts per step
};

struct TumbleContact {
  Vec3 point{0.0};            ///< [m] the corner
  Real depth = 0.0;           ///< [m] below the ground
  Real normalImpulse = 0.0;   ///< [N·s] summed over the sweeps
  Vec3 frictionImpulse{0.0};  ///< [N·s]
};

/// Advances the box by h; `contacts` receives this step's corner contacts.
void tumbleStep(TumbleBox& box, const TumbleSettings& settings, Real h, std::vector<TumbleContact>& contacts);
/// ½ m v² + ½ ω·Iω − m g·x [J], with I from RIGID-1.
Real tumbleEnergy(const TumbleBox& box, const TumbleSettings& settings);

}  // namespace pba::rigid
