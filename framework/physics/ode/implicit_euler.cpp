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
// Preconditioner (Baraff & Witkin §5.3 precondition with the diagonal of A; we take its 3×3 diagonal
// blocks, "block Jacobi"): P⁻¹ = blockdiag(A_ii)⁻¹ with A_ii = M_i − h D_ii − h² K_ii, from the system's
// forceJacobianDiagonalBlocks(). For a particle alone on a spring it is A itself (CG converges in one
// iteration); for a network it removes the large per-particle stiffness that the mass diagonal ignores.
// The blocks are SPD for the same reason A is (each is a principal submatrix of A).
// Convergence is judged on the true residual b − A Δv, recomputed after the loop, not on CG's recursive
// estimate (which drifts from it in floating point).
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <string>

#include "physics/core/format.h"
#include "physics/ode/integrators.h"

namespace pba::ode {
namespace {
/// A y = M y − (h D y + h² K y) = M y − forceDifferential(dq = h² y, dv = h y), filtered by S (pinned
/// coordinates get 0). Scratch dq, dv from the workspace: no allocation. A product is three passes: the
/// direction (dq, dv) from y, which the caller may fuse with the pass that makes y (direction()); the
/// differential; and M y − out, which also accumulates a dot product with the result (finish()).
struct SystemMatrix {
  SecondOrderSystem& system;
  Real t, h;
  std::span<const Real> q, v, invMass;
  std::span<Real> dq, dv;
  void direction(std::size_t i, Real yi) const {
    dq[i] = h * h * yi;
    dv[i] = h * yi;
  }
  /// out = A y given direction() of every y_i; calls visit(i, (A y)_i) in order of i after writing it.
  template <typename Visit>
  void finish(std::span<const Real> y, std::span<Real> out, Visit&& visit) const {
    system.forceDifferential(t, q, v, dq, dv, out);
    for (std::size_t i = 0; i < y.size(); ++i) {
      out[i] = invMass[i] > 0.0 ? y[i] / invMass[i] - out[i] : 0.0;
      visit(i, out[i]);
    }
  }
};

/// The preconditioner z = P⁻¹ r: inverse diagonal blocks when the system gave them, else M⁻¹. Applied
/// inside a pass over the coordinates (apply()): `update(i)` brings r_i up to date, then z is made for
/// the coordinates whose r is complete (one at a time, or a block of three), and `visit(i)` sees each
/// r_i and z_i in order of i, so that sums over i keep the order of separate passes.
struct Preconditioner {
  std::span<const Mat3> inverseBlocks;  // empty: mass Jacobi
  std::span<const Real> invMass;
  template <typename Update, typename Visit>
  void apply(std::span<const Real> r, std::span<Real> z, Update&& update, Visit&& visit) const {
    if (inverseBlocks.empty()) {
      for (std::size_t i = 0; i < r.size(); ++i) {
        update(i);
        z[i] = invMass[i] * r[i];
        visit(i);
      }
      return;
    }
    for (std::size_t b = 0; b < inverseBlocks.size(); ++b) {
      for (std::size_t c = 0; c < 3; ++c) update(3 * b + c);
      const Vec3 zb = inverseBlocks[b] * Vec3(r[3 * b], r[3 * b + 1], r[3 * b + 2]);
      for (std::size_t c = 0; c < 3; ++c) {
        z[3 * b + c] = zb[static_cast<int>(c)];
        visit(3 * b + c);
      }
    }
  }
};

/// Inverts A_ii = M_i − h D_ii − h² K_ii in place of K (blocks) given D (blocksD), restricted to the free
/// coordinates of the block: a pinned coordinate's row and column become those of the identity before the
/// inversion and 0 after it, so that P⁻¹ never moves a pinned coordinate.
void invertDiagonalBlocks(std::span<Mat3> blocks, std::span<const Mat3> blocksD, std::span<const Real> invMass,
                          Real h) {
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    Mat3 a = -(h * blocksD[b]) - (h * h) * blocks[b];
    bool free[3];
    for (int c = 0; c < 3; ++c) {
      const Real w = invMass[3 * b + static_cast<std::size_t>(c)];
      free[c] = w > 0.0;
      a[c][c] += free[c] ? 1.0 / w : 0.0;
    }
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        if (!free[r] || !free[c]) a[c][r] = r == c ? 1.0 : 0.0;
    Mat3 inverse = glm::inverse(a);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        if (!free[r] || !free[c]) inverse[c][r] = 0.0;
    blocks[b] = inverse;
  }
}
/// Implicit Euler for an uncoupled system (SecondOrderSystem::uncoupledGroupSize() = g ∈ {1, 3}): A is
/// block diagonal, so each group's g × g system, scaled by M⁻¹ so that a pinned coordinate's row reads
/// Δv_c = 0,
///     (I − h M⁻¹ (D + h K)) Δv = h M⁻¹ (f₀ + h K v₀),
/// is solved directly, a block of coordinates at a time, in one pass over the state: the system writes
/// f, K and D of a block into buffers that stay in cache, and the block is solved and stepped at once.
/// The same linear system as the conjugate-gradient path (which would converge on it in one iteration
/// of the exact block-Jacobi preconditioner), so the same step up to rounding.
ImplicitEulerStats uncoupledStep(SecondOrderSystem& system, Real h, int g) {
  constexpr std::size_t kBlock = 192;  // coordinates per block, a multiple of 1 and 3
  const std::size_t n = system.dofCount();
  const Real t = system.time();
  const std::span<Real> q = system.positions();
  const std::span<Real> v = system.velocities();
  const std::span<const Real> w = system.inverseMasses();
  const auto group = static_cast<std::size_t>(g);
  std::array<Real, kBlock> f;
  std::array<Real, 3 * kBlock> K, D;
  for (std::size_t first = 0; first < n; first += kBlock) {
    const std::size_t count = std::min(kBlock, n - first);
    system.uncoupledForce(t, q, v, first, std::span<Real>(f).first(count), std::span<Real>(K).first(count * group),
                          std::span<Real>(D).first(count * group));
    if (g == 1) {
      // A pinned coordinate (w = 0) gets Δv = 0 / 1 with no branch.
      for (std::size_t i = 0; i < count; ++i) {
        const std::size_t j = first + i;
        const Real dv = h * w[j] * (f[i] + h * K[i] * v[j]) / (1.0 - h * w[j] * (D[i] + h * K[i]));
        v[j] += dv;
        q[j] += h * v[j];
      }
      continue;
    }
    for (std::size_t b = 0; b < count / 3; ++b) {
      const std::size_t j = first + 3 * b;
      const Real* k = K.data() + 9 * b;
      const Real* d = D.data() + 9 * b;
      Mat3 a(1.0);  // glm: a[column][row]
      Vec3 rhs;
      for (int r = 0; r < 3; ++r) {
        const Real wr = w[j + static_cast<std::size_t>(r)];
        Real kv = 0.0;
        for (int c = 0; c < 3; ++c) {  // the blocks are column-major: (r, c) at 3c + r
          kv += k[3 * c + r] * v[j + static_cast<std::size_t>(c)];
          a[c][r] -= h * wr * (d[3 * c + r] + h * k[3 * c + r]);
        }
        rhs[r] = h * wr * (f[3 * b + static_cast<std::size_t>(r)] + h * kv);
      }
      const Vec3 dv = glm::inverse(a) * rhs;
      for (int r = 0; r < 3; ++r) {
        const std::size_t c = j + static_cast<std::size_t>(r);
        v[c] += dv[r];
        q[c] += h * v[c];
      }
    }
  }
  system.stateChanged();
  system.setTime(t + h);
  ImplicitEulerStats stats;
  stats.direct = true;
  return stats;
}
}  // namespace

