#pragma once
// What the in-place methods of the ODE layer share (second_order_methods.cpp, position_verlet.cpp): they
// update the system's own q and v arrays (no state copies). Internal to framework/physics/ode.
#include <cstddef>
#include <span>

#include "physics/ode/integrators.h"

namespace pba::ode::detail {

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
