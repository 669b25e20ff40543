#pragma once
// The fused particle kernel of the fountain and the benchmark: one pass over the arrays that applies
// gravity and linear drag with symplectic Euler and resolves a ground plane, reading and writing each
// position and velocity exactly once (96 bytes per particle update). It computes what
// ParticleSystem + symplecticEulerStep + collideWithObstacles compute for this force set, without the
// generic path's intermediate force array, so its speed can be compared with memory bandwidth.
#include <span>

#include "physics/core/types.h"
#include "physics/particles/collision.h"

namespace pba::particles {

struct FusedStepDesc {
  Vec3 gravity{0.0, -kStandardGravity, 0.0};  ///< [m/s²]
  Real dragRate = 0.0;                        ///< c/m [1/s]: linear drag per unit mass, same for all
  PlaneObstacle ground;
  ContactMaterial material;
  Real radius = 0.0;                          ///< [m] particle radius
};

/// v ← v + h (g − (c/m) v); x ← x + h v; then the plane contact of collision.h (projection + response).
void stepGravityDragPlane(std::span<Vec3> x, std::span<Vec3> v, const FusedStepDesc& desc, Real h);

/// The fountain's bulk update (issue 4: up to 10⁶ particles), fused like stepGravityDragPlane: gravity,
/// linear drag towards a wind that is uniform in space (the generic path's gusts travel in space; here
/// the gust is taken at the nozzle, so it varies in time only), a vortex about a vertical axis, then the
/// contact model of collision.h against every plane and sphere — one pass, each x and v read and written
/// once. Symplectic Euler, all particles of equal mass (an emitter's):
///   v ← v + h (g − (c/m)(v − w) + S (ŷ × r⊥)/(|r⊥|² + r_c²));  x ← x + h v;  then contacts.
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
  Real radius = 0.0;                          ///< [m] particle radius
};
/// Returns the number of contacts resolved.
std::size_t stepFountain(std::span<Vec3> x, std::span<Vec3> v, const FusedFountainDesc& desc, Real h);

}  // namespace pba::particles
