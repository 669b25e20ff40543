// Exercise ANIM-1: the Hermite basis and its derivatives (CMU asst4, "Splines").
#include "physics/animation/hermite.h"

#include "physics/exercises/not_implemented.h"

namespace pba::animation {

// ***** ANIM-1: the Hermite basis and its derivatives (CMU asst4, "Splines") *****
// Input: u in [0, 1] and a derivative order. Output: the four weights h00, h10, h01, h11 (hermite.h) of
// p0, m0, p1, m1, or their derivatives with respect to u.
// (1) derivative 0: each weight is a cubic in u. Work out the four cubics from the conditions of
//     hermite.h: at u = 0 and u = 1 the curve and its slope must come out as p0, p1, m0, m1 (four
//     conditions per weight, four coefficients).
// (2) derivative 1 and 2: differentiate each cubic with respect to u.
// (3) Any other derivative order: every weight is 0 (the third is not used by the library).
// Check: with p0 = p1 = 1 and m0 = m1 = 0 the curve is 1 for every u; finite
// differences of derivative 0 match derivative 1.
// *****
HermiteBasis hermiteBasis(Real u, int derivative) {
  // BEGIN SOLUTION
  const Real u2 = u * u;
  const Real u3 = u2 * u;
  switch (derivative) {
    case 0:
      return {2.0 * u3 - 3.0 * u2 + 1.0, u3 - 2.0 * u2 + u, -2.0 * u3 + 3.0 * u2, u3 - u2};
    case 1:
      return {6.0 * u2 - 6.0 * u, 3.0 * u2 - 4.0 * u + 1.0, -6.0 * u2 + 6.0 * u, 3.0 * u2 - 2.0 * u};
    case 2:
      return {12.0 * u - 6.0, 6.0 * u - 4.0, -12.0 * u + 6.0, 6.0 * u - 2.0};
    default:
      return {};
  }
  // END SOLUTION
  // STUB: return exercises::notImplemented("ANIM-1", HermiteBasis{}, u, derivative);
}

}  // namespace pba::animation

PBA_EXERCISE_PROBE(pba::animation::hermiteBasis(0.5, 0));
