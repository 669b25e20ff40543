// FABRIK's two passes on points (Aristidou & Lasenby 2011, Algorithm 1), exercise IK-5: the FABRIK
// method (fabrik.cpp) runs them on the points of an unconstrained chain, and on two points at a time
// for the point rule of its rigid-body passes.
#include <vector>

#include "physics/exercises/not_implemented.h"
#include "physics/ik/exercises.h"

namespace pba::ik {

// ***** IK-5: FABRIK's backward and forward passes (Aristidou & Lasenby 2011, Algorithm 1) *****
// Backward pass (fabrikBackward), on points p[0..n-1] with lengths[i] = |p[i+1] − p[i]|:
// (1) Move the last point onto the target: p[n−1] = target.
// (2) For i from n−2 down to 0: the direction d = p[i] − p[i+1]; if |d| is (almost) zero leave p[i]
//     where it is (no direction is defined); otherwise p[i] = p[i+1] + lengths[i] · d / |d|.
// Forward pass (fabrikForward):
// (3) Move the first point back onto the base: p[0] = base.
// (4) For i from 1 to n−1: d = p[i] − p[i−1]; if |d| is (almost) zero leave p[i]; otherwise
//     p[i] = p[i−1] + lengths[i−1] · d / |d|.
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
