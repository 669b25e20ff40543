// CLOTH-5: the product of the implicit system matrix (suite CLOTH_5_…, which runs CLOTH-5 alone), and the
// implicit Euler cloth that stands on it (suites Cloth…, which also run the spring force, PART-4: in the
// hand-out they are skipped, "needs …", until both are solved). Reference values: second differences of
// the springs' energy and dissipation (the matrix never comes from the code under test), Eigen's direct
// solve of the same linear system, closed forms for the static sag.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "cloth_test_support.h"
#include "physics/cloth/implicit.h"
#include "support/expect_helpers.h"

namespace pba::cloth {
namespace {

using testing::meshGrid;

/// A small cloth with every spring stretched (no compression: the exact Jacobian is the one in use).
Cloth stretchedCloth(std::mt19937& rng) {
  ClothMaterial m;
  m.stretchStiffness = 900.0;
  m.shearStiffness = 400.0;
  m.bendStiffness = 60.0;
  m.springDamping = 0.3;
  Cloth c = meshGrid(4, 0.6, 1.0, GridPins::TopCorners, m);
  std::uniform_real_distribution<Real> u(-0.01, 0.01);
  for (std::size_t i = 0; i < c.size(); ++i) c.position[i] = 1.2 * c.restPosition[i] + Vec3(u(rng), u(rng), u(rng));
  for (Vec3& v : c.velocity) v = Vec3(u(rng), u(rng), u(rng)) * 50.0;
  for (Pin& p : c.pins) {  // pins hold still where they now are
    p.target = c.position[p.particle];
    c.velocity[p.particle] = Vec3(0.0);
  }
  return c;
}

/// Rayleigh's dissipation function of the springs' damping at velocities v (positions x fixed): half the
/// damping coefficient times the squared rate of change of each spring's length, summed. The damping
/// force is minus its gradient in v, so ∂f/∂v is minus its Hessian.
Real dissipation(const Cloth& c, const std::vector<Vec3>& x, const std::vector<Vec3>& v) {
  Real r = 0.0;
  for (const Link& s : c.springs) {
    const Vec3 along = glm::normalize(x[s.j] - x[s.i]);
    const Real rate = glm::dot(along, v[s.j] - v[s.i]);
    r += 0.5 * c.material.springDamping * rate * rate;
  }
  return r;
}

/// The Hessian of a scalar function of the 3n coordinates of `at`, by the four-point central second
/// difference with step eps.
template <class Scalar>
Eigen::MatrixXd hessianByDifferences(const std::vector<Vec3>& at, Real eps, Scalar scalar) {
  const auto n = static_cast<Eigen::Index>(3 * at.size());
  Eigen::MatrixXd H(n, n);
  auto shifted = [&](Eigen::Index a, Real da, Eigen::Index b, Real db) {
    std::vector<Vec3> y = at;
    y[static_cast<std::size_t>(a / 3)][static_cast<int>(a % 3)] += da;
    y[static_cast<std::size_t>(b / 3)][static_cast<int>(b % 3)] += db;
    return scalar(y);
  };
  for (Eigen::Index a = 0; a < n; ++a) {
    for (Eigen::Index b = a; b < n; ++b) {
      H(a, b) = H(b, a) =
          (shifted(a, eps, b, eps) - shifted(a, eps, b, -eps) - shifted(a, -eps, b, eps) + shifted(a, -eps, b, -eps)) /
          (4.0 * eps * eps);
    }
  }
  return H;
}

/// A = (1 + h c) M − h ∂f/∂v − h² ∂f/∂x, with ∂f/∂x = −∇²E of the springs' stored energy (springEnergy,
/// library code; the analytic Jacobian drops the damping force's dependence on x, as Baraff & Witkin do)
/// and ∂f/∂v = −∇²R of Rayleigh's dissipation above. Neither runs the spring force (PART-4).
/// Steps: 3e-5 m for E (rounding ≈ 1e-14 J / ε² ≈ 1e-5 N/m, truncation ≈ ε² ∂⁴E ≈ 1e-5 N/m; both
/// multiplied by h² ≈ 3e-4), 1e-3 m/s for R (quadratic: exact but for rounding).
Eigen::MatrixXd systemByDifferences(const Cloth& c, Real h, Real massDamping) {
  const Eigen::MatrixXd stiffness = hessianByDifferences(
      c.position, 3e-5, [&](const std::vector<Vec3>& x) { return springEnergy(c.springs, c.material, x); });
  const Eigen::MatrixXd damping =
      hessianByDifferences(c.velocity, 1e-3, [&](const std::vector<Vec3>& v) { return dissipation(c, c.position, v); });
  Eigen::MatrixXd A = h * damping + h * h * stiffness;
  for (Eigen::Index k = 0; k < A.rows(); ++k)
    A(k, k) += (1.0 + h * massDamping) * c.mass[static_cast<std::size_t>(k / 3)];
  return A;
}

TEST(CLOTH_5_ImplicitProduct, EqualsTheSystemMatrixBuiltFromSecondDifferencesOfEnergyAndDissipation) {
  std::mt19937 rng(16);
  const Cloth c = stretchedCloth(rng);
  const Real h = 1.0 / 60.0, massDamping = 0.4;
  SpringJacobianSettings exact;
  exact.clampCompressedLateral = false;
  std::vector<SpringJacobian> J;
  springJacobians(c.springs, c.material, c.position, exact, J);
  const Eigen::MatrixXd A = systemByDifferences(c, h, massDamping);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Vec3> y(c.size()), out(c.size());
    Eigen::VectorXd yv(3 * c.size());
    for (std::size_t i = 0; i < c.size(); ++i) {
      y[i] = Vec3(u(rng), u(rng), u(rng));
      yv.segment<3>(3 * static_cast<Eigen::Index>(i)) << y[i].x, y[i].y, y[i].z;
    }
    implicitSystemProduct(J, c.mass, massDamping, h, y, out);
    const Eigen::VectorXd expected = A * yv;
    for (std::size_t i = 0; i < c.size(); ++i) {
      // Second differences (see systemByDifferences): ≈ 1e-8 per entry, summed over a row. A wrong term
      // is far larger: h² k ≈ 0.25, h k_d ≈ 5e-3, h c m ≈ 1e-4 per unit of y.
      const auto k = static_cast<Eigen::Index>(3 * i);
      SCOPED_TRACE(i);
      EXPECT_VEC3_NEAR(out[i], Vec3(expected(k), expected(k + 1), expected(k + 2)), 1e-6);
    }
  }
}

TEST(ClothImplicitStep, VelocityIsEigensDirectSolveOfTheBackwardEulerSystemWithPinsFiltered) {
  std::mt19937 rng(60);
  Cloth c = stretchedCloth(rng);
  const Real h = 1.0 / 60.0;
  ClothEnvironment env;
  env.massDamping = 0.2;
  // Reference: A v₁ = M v₀ + h f_undamped on the free coordinates, v₁ = 0 on the pinned ones.
  const Eigen::MatrixXd A = systemByDifferences(c, h, env.massDamping);
  std::vector<Vec3> f(c.size(), Vec3(0.0));
  accumulateSpringForces(c.springs, c.material, c.position, c.velocity, false, f);
  std::vector<Eigen::Index> free;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.inverseMass[i] == 0.0) continue;
    f[i] += c.mass[i] * env.gravity;
    for (int a = 0; a < 3; ++a) free.push_back(static_cast<Eigen::Index>(3 * i + a));
  }
  const auto nf = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd Af(nf, nf);
  Eigen::VectorXd bf(nf);
  for (Eigen::Index r = 0; r < nf; ++r) {
    const std::size_t i = static_cast<std::size_t>(free[r] / 3);
    const int a = static_cast<int>(free[r] % 3);
    bf(r) = c.mass[i] * c.velocity[i][a] + h * f[i][a];
    for (Eigen::Index col = 0; col < nf; ++col) Af(r, col) = A(free[r], free[col]);
  }
  const Eigen::VectorXd expected = Af.ldlt().solve(bf);

  ImplicitSettings settings;
  settings.cg.tolerance = 1e-12;
  settings.jacobian.clampCompressedLateral = false;
  ImplicitWorkspace w;
  const Cloth before = c;
  const ImplicitStats stats = implicitStep(c, env, {}, settings, h, 0.0, w);
  EXPECT_TRUE(stats.cg.converged);
  for (Eigen::Index r = 0; r < nf; ++r) {
    const std::size_t i = static_cast<std::size_t>(free[r] / 3);
    // The reference matrix comes from central differences of the forces (about 1e-8 relative), and the
    // solution reaches a few m/s: within 1e-7 of its largest component (at least 1e-7 m/s).
    EXPECT_NEAR(c.velocity[i][static_cast<int>(free[r] % 3)], expected(r),
                1e-7 * std::max(1.0, expected.lpNorm<Eigen::Infinity>()))
        << "coordinate " << free[r];
  }
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_VEC3_NEAR(c.position[i], before.position[i] + h * c.velocity[i], 1e-15);
  }
  for (const Pin& p : c.pins) EXPECT_EQ(c.position[p.particle], p.target);
}

