#pragma once
// What the methods of the ODE layer share, internal to framework/physics/ode: the generic methods
// (explicit_methods.cpp) copy the state out, advance it and copy it back; the in-place ones
// (second_order_methods.cpp, position_verlet.cpp) update the system's own q and v arrays.
#include <cstddef>
#include <span>

#include "physics/ode/integrators.h"

namespace pba::ode::detail {

// The start of every generic method: the state s(t) in w.s (n = stateSize() values), its derivative
// f(s, t) in w.k1 (which the method has sized); returns t. A system that keeps its state in one array
// lends it (stateStorage()): w.s is then that array, getState() and endGenericStep's setState() have
// nothing to copy, and the method advances the state where it lives. The numbers are the same either
// way: every method reads s only to evaluate stages and writes it only after its last evaluation.
inline Real beginGenericStep(OdeSystem& system, Workspace& w) {
  const Real time = system.time();
  const std::size_t n = system.stateSize();
  const std::span<Real> storage = system.stateStorage();
  if (storage.size() == n) {
    w.s = storage;
  } else {
    Workspace::fit(n, {&w.state});
    w.s = w.state;
  }
  system.getState(w.s);
  system.derivative(time, w.s, w.k1);
  return time;
}
// And its end: w.s becomes the system's state at time `end`.
inline void endGenericStep(OdeSystem& system, const Workspace& w, Real end) {
  system.setState(w.s);
  system.setTime(end);
}

// What every in-place method starts from: the coordinates q and velocities v of the system (its own
// storage), the time t, and the acceleration a = M⁻¹ f(t, q, v) at the start of the step in w.k1.
struct InPlaceStep {
  std::size_t n;
  Real t;
  std::span<Real> q, v;
  std::span<const Real> a;
};
inline InPlaceStep startInPlace(SecondOrderSystem& system, Workspace& w) {
  const std::size_t n = system.dofCount();
  Workspace::fit(n, {&w.k1});
  const InPlaceStep s{n, system.time(), system.positions(), system.velocities(), w.k1};
  system.acceleration(s.t, s.q, s.v, w.k1);
  return s;
}
// And what every one ends with: tell the system its state changed and advance its time to t + h.
inline void finishInPlace(SecondOrderSystem& system, const InPlaceStep& s, Real h) {
  system.stateChanged();
  system.setTime(s.t + h);
}

}  // namespace pba::ode::detail
