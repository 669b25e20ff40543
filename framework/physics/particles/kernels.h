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

}  // namespace pba::particles