Status validate(const ImplicitEulerSettings& s) {
  if (s.maxIterations < 1) {
    return Error{"implicit.maxIterations: must be at least 1, got " + std::to_string(s.maxIterations)};
  }
  if (!(std::isfinite(s.relativeTolerance) && s.relativeTolerance > 0.0 && s.relativeTolerance < 1.0)) {
    return Error{"implicit.relativeTolerance: must be in (0, 1), got " + formatExact(s.relativeTolerance)};
  }
  return Status::success();
}

ImplicitEulerStats implicitEulerStep(SecondOrderSystem& system, Real h, const ImplicitEulerSettings& settings,
                                     Workspace& w) {
  assert(validate(settings).ok());
  const std::size_t n = system.dofCount();
  if (const int g = system.uncoupledGroupSize(); (g == 1 || g == 3) && n % static_cast<std::size_t>(g) == 0)
    return uncoupledStep(system, h, g);
  Workspace::fit(n, {&w.k1, &w.k2, &w.k3, &w.k4, &w.k5, &w.k6, &w.k7, &w.tmp});
  std::vector<Real>& b = w.k1;   // right-hand side
  std::vector<Real>& x = w.k2;   // Δv
  std::vector<Real>& r = w.k3;   // residual
  std::vector<Real>& p = w.k4;   // search direction
  std::vector<Real>& Ap = w.k5;  // A p
  std::vector<Real>& z = w.tmp;  // preconditioned residual
  const Real t = system.time();
  const std::span<Real> q = system.positions();
  const std::span<Real> v = system.velocities();
  const std::span<const Real> invMass = system.inverseMasses();
  const SystemMatrix A{system, t, h, q, v, invMass, w.k6, w.k7};

  // b = h f₀ + h² K v₀ = h f₀ + forceDifferential(dq = h² v₀, dv = 0), filtered; x₀ = 0, r₀ = b.
  system.force(t, q, v, b);
  for (std::size_t i = 0; i < n; ++i) {
    A.dq[i] = h * h * v[i];
    A.dv[i] = 0.0;
  }
  system.forceDifferential(t, q, v, A.dq, A.dv, Ap);
  Real bb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    b[i] = invMass[i] > 0.0 ? h * b[i] + Ap[i] : 0.0;
    x[i] = 0.0;
    r[i] = b[i];
    bb += b[i] * b[i];
  }

  ImplicitEulerStats stats;
  Preconditioner P{{}, invMass};
  if (n % 3 == 0) {
    w.blocks.resize(n / 3);
    w.blocks2.resize(n / 3);
    if (system.forceJacobianDiagonalBlocks(t, q, v, w.blocks, w.blocks2)) {
      invertDiagonalBlocks(w.blocks, w.blocks2, invMass, h);
      P.inverseBlocks = w.blocks;
      stats.blockPreconditioner = true;
    }
  }

  // Preconditioned conjugate gradients (Shewchuk 1994, "CG without the agonizing pain", §B3), x₀ = 0.
  // CG's recursive residual drifts from b − A x in floating point: when it says "converged" and the true
  // residual disagrees, CG restarts once from the current x with the true residual.
  // Every vector update shares its pass with the dot products of what it wrote (r·z and r·r with the
  // step of x and r; p·Ap with the product; p with the direction of the next product): the same sums, in
  // the same order, as one pass per operation, so the same numbers, with four passes per iteration
  // instead of nine.
  const Real bNorm = std::sqrt(bb);
  const Real target = settings.relativeTolerance * bNorm;
  Real rr = 0.0;  // r·r of the current residual, from the pass that last wrote r
  const auto noUpdate = [](std::size_t) {};
  for (int pass = 0; pass < 2 && bNorm > 0.0; ++pass) {
    Real rz = 0.0;
    rr = 0.0;
    P.apply(r, z, noUpdate, [&](std::size_t i) {
      rz += r[i] * z[i];
      rr += r[i] * r[i];
    });
    bool first = true;  // p = z, else p = z + β p
    Real beta = 0.0;
    while (stats.iterations < settings.maxIterations && std::sqrt(rr) > target) {
      if (first) {
        for (std::size_t i = 0; i < n; ++i) A.direction(i, p[i] = z[i]);
      } else {
        for (std::size_t i = 0; i < n; ++i) A.direction(i, p[i] = z[i] + beta * p[i]);
      }
      first = false;
      Real pAp = 0.0;
      A.finish(p, Ap, [&](std::size_t i, Real api) { pAp += p[i] * api; });
      if (!(pAp > 0.0)) break;  // not positive definite along p (should not happen): keep what we have
      const Real alpha = rz / pAp;
      Real rzNew = 0.0;
      rr = 0.0;
      P.apply(
          r, z,
          [&](std::size_t i) {
            x[i] += alpha * p[i];
            r[i] -= alpha * Ap[i];
          },
          [&](std::size_t i) {
            rzNew += r[i] * z[i];
            rr += r[i] * r[i];
          });
      beta = rzNew / rz;
      rz = rzNew;
      ++stats.iterations;
    }
    for (std::size_t i = 0; i < n; ++i) A.direction(i, x[i]);  // the true residual of the Δv we return
    rr = 0.0;
    A.finish(x, Ap, [&](std::size_t i, Real api) {
      r[i] = b[i] - api;
      rr += r[i] * r[i];
    });
    stats.relativeResidual = std::sqrt(rr) / bNorm;
    stats.converged = stats.relativeResidual <= settings.relativeTolerance;
    if (stats.converged || stats.iterations >= settings.maxIterations) break;
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