/// Frames of a passive cloth hanging from two corners under implicit Euler: the largest energy seen
/// relative to the start, (max E − E₀)/|E₀|, and the last energy.
struct EnergyTrace {
  Real worstGrowth = 0.0, last = 0.0, first = 0.0;
  Real strain = 0.0, lowest = 0.0;
};
EnergyTrace hangImplicit(Real k, int frames) {
  ClothMaterial m;
  m.stretchStiffness = m.shearStiffness = k;
  m.bendStiffness = 0.1 * k;
  m.springDamping = 0.1;
  Cloth c = meshGrid(16, 1.0, 1.5, GridPins::TopCorners, m);
  ClothEnvironment env;
  ClothSolverSettings s;
  s.kind = ClothSolverKind::Implicit;
  s.substeps = 1;
  ClothSolver solver;
  EnergyTrace trace;
  trace.first = clothEnergy(c, env, s.kind);
  Real t = 0.0;
  for (int f = 0; f < frames; ++f) {
    const ClothStepStats stats = solver.step(c, env, {}, s, 1.0 / 60.0, t);
    t += 1.0 / 60.0;
    EXPECT_FALSE(describeNonFinite(c).has_value()) << "frame " << f;
    EXPECT_GT(stats.cgIterations, 0) << "frame " << f;
    trace.last = clothEnergy(c, env, s.kind);
    trace.worstGrowth = std::max(trace.worstGrowth, (trace.last - trace.first) / std::abs(trace.first));
  }
  trace.strain = edgeStrain(c).max;
  trace.lowest = c.position.back().y;
  return trace;
}

