#include "physics/ode/ode_system.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>
#include <vector>

namespace pba::ode {
namespace {
// Copies `from` to `to` through raw pointers, so that it is one memmove: std::ranges::copy into a span's
// iterator compiles to an element-by-element loop (GCC 12), and getState/setState are on every step's path.
void copyReals(std::span<const Real> from, Real* to) { std::copy(from.data(), from.data() + from.size(), to); }
}  // namespace

void SecondOrderSystem::acceleration(Real t, std::span<const Real> q, std::span<const Real> v,
                                     std::span<Real> out) const {
  force(t, q, v, out);
  const std::span<const Real> w = inverseMasses();
  assert(w.size() == out.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] *= w[i];
}

void SecondOrderSystem::getState(std::span<Real> out) const {
  const std::size_t n = dofCount();
  assert(out.size() == 2 * n);
  if (out.data() == positions().data()) return;  // the system's own storage (stateStorage()): nothing to copy
  copyReals(positions(), out.data());
  copyReals(velocities(), out.data() + n);
}

void SecondOrderSystem::setState(std::span<const Real> state) {
  const std::size_t n = dofCount();
  assert(state.size() == 2 * n);
  if (state.data() != positions().data()) {  // else the system's own storage, already in place
    copyReals(state.first(n), positions().data());
    copyReals(state.subspan(n), velocities().data());
  }
  stateChanged();
}

void SecondOrderSystem::derivative(Real t, std::span<const Real> state, std::span<Real> out) const {
  const std::size_t n = dofCount();
  copyReals(state.subspan(n), out.data());  // q̇ = v
  acceleration(t, state.first(n), state.subspan(n), out.subspan(n));
}

void SecondOrderSystem::uncoupledForce(Real, std::span<const Real>, std::span<const Real>, std::size_t,
                                       std::span<Real> f, std::span<Real> dfdq, std::span<Real> dfdv) const {
  assert(uncoupledGroupSize() == 0 && "an uncoupled system overrides uncoupledForce()");
  std::fill(f.begin(), f.end(), 0.0);
  std::fill(dfdq.begin(), dfdq.end(), 0.0);
  std::fill(dfdv.begin(), dfdv.end(), 0.0);
}

void SecondOrderSystem::forceDifferential(Real t, std::span<const Real> q, std::span<const Real> v,
                                          std::span<const Real> dq, std::span<const Real> dv, std::span<Real> out) {
  // Central difference along the direction (dq, dv): [f(s + εd) − f(s − εd)] / 2ε, error O(ε²).
  // ε scales with the size of s and of d so that the perturbation is a fixed relative change.
  const std::size_t n = dofCount();
  Real stateScale = 1.0, dirScale = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    stateScale = std::max({stateScale, std::abs(q[i]), std::abs(v[i])});
    dirScale = std::max({dirScale, std::abs(dq[i]), std::abs(dv[i])});
  }
  if (dirScale == 0.0) {
    std::fill(out.begin(), out.end(), 0.0);  // not std::ranges::fill: libc++ 14 lacks it
    return;
  }
  const Real eps = 1e-6 * stateScale / dirScale;
  if (differenceScratch_.size() != 5 * n) differenceScratch_.assign(5 * n, 0.0);
  const std::span<Real> scratch(differenceScratch_);
  const std::span<Real> qp = scratch.subspan(0, n), vp = scratch.subspan(n, n), qm = scratch.subspan(2 * n, n),
                        vm = scratch.subspan(3 * n, n), fm = scratch.subspan(4 * n, n);
  for (std::size_t i = 0; i < n; ++i) {
    qp[i] = q[i] + eps * dq[i];
    vp[i] = v[i] + eps * dv[i];
    qm[i] = q[i] - eps * dq[i];
    vm[i] = v[i] - eps * dv[i];
  }
  force(t, qp, vp, out);
  force(t, qm, vm, fm);
  for (std::size_t i = 0; i < n; ++i) out[i] = (out[i] - fm[i]) / (2.0 * eps);
}

OwnedStateSystem::OwnedStateSystem(const std::vector<Real>& q, const std::vector<Real>& v, std::vector<Real> w)
    : w_(std::move(w)) {
  assert(q.size() == w_.size() && v.size() == w_.size());
  s_.reserve(2 * w_.size());
  s_.insert(s_.end(), q.begin(), q.end());
  s_.insert(s_.end(), v.begin(), v.end());
}

}  // namespace pba::ode
