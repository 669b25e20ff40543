// Methods that use the split s = (q, v): symplectic Euler, velocity Verlet, position Verlet.
// They update the system's own arrays in place (no state copies).
#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "physics/ode/oscillator.h"
#include "physics/exercises/not_implemented.h"
#include "physics/ode/integrators.h"

namespace pba::ode {
namespace {
// What every in-place method starts from: the coordinates q and velocities v of the system (its own
// storage), the time t, and the acceleration a = M⁻¹ f(t, q, v) at the start of the step in w.k1.
struct InPlaceStep {
  std::size_t n;
  Real t;
  std::span<Real> q, v;
  std::span<const Real> a;
};
InPlaceStep startInPlace(SecondOrderSystem& system, Workspace& w) {
  const std::size_t n = system.dofCount();
  Workspace::fit(n, {&w.k1});
  const InPlaceStep s{n, system.time(), system.positions(), system.velocities(), w.k1};
  system.acceleration(s.t, s.q, s.v, w.k1);
  return s;
}
// And what every one ends with: tell the system its state changed and advance its time to t + h.
void finishInPlace(SecondOrderSystem& system, const InPlaceStep& s, Real h) {
  system.stateChanged();
  system.setTime(s.t + h);
}
}  // namespace

void symplecticEulerStep([[maybe_unused]] SecondOrderSystem& system, [[maybe_unused]] Real h,
                         [[maybe_unused]] Workspace& w) {
  // BEGIN SOLUTION
  const InPlaceStep s = startInPlace(system, w);  // q, v, t and a = M⁻¹ f(t, q, v)
  for (std::size_t i = 0; i < s.n; ++i) {
    s.v[i] += h * s.a[i];
    s.q[i] += h * s.v[i];
  }
  finishInPlace(system, s, h);
  // END SOLUTION
  // STUB: exercises::markNotImplemented("PART-2");  // the state stays where it is
}

void velocityVerletStep(SecondOrderSystem& system, Real h, Workspace& w) {
  const InPlaceStep s = startInPlace(system, w);
  for (std::size_t i = 0; i < s.n; ++i) {
    s.q[i] += h * s.v[i] + 0.5 * h * h * s.a[i];
    s.v[i] += 0.5 * h * s.a[i];  // half kick
  }
  system.acceleration(s.t + h, s.q, s.v, w.k1);  // a at the new positions (s.a views w.k1)
  for (std::size_t i = 0; i < s.n; ++i) s.v[i] += 0.5 * h * s.a[i];  // second half kick
  finishInPlace(system, s, h);
}

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
  if (!verletRecurrence(q, v, a, history.previous, h)) return;  // a stub: the state and clock stay
  history.lastQ.assign(q.begin(), q.end());
  history.lastV.assign(v.begin(), v.end());
  history.lastH = h;
  history.valid = true;
  finishInPlace(system, s, h);
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
