#pragma once
// Particle collisions with static obstacles (planes, spheres, boxes), after the Lobb notes'
// "particle–plane collision": split v = v_n + v_t with v_n = (N·v) N, reflect v_n' = −r v_n, and treat
// slow contacts as resting contact.
//
// Our contact model, step by step (applied after each integrator step):
//   1. Signed distance φ of the particle's surface to the obstacle and the outward normal N.
//   2. Position projection: if φ < 0 move the particle out by −φ along N. The notes back the step up to
//      the contact time; projecting is the cheap, robust alternative (Jakobsen 2001; also what the
//      Ragdoll paper's "projection" does) and it guarantees that nothing ends below a surface.
//   3. Approach speed at the contact time. A particle found a depth d below the surface fell that far
//      past the contact under the uniform acceleration a (gravity): its normal speed then was
//      s_c = √(s² − 2 a_n d), a_n = −N·a > 0 the inward part of a (constant-acceleration kinematics).
//      This is the notes' "back the step up to the contact time" for the velocity; without it the
//      projection keeps the speed gained below the surface, and the methods that are exact under
//      gravity (velocity Verlet, RK4, ...) return each impact ≈ e·s + g·h: a micro-bounce forever.
//   4. Resting contact (Lobb notes §2): s_c ≤ restingSpeed + a_n h — no faster than one step of the
//      acceleration explains — is contact, not an impact: restitution 0 (no jitter).
//   5. Velocity response (PART-5) when the particle touches (φ < slop) and moves inward (v_n < 0):
//      restitution on the normal part (of the contact-time speed s_c for an impact) and Coulomb
//      friction on the tangential part, as an impulse bounded by μ times the normal impulse (the full
//      inward speed s for a resting contact, which is g·h per step under gravity).
//   6. Safety net: a touching particle still moving inward after step 5 loses that inward speed. A correct
//      PART-5 never leaves one (the net is then a no-op); it keeps the scenes sane while PART-5 is a stub,
//      and every use is counted (heldBySafetyNet), so that no test can pass because of it unnoticed.
// resolveContact() below is this model for one particle and one surface: collideWithObstacles, the fused
// kernels (kernels.h) and, for steps 3–4, the hello lab's ground (hello/ball.h) all use it.
// Why the impulse form is Coulomb's law: over a step the normal impulse per unit mass is Δv_n; Coulomb
// bounds the tangential impulse by μ Δv_n. Resting on a plane under gravity Δv_n = g h each step, so
// kinetic friction decelerates by exactly μ_k g, and a particle on a slope of angle θ sticks when
// tan θ ≤ μ_s — the closed forms the tests check.
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "physics/core/result.h"
#include "physics/core/types.h"
#include "physics/particles/particles.h"

