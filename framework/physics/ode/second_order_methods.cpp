// Methods that use the split s = (q, v): symplectic Euler and velocity Verlet (position Verlet, which also
// does, is in position_verlet.cpp). They update the system's own arrays in place (no state copies).
#include <cstddef>

#include "physics/exercises/not_implemented.h"
#include "physics/ode/in_place_step.h"
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
  for (std::size_t i = 0; i < s.n; ++i) {
    s.q[i] += h * s.v[i] + 0.5 * h * h * s.a[i];
    s.v[i] += 0.5 * h * s.a[i];  // half kick
  }
  system.acceleration(s.t + h, s.q, s.v, w.k1);  // a at the new positions (s.a views w.k1)
  for (std::size_t i = 0; i < s.n; ++i) s.v[i] += 0.5 * h * s.a[i];  // second half kick
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