TEST(ClothImplicitCloth, EnergyNeverGrowsInAPassiveHangingCloth) {
  const EnergyTrace e = hangImplicit(1e3, 240);
  EXPECT_LE(e.worstGrowth, 0.01);
  EXPECT_LT(e.last, e.first);
  EXPECT_LT(e.lowest, 1.0);  // it did fall
}

TEST(ClothImplicitCloth, StableAndDissipativeAtTheFrameStepWithStiffSpringsWhereExplicitBlowsUp) {
  // k = 10⁵ N/m at h = 1/60 s: ω h ≈ 10³. One Newton step linearises springs that rotate as the cloth
  // falls, which stretches them a little in the first frames (B&W accept it: one step, no line search);
  // measured: +1 % at most, gone after a few frames. Bound 5 %, then the energy must end below E₀.
  const EnergyTrace e = hangImplicit(1e5, 240);
  EXPECT_LE(e.worstGrowth, 0.05);
  EXPECT_LT(e.last, e.first);
  EXPECT_LT(e.strain, 0.01);  // hangs nearly inextensible
  EXPECT_LT(e.lowest, 1.0);
  pba::testing::FloatingPointTrapsOff traps;  // the explicit run overflows on purpose
  ClothMaterial m;
  m.stretchStiffness = m.shearStiffness = 1e5;
  m.bendStiffness = 1e4;
  Cloth c = meshGrid(16, 1.0, 1.5, GridPins::TopCorners, m);
  ClothSolver solver;
  ClothSolverSettings s;
  s.kind = ClothSolverKind::Explicit;
  s.substeps = 1;
  const ClothEnvironment env;
  const Real e0 = clothEnergy(c, env, s.kind);
  testing::run(c, solver, env, {}, s, 1.0 / 60.0, 30);
  const Real blown = clothEnergy(c, env, s.kind);
  EXPECT_TRUE(!std::isfinite(blown) || blown > 100.0 * std::abs(e0));
}

TEST(ClothImplicitChain, SettlesToTheClosedFormStaticSagWithPinsExact) {
  ClothMaterial m;
  m.stretchStiffness = 2e4;  // ω h ≈ 30 at h = 1/60: far beyond any explicit limit
  m.springDamping = 1.0;
  const int n = 8;
  const Real mass = 0.02;
  Cloth c = testing::hangingChain(n, mass, 0.1, 2.0, m);
  const Vec3 top = c.position[0];
  ClothSolverSettings s;
  s.kind = ClothSolverKind::Implicit;
  s.substeps = 1;
  s.implicit.cg.tolerance = 1e-10;
  ClothSolver solver;
  testing::run(c, solver, ClothEnvironment{}, {}, s, 1.0 / 60.0, 600);
  EXPECT_EQ(c.position[0], top);
  for (int k = 1; k < n; ++k) {
    const Real expected = k * mass * kStandardGravity / m.stretchStiffness;  // link k from the bottom
    EXPECT_NEAR(testing::chainExtension(c, static_cast<std::size_t>(n - 1 - k)), expected, 1e-3 * expected)
        << "link " << k;
  }
}

}  // namespace
}  // namespace pba::cloth
