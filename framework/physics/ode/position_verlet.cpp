// Position Verlet (PART-6): a two-step recurrence on the positions, in place on the system's arrays.
#include <algorithm>
#include <cstddef>

#include "physics/exercises/not_implemented.h"
#include "physics/ode/in_place_step.h"
#include "physics/ode/integrators.h"
#include "physics/ode/oscillator.h"

namespace pba::ode {
using detail::finishInPlace;
using detail::InPlaceStep;
using detail::startInPlace;

namespace {
// Position Verlet's memory of the state it produced, so that its next step notices a change from outside.
[[maybe_unused]] void rememberProduced(VerletHistory& history, const InPlaceStep& s, Real h) {
  history.lastQ.assign(s.q.begin(), s.q.end());
  history.lastV.assign(s.v.begin(), s.v.end());
  history.lastH = h;
  history.valid = true;
}
}  // namespace

void verletStep(SecondOrderSystem& system, [[maybe_unused]] Real h, VerletHistory& history, Workspace& w) {
  const InPlaceStep s = startInPlace(system, w);
  const std::size_t n = s.n;
  const std::span<Real> q = s.q, v = s.v;
  const std::span<const Real> a = s.a;
  // Start (or restart) the two-step recurrence when the state is not the one this method produced:
  // q(t − h) from the Taylor expansion q − h v + h²a/2, exact under constant acceleration.
  const bool same = history.valid && history.lastH == h && history.previous.size() == n &&
                    std::ranges::equal(history.lastQ, q) && std::ranges::equal(history.lastV, v);
  if (!same) {
    history.previous.resize(n);
    for (std::size_t i = 0; i < n; ++i) history.previous[i] = q[i] - h * v[i] + 0.5 * h * h * a[i];
  }
  // BEGIN SOLUTION
  for (std::size_t i = 0; i < n; ++i) {
    const Real next = 2.0 * q[i] - history.previous[i] + h * h * a[i];
    v[i] = (next - q[i]) / h + 0.5 * h * a[i];
    history.previous[i] = q[i];
    q[i] = next;
  }
  rememberProduced(history, s, h);
  finishInPlace(system, s, h);
  // END SOLUTION
  // STUB: exercises::markNotImplemented("PART-6");  // the state and the time stay where they are
}

// Start-up probe: tells the lab whether PART-6 is still a stub.
namespace {
void probeVerlet() {
  HarmonicOscillator oscillator;
  Workspace w;
  VerletHistory history;
  verletStep(oscillator, 0.01, history, w);
}
}  // namespace
PBA_EXERCISE_PROBE(probeVerlet());

}  // namespace pba::ode
