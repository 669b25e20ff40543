// Methods that use the split s = (q, v): symplectic Euler (PART-2), velocity Verlet and midpoint (PART-7)
// (position Verlet, which also does, is in position_verlet.cpp). They update the system's own arrays in
// place (no state copies).
#include <cstddef>
#include <span>

#include "physics/exercises/not_implemented.h"
#include "physics/ode/integrators.h"
#include "physics/ode/oscillator.h"
#include "physics/ode/step_helpers.h"

namespace pba::ode {
using detail::finishInPlace;
using detail::InPlaceStep;
using detail::startInPlace;

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
  // STUB: exercises::markNotImplemented("PART-2");  // the state and the time stay where they are
}

void velocityVerletStep(SecondOrderSystem& system, Real h, Workspace& w) {
  const InPlaceStep s = startInPlace(system, w);
  const Real halfStep = 0.5 * h;
  Real* __restrict q = s.q.data();
  Real* __restrict v = s.v.data();
  const Real* a = w.k1.data();  // s.a: the acceleration, refreshed in the middle of the step
  // One pass for the half kick v(t + h/2) = v + (h/2) a and the drift q ← q + h v(t + h/2) = q + h v + h² a/2.
  for (std::size_t i = 0; i < s.n; ++i) {
    v[i] += halfStep * a[i];
    q[i] += h * v[i];
  }
  system.acceleration(s.t + h, s.q, s.v, w.k1);  // a at the new positions and the half-step velocity
  for (std::size_t i = 0; i < s.n; ++i) v[i] += halfStep * a[i];
  finishInPlace(system, s, h);
}

void midpointStep([[maybe_unused]] SecondOrderSystem& system, [[maybe_unused]] Real h, [[maybe_unused]] Workspace& w) {
  // BEGIN SOLUTION
  const InPlaceStep s = startInPlace(system, w);  // the start slope: (v, a₁), a₁ in w.k1
  Workspace::fit(s.n, {&w.k2, &w.tmp, &w.tmp2});
  const Real half = 0.5 * h;
  const std::span<Real> qMid(w.tmp), vMid(w.tmp2);
  for (std::size_t i = 0; i < s.n; ++i) {  // half a step along the start slope
    qMid[i] = s.q[i] + half * s.v[i];
    vMid[i] = s.v[i] + half * s.a[i];
  }
  system.acceleration(s.t + half, qMid, vMid, w.k2);  // the middle slope: (vMid, a₂), a₂ in w.k2
  for (std::size_t i = 0; i < s.n; ++i) {             // the whole step along the middle slope
    s.q[i] += h * vMid[i];
    s.v[i] += h * w.k2[i];
  }
  finishInPlace(system, s, h);
  // END SOLUTION
  // STUB: exercises::markNotImplemented("PART-7");  // the state and the time stay where they are
}

// Start-up probe: tells the lab whether PART-2 and PART-7 are still stubs.
namespace {
void probeSecondOrderMethods() {
  HarmonicOscillator oscillator;
  Workspace w;
  symplecticEulerStep(oscillator, 0.01, w);
  midpointStep(oscillator, 0.01, w);
}
}  // namespace
PBA_EXERCISE_PROBE(probeSecondOrderMethods());

}  // namespace pba::ode
