#pragma once
// The fused particle kernels of the fountain and the benchmark: one pass over the arrays that applies
// gravity and linear drag with velocity Verlet and resolves the obstacles with the library's contact
// model (collision.h, resolveContact: projection, contact-time speed, resting contact, PART-5's
// response), reading and writing each position and velocity exactly once (96 bytes per particle update).
// They compute what ParticleSystem + ode::velocityVerletStep + collideWithObstacles (with ContactStep
// {gravity, h}) compute for this force set, without the generic path's intermediate force arrays, so
// their speed can be compared with memory bandwidth.
//
// Velocity Verlet with a velocity-dependent force a(x, v) (Swope et al. 1982; the force sees the
// half-step velocity, as in ode::velocityVerletStep):
//   v½ = v + (h/2) a(x, v),   x' = x + h v½   (= x + h v + h²a/2),   v' = v½ + (h/2) a(x', v½).
// For a = G − k v + s(x) (G constant, k = c/m, s the vortex swirl) both half kicks read
//   v ← (1 − hk/2) v + (h/2) (G + s(x)),
// a form with one multiply-add per component and the swirl's one division per evaluation.
#include <span>

#include "physics/core/types.h"
#include "physics/particles/collision.h"
#include "physics/particles/particles.h"

namespace pba::particles {

struct FusedStepDesc {
  Vec3 gravity{0.0, -kStandardGravity, 0.0};  ///< [m/s²]
  Real dragRate = 0.0;                        ///< c/m [1/s]: linear drag per unit mass, same for all
  PlaneObstacle ground;
  ContactMaterial material;
  Real radius = 0.0;  ///< [m] particle radius
};

/// Velocity Verlet under a = g − (c/m) v, then the contact model of collision.h against the plane.
void stepGravityDragPlane(std::span<Vec3> x, std::span<Vec3> v, const FusedStepDesc& desc, Real h);

/// The fountain's bulk update (issue 4: up to 10⁶ particles), fused like stepGravityDragPlane: gravity,
/// linear drag towards a wind that is uniform in space (the generic path's gusts travel in space; here
/// the gust is taken at the nozzle, so it varies in time only), a vortex about a vertical axis, then the
/// contact model of collision.h against every plane and sphere (any number of each). Velocity Verlet, all
/// particles of equal mass (an emitter's), with
///   a(x, v) = g − (c/m)(v − w) + S (ŷ × r⊥)/(|r⊥|² + r_c²).
struct FusedFountainDesc {
  Vec3 gravity{0.0, -kStandardGravity, 0.0};  ///< [m/s²]
  Real dragRate = 0.0;                        ///< c/m [1/s]
  Vec3 wind{0.0};                             ///< [m/s] uniform wind velocity this step
  Vec3 vortexCenter{0.0};                     ///< [m] a point of the vortex's vertical axis
  Real vortexStrength = 0.0;                  ///< S [m²/s²]; 0 = no vortex
  Real vortexCore = 0.5;                      ///< r_c [m] > 0
  std::span<const PlaneObstacle> planes;
  std::span<const SphereObstacle> spheres;
  ContactMaterial material;
  Real radius = 0.0;  ///< [m] particle radius
};

/// What one stepFountain() call found, gathered on the way (no extra pass over the pool).
struct FountainStepStats {
  std::size_t contacts = 0;         ///< particle–obstacle contacts resolved
  std::size_t heldBySafetyNet = 0;  ///< contacts the contact model's safety net corrected (0 for a correct PART-5)
  std::size_t expired = 0;          ///< particles removed because age ≥ lifetime
  bool nonFinite = false;           ///< some survivor's x or v is NaN or ±∞ (describeNonFinite() names it)
  Real kineticPerMass = 0.0;        ///< Σ ½|v|² over the survivors after the step [J/kg]
  Real potentialPerMass = 0.0;      ///< Σ −g·x over the survivors after the step [J/kg] (zero at the origin)
};

/// One step of an emitter's pool in one sweep over its arrays (the whole step of the fountain at 10⁶):
///   1. age ← age + h; a particle whose age reaches its lifetime is removed. Removal is a stable
///      compaction (survivors slide down, keeping their order), so a pool filled by an emitter stays
///      sorted by birth and a strided subsample spans every age.
///   2. The survivors move as described for FusedFountainDesc, then meet the obstacles. The sweep goes
///      in blocks of 256: first the motion of the whole block with no branch on the particles' data,
///      flagging those within reach of an obstacle, then the contact model for the flagged ones while
///      the block is still in cache (a resting pool touches the ground often, and branches on the data
///      inside the motion loop would keep it from running straight through). The contact pass is
///      PART-5's fast path (fountain_contacts.h); in the hand-out it runs the student's contactVelocity.
///   3. The energy sums are accumulated over the block; they double as the instability guard's
///      finiteness test (a NaN or ±∞ in any x or v makes them non-finite), so the guard needs no pass of
///      its own: call describeNonFinite() only when nonFinite is set, to name the particle.
/// Colours are not touched (evaluate colorOverLife() of emitter.h for the particles you draw) and
/// nothing is spawned (Emitter::spawn). Same result, to rounding, as Emitter::update's ageing and removal
/// followed by ParticleSystem + ode::velocityVerletStep + collideWithObstacles with ContactStep{g, h}
/// (uniform wind), except for the order of the survivors.
FountainStepStats stepFountain(Particles& p, const FusedFountainDesc& desc, Real h);

}  // namespace pba::particles
