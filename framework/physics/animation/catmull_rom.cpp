// Exercise ANIM-2: Catmull-Rom tangents on non-uniform knots with asst4's boundary rules.
#include "physics/animation/catmull_rom.h"

#include <algorithm>

#include "physics/exercises/not_implemented.h"

namespace pba::animation {

// ***** ANIM-2: Catmull-Rom tangents with non-uniform knots and the boundary rules (CMU asst4) *****
// (1) No knot: region Empty. One knot, t at or before the first knot, or t at or after the last: region
//     Constant with `key` the knot whose value holds.
// (2) Otherwise find the interval [t_i, t_i+1) that holds t (the times increase strictly; a binary
//     search keeps long channels cheap); key = i, length h = t_i+1 − t_i, u = (t − t_i)/h.
// (3) The tangent at k1 is (p2 − p0)/(t2 − t0); times h it is a weight on p0 and one on p2 (slots 0
//     and 2 of startTangent). The tangent at k2 is (p3 − p1)/(t3 − t1) times h (slots 3 and 1).
// (4) A missing k0 (i = 0) is the mirror k1 − (k2 − k1): write p0 and t0 in terms of k1 and k2 and fold
//     p0's weight into theirs. Likewise a missing k3 at the last interval.
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
