// Methods that use the split s = (q, v): symplectic Euler and velocity Verlet (position Verlet, which also
// does, is in position_verlet.cpp). They update the system's own arrays in place (no state copies).
#include <algorithm>
#include <cstddef>

#include "physics/exercises/not_implemented.h"
#include "physics/ode/step_helpers.h"
#include "physics/ode/integrators.h"
#include "physics/ode/oscillator.h"

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
  // v ← v + (h/2) a, with the acceleration in w.k1 (which s.a views).
  auto halfKick = [&] {
    std::transform(s.v.begin(), s.v.end(), s.a.begin(), s.v.begin(), [&](Real vi, Real ai) { return vi + halfStep * ai; });
  };
  halfKick();  // v(t + h/2)
  // q ← q + h v(t + h/2) = q + h v + h² a/2.
  std::transform(s.q.begin(), s.q.end(), s.v.begin(), s.q.begin(), [&](Real qi, Real vi) { return qi + h * vi; });
  system.acceleration(s.t + h, s.q, s.v, w.k1);  // a at the new positions and the half-step velocity
  halfKick();
  finishInPlace(system, s, h);
}

// Start-up probe: tells the lab whether PART-2 is still a stub.
namespace {
void probeSymplecticEuler() {
  HarmonicOscillator oscillator;
  Workspace w;
  symplecticEulerStep(oscillator, 0.01, w);
}
}  // namespace
PBA_EXERCISE_PROBE(probeSymplecticEuler());

}  // namespace pba::ode
