// Methods that use the split s = (q, v): symplectic Euler, velocity Verlet, position Verlet.
// They update the system's own arrays in place (no state copies).
#include <algorithm>
#include <cstddef>

#include "physics/ode/oscillator.h"
#include "physics/exercises/not_implemented.h"
#include "physics/ode/integrators.h"

namespace pba::ode {
namespace {
void resize(std::vector<Real>& v, std::size_t n) {
  if (v.size() != n) v.assign(n, 0.0);
}
}  // namespace

void symplecticEulerStep(SecondOrderSystem& system, [[maybe_unused]] Real h, Workspace& w) {
  const std::size_t n = system.dofCount();
  resize(w.k1, n);
  // BEGIN SOLUTION
  const Real t = system.time();
  const std::span<Real> q = system.positions();
  const std::span<Real> v = system.velocities();
  system.acceleration(t, q, v, w.k1);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] += h * w.k1[i];
    q[i] += h * v[i];
  }
  system.stateChanged();
  system.setTime(t + h);
  // END SOLUTION
  // STUB: exercises::markNotImplemented("PART-2");  // the state stays where it is
}

void velocityVerletStep(SecondOrderSystem& system, Real h, Workspace& w) {
  const std::size_t n = system.dofCount();
  resize(w.k1, n);
  const Real t = system.time();
  const std::span<Real> q = system.positions();
  const std::span<Real> v = system.velocities();
  system.acceleration(t, q, v, w.k1);
  for (std::size_t i = 0; i < n; ++i) {
    q[i] += h * v[i] + 0.5 * h * h * w.k1[i];
    v[i] += 0.5 * h * w.k1[i];  // half kick
  }
  system.acceleration(t + h, q, v, w.k1);
  for (std::size_t i = 0; i < n; ++i) v[i] += 0.5 * h * w.k1[i];  // second half kick
  system.stateChanged();
  system.setTime(t + h);
}

void verletStep(SecondOrderSystem& system, [[maybe_unused]] Real h, VerletHistory& history, Workspace& w) {
  const std::size_t n = system.dofCount();
  resize(w.k1, n);
  const Real t = system.time();
  const std::span<Real> q = system.positions();
  const std::span<Real> v = system.velocities();
  system.acceleration(t, q, v, w.k1);
  const std::span<const Real> a = w.k1;
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
  // END SOLUTION
  // STUB: exercises::markNotImplemented("PART-6");  // the state stays where it is
  history.lastQ.assign(q.begin(), q.end());
  history.lastV.assign(v.begin(), v.end());
  history.lastH = h;
  history.valid = true;
  system.stateChanged();
  system.setTime(t + h);
}

// Start-up probes: tell the lab whether PART-2 and PART-6 are still stubs.
namespace {
void probeSecondOrderMethods() {
  HarmonicOscillator oscillator;
  Workspace w;
  VerletHistory history;
  symplecticEulerStep(oscillator, 0.01, w);
  verletStep(oscillator, 0.01, history, w);
}
}  // namespace
PBA_EXERCISE_PROBE(probeSecondOrderMethods());

}  // namespace pba::ode
