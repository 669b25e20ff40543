// The explicit methods of the Lobb notes' "ODE view": explicit Euler (PART-1) on a second-order system's split
// s = (q, v) in place, its derivative assembled from the forces; RK4 (PART-3) on any OdeSystem. Midpoint
// (RK2, PART-7) works on the split in place too: second_order_methods.cpp.
#include <cstddef>
#include <span>

#include "physics/exercises/not_implemented.h"
#include "physics/ode/integrators.h"
#include "physics/ode/oscillator.h"
#include "physics/ode/step_helpers.h"

namespace pba::ode {
using detail::beginGenericStep;
using detail::endGenericStep;

void explicitEulerStep([[maybe_unused]] SecondOrderSystem& system, [[maybe_unused]] Real h,
                       [[maybe_unused]] Workspace& w) {
  // BEGIN SOLUTION
  Workspace::fit(system.dofCount(), {&w.k1});
  const Real start = system.time();
  const std::span<Real> positions = system.positions(), velocities = system.velocities();
  system.force(start, positions, velocities, w.k1);  // f(t, q, v) [N] at the start of the step
  const std::span<const Real> inverseMass = system.inverseMasses();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Real acceleration = w.k1[i] * inverseMass[i];  // v̇ = M⁻¹ f: 0 on a pinned coordinate
    positions[i] += h * velocities[i];                   // q̇ = v, before v changes
    velocities[i] += h * acceleration;
  }
  system.stateChanged();
  system.setTime(start + h);
  // END SOLUTION
  // STUB: exercises::markNotImplemented("PART-1");  // the state and the time stay where they are
}

void rk4Step(OdeSystem& system, [[maybe_unused]] Real h, Workspace& w) {
  const std::size_t n = system.stateSize();
  Workspace::fit(n, {&w.k1, &w.k2, &w.k3, &w.k4, &w.tmp});
  // BEGIN SOLUTION
  const Real t = beginGenericStep(system, w);  // s in w.s, k1 = f(s, t) in w.k1
  for (std::size_t i = 0; i < n; ++i) w.tmp[i] = w.s[i] + 0.5 * h * w.k1[i];
  system.derivative(t + 0.5 * h, w.tmp, w.k2);
  for (std::size_t i = 0; i < n; ++i) w.tmp[i] = w.s[i] + 0.5 * h * w.k2[i];
  system.derivative(t + 0.5 * h, w.tmp, w.k3);
  for (std::size_t i = 0; i < n; ++i) w.tmp[i] = w.s[i] + h * w.k3[i];
  system.derivative(t + h, w.tmp, w.k4);
  for (std::size_t i = 0; i < n; ++i) w.s[i] += (h / 6.0) * (w.k1[i] + 2.0 * w.k2[i] + 2.0 * w.k3[i] + w.k4[i]);
  endGenericStep(system, w, t + h);
  // END SOLUTION
  // STUB: exercises::markNotImplemented("PART-3");  // the state and the time stay where they are
}

// Start-up probes: tell the lab whether PART-1 and PART-3 are still stubs.
namespace {
void probeExplicitMethods() {
  HarmonicOscillator oscillator;
  Workspace w;
  explicitEulerStep(oscillator, 0.01, w);
  rk4Step(oscillator, 0.01, w);
}
}  // namespace
PBA_EXERCISE_PROBE(probeExplicitMethods());

}  // namespace pba::ode
