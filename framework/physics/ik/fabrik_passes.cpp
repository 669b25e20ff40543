// FABRIK's two passes on points (Aristidou & Lasenby 2011, Algorithm 1), exercise IK-5: the FABRIK
// method (fabrik.cpp) runs them on the points of an unconstrained chain, and on two points at a time
// for the point rule of its rigid-body passes.
#include <vector>

#include "physics/exercises/not_implemented.h"
#include "physics/ik/exercises.h"

namespace pba::ik {

// ***** IK-5: FABRIK's backward and forward passes (Aristidou & Lasenby 2011, Algorithm 1) *****
// The chain is the points p[0..n-1] [m] with segment lengths lengths[i] between p[i] and p[i+1].
// Backward pass (fabrikBackward): pin the last point on the target and walk back to the first. Forward
// pass (fabrikForward): pin the first point back on the base and walk out to the last.
// (1) In either pass, each point's new place depends only on its already-moved neighbour and where the
//     point itself was: the segment between them must get its length back, and the point must stay on
//     the line toward that neighbour. Work out where that puts it.
// (2) If a point coincides with its neighbour no direction is defined: leave it where it is.
// Check: after a backward pass the last point is on the target and every segment has its length; after a
// forward pass the first point is on the base; a reachable target is approached pass after pass.
// *****
void fabrikBackward([[maybe_unused]] std::vector<Vec3>& points, [[maybe_unused]] const std::vector<Real>& lengths,
                    [[maybe_unused]] const Vec3& target) {
  // BEGIN SOLUTION
  if (points.empty()) return;
  points.back() = target;
  for (size_t i = points.size() - 1; i-- > 0;) {
    const Vec3 d = points[i] - points[i + 1];
    const Real l = glm::length(d);
    if (l > 1e-12) points[i] = points[i + 1] + d * (lengths[i] / l);
  }
  return;
  // END SOLUTION
  // STUB: exercises::markNotImplemented("IK-5");
}

void fabrikForward([[maybe_unused]] std::vector<Vec3>& points, [[maybe_unused]] const std::vector<Real>& lengths,
                   [[maybe_unused]] const Vec3& base) {
  // BEGIN SOLUTION
  if (points.empty()) return;
  points.front() = base;
  for (size_t i = 1; i < points.size(); ++i) {
    const Vec3 d = points[i] - points[i - 1];
    const Real l = glm::length(d);
    if (l > 1e-12) points[i] = points[i - 1] + d * (lengths[i - 1] / l);
  }
  return;
  // END SOLUTION
  // STUB: exercises::markNotImplemented("IK-5");
}

// Start-up probe: tells the lab whether IK-5 is still a stub.
namespace {
void probeFabrikPasses() {
  std::vector<Vec3> points{Vec3(0.0), Vec3(1.0, 0.0, 0.0)};
  const std::vector<Real> lengths{1.0};
  fabrikBackward(points, lengths, Vec3(0.0, 1.0, 0.0));
  fabrikForward(points, lengths, Vec3(0.0));
}
}  // namespace
PBA_EXERCISE_PROBE(probeFabrikPasses());

}  // namespace pba::ik
