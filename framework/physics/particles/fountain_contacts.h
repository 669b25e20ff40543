#pragma once
// The contact pass of the fountain's pool step (kernels.h, stepFountain's pass 2): the contact model of
// collision.h (resolveContact, and through it PART-5's contactVelocity) for the particles of a block that
// the motion pass flagged as within reach of an obstacle, planes first, then spheres, as
// collideWithObstacles orders them. Two routes with the same results, to the bit:
//   - resolveFountainContactsScalar: one particle and one obstacle at a time through resolveContact;
//   - resolveFountainContactsFast: PART-5's fast path (docs/architecture.md §5, "Fast paths";
//     fountain_contacts_fast_path.cpp), two flagged particles at a time in the lanes of core/lanes.h.
//     In the hand-out it runs the scalar route over the student's contactVelocity.
#include <cstddef>
#include <cstdint>
#include <span>

#include "physics/core/types.h"
#include "physics/particles/collision.h"

namespace pba::particles {

/// A plane as the fountain kernel tests it.
struct PlaneReach {
  Vec3 normal;  ///< unit, to the free side
  Real offset;  ///< [m] n·p + particle radius: contact when n·x − offset < kContactSlop
};
/// A sphere as the fountain kernel tests it.
struct SphereReach {
  Vec3 center;   ///< [m]
  Real surface;  ///< [m] sphere radius + particle radius
  Real reach2;   ///< [m²] (surface + kContactSlop)²: nothing to do when |x − c|² ≥ reach2
};

/// The obstacles, their material and the step that brought the particles there.
struct FountainObstacles {
  std::span<const PlaneReach> planes;
  std::span<const SphereReach> spheres;
  ContactMaterial material;
  ContactStep step;  ///< gravity and h (collision.h, steps 3–4)
};

struct FountainContactCounts {
  std::size_t contacts = 0;         ///< resting contacts and impacts resolved
  std::size_t heldBySafetyNet = 0;  ///< of which the contact model's safety net corrected
};

/// The contact model for particles x[k], v[k], k in `flagged` (distinct indices), against every obstacle.
/// A flagged particle that touches nothing is left alone, so flagging too many changes nothing.
FountainContactCounts resolveFountainContactsScalar(std::span<Vec3> x, std::span<Vec3> v,
                                                    std::span<const std::uint32_t> flagged,
                                                    const FountainObstacles& obstacles);
/// The same, bit for bit, two flagged particles at a time (PART-5's fast path).
FountainContactCounts resolveFountainContactsFast(std::span<Vec3> x, std::span<Vec3> v,
                                                  std::span<const std::uint32_t> flagged,
                                                  const FountainObstacles& obstacles);

}  // namespace pba::particles
