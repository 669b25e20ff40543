#pragma once
// Cubic Hermite curves (CMU asst4, "Splines"): the basis on the unit interval and the evaluation of one
// segment, templated over the value type (Real, Vec3, a colour: anything with + and scalar *).
//
// On u ∈ [0, 1] a segment from p0 to p1 with tangents m0, m1 (d/du, normalised time) is
//   H(u) = h00(u) p0 + h10(u) m0 + h01(u) p1 + h11(u) m1,
// with four cubics in u fixed by H(0) = p0, H(1) = p1, H'(0) = m0, H'(1) = m1 (ANIM-1 works them out).
// Limiting cases: H(0) = p0, H(1) = p1, H'(0) = m0, H'(1) = m1. On a knot interval [t1, t2] of length
// h, u = (t − t1)/h, so the tangents in time units are m/h and d/dt = (1/h) d/du, d²/dt² = (1/h²) d²/du².
#include "physics/core/types.h"

namespace pba::animation {

/// The four Hermite basis functions (or their derivatives) at one parameter value.
struct HermiteBasis {
  Real h00 = 0.0;  ///< weight of the start value p0
  Real h10 = 0.0;  ///< weight of the start tangent m0
  Real h01 = 0.0;  ///< weight of the end value p1
  Real h11 = 0.0;  ///< weight of the end tangent m1
};

/// The basis at u ∈ [0, 1] (derivative 0), or its first (1) or second (2) derivative d/du. Exercise ANIM-1.
HermiteBasis hermiteBasis(Real u, int derivative);

/// d^derivative/du^derivative of the Hermite segment (p0, m0, p1, m1) at u.
template <typename T>
T hermite(const T& p0, const T& m0, const T& p1, const T& m1, Real u, int derivative = 0) {
  const HermiteBasis b = hermiteBasis(u, derivative);
  return b.h00 * p0 + b.h10 * m0 + b.h01 * p1 + b.h11 * m1;
}

}  // namespace pba::animation