namespace pba::particles {

struct ContactMaterial {
  Real restitution = 0.5;      ///< r in [0, 1]: share of the normal speed a bounce keeps
  Real staticFriction = 0.6;   ///< μ_s ≥ 0: sticks while |v_t| ≤ μ_s Δv_n
  Real kineticFriction = 0.4;  ///< μ_k ≥ 0, typically ≤ μ_s: sliding loses μ_k Δv_n of tangential speed
  Real restingSpeed = 0.1;     ///< [m/s] ≥ 0: impacts slower than this do not bounce (resting contact)
};
/// Restitution in [0, 1], frictions and resting speed ≥ 0, all finite; the message names the field.
Status validate(const ContactMaterial& material);

/// Distance below which a particle moving inward counts as touching [m].
inline constexpr Real kContactSlop = 1e-6;

struct PlaneObstacle {
  Vec3 point{0.0};             ///< [m] any point of the plane
  Vec3 normal{0.0, 1.0, 0.0};  ///< unit, pointing to the free side
};
struct SphereObstacle {
  Vec3 center{0.0};   ///< [m]
  Real radius = 1.0;  ///< [m] > 0
};
struct BoxObstacle {
  Vec3 center{0.0};       ///< [m]
  Vec3 halfExtents{0.5};  ///< [m] > 0
  Quat orientation{1.0, 0.0, 0.0, 0.0};
};

struct Obstacles {
  std::vector<PlaneObstacle> planes;
  std::vector<SphereObstacle> spheres;
  std::vector<BoxObstacle> boxes;
  ContactMaterial material;
};
/// Finite geometry, unit plane normals, positive radii and half extents, a valid material.
Status validate(const Obstacles& obstacles);

/// Signed distance from point x to the surface (negative inside) and the outward normal there.
struct SurfacePoint {
  Real distance = 0.0;  ///< [m]
  Vec3 normal{0.0, 1.0, 0.0};
};
SurfacePoint closestSurface(const PlaneObstacle& o, const Vec3& x);
SurfacePoint closestSurface(const SphereObstacle& o, const Vec3& x);
SurfacePoint closestSurface(const BoxObstacle& o, const Vec3& x);

// ***** PART-5: contact velocity with restitution and Coulomb friction (Lobb notes, collisions) *****
// Given the velocity v [m/s] of a particle touching a surface with outward unit normal N (world axes),
// return the velocity after the contact. `material` holds the restitution e, the resting speed below
// which an impact must not bounce [m/s], and the static and kinetic friction coefficients.
// (1) Decompose v into its part along N and its part in the surface. Decide when the contact has
//     nothing to do (which way is the particle heading?).
// (2) The normal part: how much of the approach speed comes back, and when must none come back (a slow
//     impact is resting contact)? The change of normal velocity is the contact's impulse per unit mass.
// (3) The tangential part: Coulomb friction is an impulse per unit mass bounded by the friction
//     coefficients times that normal change. When the bound can stop the sliding (static coefficient),
//     the particle sticks; otherwise the kinetic bound takes speed off along the sliding direction.
// Check: a leaving particle is untouched; a resting contact leaves no normal speed; friction never
// reverses the sliding direction nor adds speed; with no friction the tangential part is unchanged.
// *****
Vec3 contactVelocity(const Vec3& v, const Vec3& normal, const ContactMaterial& material);

/// What the contact model knows of the step that brought the particles here (steps 3–4 above).
/// The default (no acceleration, dt 0) turns both steps off: plain projection + PART-5.
struct ContactStep {
  Vec3 acceleration{0.0};  ///< [m/s²] uniform acceleration of the free particles (gravity)
  Real dt = 0.0;           ///< [s] the integrator step just taken
};

/// Steps 3–4: what a touching particle moving inward makes of its contact.
enum class ContactKind {
  None,     ///< not touching, or leaving the surface: only the projection applies
  Resting,  ///< no faster than the acceleration explains: restitution 0
  Impact,   ///< a bounce: restitution applies to the contact-time speed
};
struct ContactApproach {
  ContactKind kind = ContactKind::None;
  Real contactSpeed = 0.0;  ///< [m/s] > 0 for an impact: the inward normal speed at the contact time s_c
};
/// Steps 3–4 for a particle found `depth` ≥ 0 [m] below the surface, moving inward at `inwardSpeed` > 0
/// [m/s] at the end of a step of `dt` [s] under the inward acceleration `inwardAcceleration` = max(0, −N·a)
/// [m/s²]: s_c = √(s² − 2 a_n d); resting when s_c ≤ restingSpeed + a_n dt, else an impact at s_c. (The
/// test compares squares, so that resting contact, a third of a settled fountain, needs no square root.)
inline ContactApproach classifyApproach(Real depth, Real inwardSpeed, Real inwardAcceleration, Real restingSpeed,
                                        Real dt) {
  const Real contactSpeed2 = std::max(0.0, inwardSpeed * inwardSpeed - 2.0 * inwardAcceleration * depth);
  const Real threshold = restingSpeed + inwardAcceleration * dt;
  if (contactSpeed2 <= threshold * threshold) return {ContactKind::Resting, 0.0};
  return {ContactKind::Impact, std::sqrt(contactSpeed2)};
}

/// What resolveContact did to one particle.
struct ContactResult {
  ContactKind kind = ContactKind::None;
  Real depth = 0.0;              ///< [m] ≥ 0, the projection distance
  bool heldBySafetyNet = false;  ///< step 6 had to remove an inward speed that step 5 left
};
/// Inward normal speed [m/s] below which step 6 counts as rounding, not as a use of the safety net.
inline constexpr Real kSafetyNetSpeed = 1e-9;

/// Steps 2–6 of the contact model for one particle (position x, velocity v) and one surface, given the
/// signed distance φ [m] of the particle's surface (centre distance − radius) and the outward unit normal.
/// Nothing happens when φ ≥ kContactSlop.
inline ContactResult resolveContact(Vec3& x, Vec3& v, const Vec3& normal, Real phi, const ContactMaterial& m,
                                    const ContactStep& step) {
  ContactResult result;
  if (phi >= kContactSlop) return result;
  if (phi < 0.0) {
    result.depth = -phi;
    x += result.depth * normal;
  }
  const Real vn = glm::dot(v, normal);
  if (vn >= 0.0) return result;
  const Real inwardAcceleration = std::max(0.0, -glm::dot(step.acceleration, normal));
  const ContactApproach approach = classifyApproach(result.depth, -vn, inwardAcceleration, m.restingSpeed, step.dt);
  result.kind = approach.kind;
  if (approach.kind == ContactKind::Resting) {
    ContactMaterial resting = m;
    resting.restitution = 0.0;
    v = contactVelocity(v, normal, resting);
  } else {
    v += (-vn - approach.contactSpeed) * normal;  // the normal speed it had at the contact time
    v = contactVelocity(v, normal, m);
  }
  const Real vnAfter = glm::dot(v, normal);
  if (vnAfter < 0.0) {
    v -= vnAfter * normal;
    result.heldBySafetyNet = vnAfter < -kSafetyNetSpeed;
  }
  return result;
}

struct CollisionStats {
  std::size_t contacts = 0;         ///< particle–obstacle contacts this call (resting and impacts)
  std::size_t impacts = 0;          ///< of which bounces (ContactKind::Impact)
  std::size_t heldBySafetyNet = 0;  ///< contacts that step 6 had to correct (0 for a correct PART-5)
  Real deepestPenetration = 0.0;    ///< [m] before projection
};
/// Steps 1–6 of the contact model for every free particle of radius `radius` [m] against every obstacle.
CollisionStats collideWithObstacles(Particles& p, const Obstacles& obstacles, Real radius,
                                    const ContactStep& step = {});

}  // namespace pba::particles
