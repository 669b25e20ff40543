#pragma once
// Time of impact by conservative advancement (Mirtich, "Impulse-based Dynamic Simulation of Rigid Body
// Systems", PhD thesis 1996, §2.3; Catto, "Continuous Collision", GDC 2013): step the sweep forward by
// the current distance divided by a bound on how fast any two surface points can approach, which can
// never step past the first contact.
#include "physics/collision/shapes.h"

namespace pba::collision {

/// A body's motion over one step: pose at t = 0 and t = 1 (the rotation is interpolated by nlerp).
struct Sweep {
  Vec3 c0{0.0}, c1{0.0};
  Quat q0{1, 0, 0, 0}, q1{1, 0, 0, 0};
  Transform at(Real t) const;
};

struct ToiResult {
  enum class State { Separated, Hit, Overlapping, Failed };
  State state = State::Separated;
  Real t = 1.0;  ///< fraction of the step at the hit
  int iterations = 0;
};

/// b may be a plane (a must be convex). First t ∈ [0, 1] at which the surfaces of a and b come within `target` [m] (with tolerance
/// `tolerance` [m]). Overlapping: already within target at t = 0.
ToiResult timeOfImpact(const Shape& a, const Sweep& sa, const Shape& b, const Sweep& sb, Real target, Real tolerance);

}  // namespace pba::collision
