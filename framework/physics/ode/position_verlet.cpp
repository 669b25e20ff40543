// Position Verlet (PART-6): a two-step recurrence on the positions, in place on the system's arrays.
#include <cstddef>
#include <cstring>
#include <span>
#include <vector>

#include "physics/exercises/not_implemented.h"
#include "physics/ode/integrators.h"
#include "physics/ode/oscillator.h"
#include "physics/ode/step_helpers.h"

namespace pba::ode {
using detail::finishInPlace;
using detail::InPlaceStep;
using detail::startInPlace;

namespace {
// PART-6's update of every coordinate (q, v and the remembered q(t − h)); true when it stepped.
bool verletRecurrence([[maybe_unused]] std::span<Real> q, [[maybe_unused]] std::span<Real> v,
                      [[maybe_unused]] std::span<const Real> a, [[maybe_unused]] std::vector<Real>& previous,
                      [[maybe_unused]] Real h) {
  // BEGIN SOLUTION
  for (std::size_t i = 0; i < q.size(); ++i) {
    const Real next = 2.0 * q[i] - previous[i] + h * h * a[i];
    v[i] = (next - q[i]) / h + 0.5 * h * a[i];
    previous[i] = q[i];
    q[i] = next;
  }
  return true;
  // END SOLUTION
  // STUB: return exercises::notImplemented("PART-6", false, q, v, a, previous, h);  // the state stays
}

// Whether q and v are, bit for bit, the lastQ and lastV the method produced (sizes equal): memcmp, which
// the C library runs at the memory's speed (a loop of == that stops at the first difference compiles to
// one scalar compare and branch per value, and was half of a step). Bits rather than values: any outside
// write that changed a value restarts the recurrence, also −0 over +0, and a NaN the method produced
// itself does not force a restart at every later step.
bool sameState(const VerletHistory& history, std::span<const Real> q, std::span<const Real> v) {
  if (q.empty()) return true;  // memcmp wants valid pointers even for 0 bytes
  return std::memcmp(q.data(), history.lastQ.data(), q.size_bytes()) == 0 &&
         std::memcmp(v.data(), history.lastV.data(), v.size_bytes()) == 0;
}
}  // namespace

void verletStep(SecondOrderSystem& system, [[maybe_unused]] Real h, VerletHistory& history, Workspace& w) {
  const InPlaceStep s = startInPlace(system, w);
  const std::size_t n = s.n;
  const std::span<Real> q = s.q, v = s.v;
  const std::span<const Real> a = s.a;
  // Start (or restart) the two-step recurrence when the state is not the one this method produced:
  // q(t − h) from the Taylor expansion q − h v + h²a/2, exact under constant acceleration.
  const bool same = history.valid && history.lastH == h && history.previous.size() == n && history.lastQ.size() == n &&
                    history.lastV.size() == n && sameState(history, q, v);
  if (!same) {
    history.previous.resize(n);
    for (std::size_t i = 0; i < n; ++i) history.previous[i] = q[i] - h * v[i] + 0.5 * h * h * a[i];
  }
  if (!verletRecurrence(q, v, a, history.previous, h)) return;  // a stub: the state and clock stay
  history.lastQ.assign(q.data(), q.data() + n);                 // pointers: one memmove each
  history.lastV.assign(v.data(), v.data() + n);
  history.lastH = h;
  history.valid = true;
  finishInPlace(system, s, h);
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
