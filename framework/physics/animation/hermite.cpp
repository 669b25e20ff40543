// Exercise ANIM-1: the Hermite basis and its derivatives (CMU asst4, "Splines").
#include "physics/animation/hermite.h"

#include "physics/exercises/not_implemented.h"

namespace pba::animation {

// ***** ANIM-1: the Hermite basis and its derivatives (CMU asst4, "Splines") *****
// (1) derivative 0: the four cubics of the comment in hermite.h at u (powers of u, no loops needed).
// (2) derivative 1: differentiate each cubic once with respect to u.
// (3) derivative 2: differentiate once more (each becomes a straight line in u).
// (4) Any other derivative order: every weight is 0 (a cubic's fourth derivative vanishes; the third is
//     not used by the library).
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
