// Linearised backward Euler with a matrix-free conjugate-gradient solve (Baraff & Witkin 1998).
//
// Derivation (Baraff & Witkin 1998 §4.1, eq. 15–18, velocity form). Backward Euler takes the force at
// the END of the step:  Δv = h M⁻¹ f(q₀ + Δq, v₀ + Δv),  Δq = h (v₀ + Δv).
// One Newton step, i.e. the first-order Taylor expansion f(q₀ + Δq, v₀ + Δv) ≈ f₀ + K Δq + D Δv with
// K = ∂f/∂q and D = ∂f/∂v, gives the linear system
//     (M − h D − h² K) Δv = h (f₀ + h K v₀).                                   (B&W eq. 16, × M)
// For springs K and D are symmetric (and negative semi-definite after the definiteness fix in
// springs/spring_network.cpp), so A = M − hD − h²K is symmetric positive definite: conjugate gradients
// apply. Limiting cases: h → 0 gives Δv = h M⁻¹ f₀ (explicit Euler); for ẍ = −ω²x the step is exact
// backward Euler and multiplies the energy by 1/(1 + ω²h²) < 1 at any h.
// Pinned coordinates (M⁻¹ = 0) are held by zeroing their entries of every CG vector (B&W §5.3's filter
// S for a fully constrained particle), which solves the system restricted to the free coordinates.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "physics/ode/integrators.h"

namespace pba::ode {
namespace {
Real dot(std::span<const Real> a, std::span<const Real> b) {
  Real s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}
}  // namespace

ImplicitEulerStats implicitEulerStep(SecondOrderSystem& system, Real h, const ImplicitEulerSettings& settings,
                                     Workspace& w) {
  const std::size_t n = system.dofCount();
  Workspace::fit(n, {&w.k1, &w.k2, &w.k3, &w.k4, &w.k5, &w.k6, &w.k7, &w.tmp, &w.tmp2});
  std::vector<Real>& b = w.k1;   // right-hand side, then scratch
  std::vector<Real>& x = w.k2;   // Δv
  std::vector<Real>& r = w.k3;   // residual
  std::vector<Real>& p = w.k4;   // search direction
  std::vector<Real>& Ap = w.k5;  // A p
  std::vector<Real>& z = w.tmp;  // preconditioned residual
  std::vector<Real>& zero = w.tmp2;
  std::vector<Real>& dq = w.k6;  // scratch of applyA
  std::vector<Real>& dv = w.k7;
  const Real t = system.time();
  const std::span<Real> q = system.positions();
  const std::span<Real> v = system.velocities();
  const std::span<const Real> invMass = system.inverseMasses();
  std::ranges::fill(zero, 0.0);

  // b = h f₀ + h² K v₀ = h f₀ + forceDifferential(dq = h² v₀, dv = 0).
  system.force(t, q, v, b);
  for (std::size_t i = 0; i < n; ++i) dq[i] = h * h * v[i];
  system.forceDifferential(t, q, v, dq, zero, Ap);
  for (std::size_t i = 0; i < n; ++i) b[i] = invMass[i] > 0.0 ? h * b[i] + Ap[i] : 0.0;

  // A y = M y − (h D y + h² K y) = M y − forceDifferential(dq = h² y, dv = h y), filtered.
  auto applyA = [&](std::span<const Real> y, std::span<Real> out) {
    for (std::size_t i = 0; i < n; ++i) {
      dq[i] = h * h * y[i];
      dv[i] = h * y[i];
    }
    system.forceDifferential(t, q, v, dq, dv, out);
    for (std::size_t i = 0; i < n; ++i) out[i] = invMass[i] > 0.0 ? y[i] / invMass[i] - out[i] : 0.0;
  };

  // Preconditioned CG, Jacobi preconditioner P⁻¹ = M⁻¹ (the mass dominates A for small h).
  std::ranges::fill(x, 0.0);
  r = b;
  for (std::size_t i = 0; i < n; ++i) z[i] = invMass[i] * r[i];
  p = z;
  Real rz = dot(r, z);
  const Real bNorm = std::sqrt(dot(b, b));
  ImplicitEulerStats stats;
  if (bNorm > 0.0) {
    for (int k = 0; k < settings.maxIterations; ++k) {
      if (std::sqrt(dot(r, r)) <= settings.relativeTolerance * bNorm) break;
      applyA(p, Ap);
      const Real pAp = dot(p, Ap);
      if (!(pAp > 0.0)) break;  // not positive definite along p (should not happen): keep what we have
      const Real alpha = rz / pAp;
      for (std::size_t i = 0; i < n; ++i) {
        x[i] += alpha * p[i];
        r[i] -= alpha * Ap[i];
      }
      for (std::size_t i = 0; i < n; ++i) z[i] = invMass[i] * r[i];
      const Real rzNew = dot(r, z);
      const Real beta = rzNew / rz;
      rz = rzNew;
      for (std::size_t i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
      stats.iterations = k + 1;
    }
    stats.relativeResidual = std::sqrt(dot(r, r)) / bNorm;
  }
  for (std::size_t i = 0; i < n; ++i) {
    v[i] += x[i];
    q[i] += h * v[i];
  }
  system.stateChanged();
  system.setTime(t + h);
  return stats;
}

}  // namespace pba::ode
