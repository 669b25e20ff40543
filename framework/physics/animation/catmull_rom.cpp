// Exercise ANIM-2: Catmull-Rom tangents on non-uniform knots with asst4's boundary rules.
#include "physics/animation/catmull_rom.h"

#include <algorithm>

#include "physics/exercises/not_implemented.h"

namespace pba::animation {

// ***** ANIM-2: Catmull-Rom tangents with non-uniform knots and the boundary rules (CMU asst4) *****
// Inputs: the channel's knot times [s] (strictly increasing) and the time t [s]. Output: the region, the
// knot `key`, the interval length h [s] and u in [0, 1), and the weights that make the segment's start
// and end tangents out of the knot values.
// (1) No knot: region Empty. One knot, or t at or before the first knot or at or after the last: region
//     Constant, `key` the knot whose value holds.
// (2) Otherwise find the interval that holds t (a binary search keeps long channels cheap) and u.
// (3) The tangent at a knot is the slope between its two neighbours, in value per second; the Hermite
//     segment wants it per unit of u: work out the weights each neighbour's value gets (slots 0 and 2
//     of startTangent for the start, 3 and 1 for the end).
// (4) At the first and last interval a neighbour is missing: it is the mirror of the far knot through
//     the near one. Write its value and time in terms of the two real knots and fold its weight into
//     theirs.
// Check: on knots with values on a straight line the tangents equal the line's slope times h, also at
// the ends; uniform knots give the uniform Catmull-Rom tangents of asst4.
// *****
CatmullRomSegment catmullRomSegment(std::span<const Real> times, Real t) {
  // BEGIN SOLUTION
  CatmullRomSegment s;
  const int n = static_cast<int>(times.size());
  if (n == 0) return s;
  s.region = SegmentRegion::Constant;
  if (n == 1 || t <= times.front()) return s;
  if (t >= times.back()) {
    s.key = n - 1;
    return s;
  }
  const int i = static_cast<int>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  const Real t1 = times[static_cast<size_t>(i)];
  const Real t2 = times[static_cast<size_t>(i + 1)];
  s.region = SegmentRegion::Interior;
  s.key = i;
  s.length = t2 - t1;
  s.u = (t - t1) / s.length;
  if (i > 0) {
    const Real w = s.length / (t2 - times[static_cast<size_t>(i - 1)]);
    s.startTangent = {-w, 0.0, w, 0.0};
  } else {
    s.startTangent = {0.0, -1.0, 1.0, 0.0};  // mirrored k0: (p2 − (2p1 − p2)) / (2h) · h
  }
  if (i + 2 < n) {
    const Real w = s.length / (times[static_cast<size_t>(i + 2)] - t1);
    s.endTangent = {0.0, -w, 0.0, w};
  } else {
    s.endTangent = {0.0, -1.0, 1.0, 0.0};  // mirrored k3: ((2p2 − p1) − p1) / (2h) · h
  }
  return s;
  // END SOLUTION
  // STUB: return exercises::notImplemented("ANIM-2", CatmullRomSegment{}, times, t);
}

}  // namespace pba::animation

namespace {
const pba::Real kProbeTimes[] = {0.0, 1.0};
}
PBA_EXERCISE_PROBE(pba::animation::catmullRomSegment(kProbeTimes, 0.5));
