#pragma once
// The reference kernels of the particle ragdoll (not exercises: the solver's own route, see exercises.h).
//
// One projection serves every constraint (Müller et al. 2007, "Position Based Dynamics", §3.3, with
// inverse masses): a constraint C(x) whose gradient with respect to particle k is a_k n (one unit
// direction n for all, a scalar a_k each) is removed to first order by
//   Δx_k = −s w_k a_k n,   s = C / Σ_j w_j a_j².
// Limiting cases: all w = 0 (fixed) → nothing moves; one free particle → it takes all of C/a_k.
// A stick is C = |x_b − x_a| − L with a = (−1, +1) along n = (x_b − x_a)/|·|; a joint point or a contact
// point embedded with barycentric weights c_i has a_i = c_i (one side, plus) and −c_i (the other).
//
// Limits are measured as angles here (atan2 about the hinge axis; the angle from the cone axis) and
// clamped; the exercises RAG-2/RAG-3 do the same with the paper's planes.
#include <span>
#include <vector>

#include "physics/core/types.h"

namespace pba::ragdoll {

struct Term {
  int particle = 0;
  Real coefficient = 0.0;  ///< a_k
};

/// The projection above; false when nothing can move (Σ w a² = 0). Inline: every stick, joint point and
/// contact of every relaxation pass goes through it, and the call and the span cost more than the sums.
inline bool projectAlongGradient(std::vector<Vec3>& x, const std::vector<Real>& w, std::span<const Term> terms,
                                 const Vec3& n, Real c) {
  Real denominator = 0.0;
  for (const Term& t : terms) denominator += w[t.particle] * t.coefficient * t.coefficient;
  if (!(denominator > 1e-300)) return false;
  const Real s = c / denominator;
  for (const Term& t : terms) x[t.particle] -= (s * w[t.particle] * t.coefficient) * n;
  return true;
}

/// A hinge of the particle ragdoll seen from bone A: the axis through `origin`, and the direction of
/// angle 0 (unit, ⟂ axis). Angles about the axis by the right-hand rule.
struct HingeFrame {
  Vec3 origin{0.0};          ///< [m] a point of the axis
  Vec3 axis{1.0, 0.0, 0.0};  ///< unit
  Vec3 zero{0.0, 1.0, 0.0};  ///< unit, ⟂ axis
};

/// Angle of p about the hinge axis from `zero`, in (−π, π] (0 when p is on the axis).
Real hingeAngle(const HingeFrame& f, const Vec3& p);
/// The angle `a` measured from the middle of [lower, upper] into (mid − π, mid + π], so that a wedge
/// wider than π is tested without a jump at ±π.
Real unwrapAround(Real a, Real lower, Real upper);
/// p turned about the hinge axis to the angle `target`.
Vec3 atHingeAngle(const HingeFrame& f, const Vec3& p, Real target);
/// Angle of p − apex from the unit axis, in [0, π].
Real angleFromAxis(const Vec3& apex, const Vec3& axis, const Vec3& p);
/// p turned towards (or away from) the axis, about apex, to the angle `target` from it.
Vec3 atAngleFromAxis(const Vec3& apex, const Vec3& axis, const Vec3& p, Real target);
/// A unit vector ⟂ n.
Vec3 anyPerpendicular(const Vec3& n);

}  // namespace pba::ragdoll
