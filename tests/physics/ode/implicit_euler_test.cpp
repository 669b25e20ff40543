// Implicit Euler (Baraff & Witkin 1998) on mass-spring systems: the preconditioned CG solution against a
// dense direct solve (Eigen), the step against the closed-form solution of one spring's linear system,
// what the statistics report, and the block-Jacobi preconditioner's effect. The force f₀ is read from the
// system itself, so these tests check the solve, whatever the spring force (PART-4) is.
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "physics/ode/integrators.h"
#include "physics/ode/oscillator.h"
#include "physics/particles/particle_system.h"
#include "physics/springs/builders.h"
#include "support/expect_helpers.h"

namespace pba::ode {
namespace {

/// 11 particles, the first pinned (30 free coordinates), springs along a chain and across it with rest
/// lengths from 0.6× to 1.4× their length (so that some are compressed and the definiteness clamp
/// acts), spring damping, linear and quadratic drag, random velocities.
particles::ParticleSystem thirtyDofSystem() {
  std::mt19937_64 rng(30);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  particles::ParticleSystem sys;
  for (int i = 0; i < 11; ++i) {
    sys.particles.add(Vec3(0.3 * i, 1.0 + 0.1 * u(rng), 0.1 * u(rng)), Vec3(u(rng), u(rng), u(rng)),
                      i == 0 ? 0.0 : 0.05 * (1.5 + u(rng)));
  }
  for (std::uint32_t i = 0; i < 11; ++i) {
    for (std::uint32_t j : {i + 1, i + 2, i + 4}) {
      if (j >= 11) continue;
      const Real length = glm::length(sys.particles.position[j] - sys.particles.position[i]);
      sys.springs.push_back({i, j, length * (1.0 + 0.4 * u(rng)), 500.0 * (1.5 + u(rng)), 0.5 * (1.0 + u(rng))});
    }
  }
  sys.forces.drag.linear = 0.02;
  sys.forces.drag.quadratic = 0.01;
  sys.syncMasses();
  return sys;
}

/// The system matrix A = M − h D − h² K and right-hand side b = h f₀ + h² K v₀ of one step, restricted to
/// the free coordinates, assembled densely from the system's force and force differential (each column
/// of K and D probed by a unit direction).
struct DenseStep {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  std::vector<std::size_t> free;  // coordinate of each row
};
DenseStep assemble(particles::ParticleSystem& sys, Real h) {
  const std::size_t n = sys.dofCount();
  const std::span<const Real> q = sys.positions(), v = sys.velocities(), w = sys.inverseMasses();
  DenseStep d;
  for (std::size_t i = 0; i < n; ++i)
    if (w[i] > 0.0) d.free.push_back(i);
  const auto m = static_cast<Eigen::Index>(d.free.size());
  d.A.resize(m, m);
  d.b.resize(m);
  std::vector<Real> f(n), dq(n, 0.0), dv(n, 0.0), out(n);
  for (Eigen::Index c = 0; c < m; ++c) {
    std::fill(dq.begin(), dq.end(), 0.0);
    std::fill(dv.begin(), dv.end(), 0.0);
    dq[d.free[c]] = h * h;
    dv[d.free[c]] = h;
    sys.forceDifferential(0.0, q, v, dq, dv, out);
    for (Eigen::Index r = 0; r < m; ++r) {
      d.A(r, c) = (r == c ? 1.0 / w[d.free[r]] : 0.0) - out[d.free[r]];
    }
  }
  sys.force(0.0, q, v, f);
  for (std::size_t i = 0; i < n; ++i) dq[i] = h * h * v[i];
  std::fill(dv.begin(), dv.end(), 0.0);
  sys.forceDifferential(0.0, q, v, dq, dv, out);
  for (Eigen::Index r = 0; r < m; ++r) d.b(r) = h * f[d.free[r]] + out[d.free[r]];
  return d;
}

TEST(ImplicitEuler, TheConjugateGradientSolutionMatchesADenseDirectSolveOnThirtyDegreesOfFreedom) {
  particles::ParticleSystem sys = thirtyDofSystem();
  const Real h = 1.0 / 60.0;
  const DenseStep dense = assemble(sys, h);
  ASSERT_EQ(dense.b.size(), 30);
  // A is symmetric positive definite (springs' clamp): Eigen's Cholesky (LLT) must succeed.
  ASSERT_LT((dense.A - dense.A.transpose()).norm(), 1e-12 * dense.A.norm());
  const Eigen::LLT<Eigen::MatrixXd> llt(dense.A);
  ASSERT_EQ(llt.info(), Eigen::Success);
  const Eigen::VectorXd expected = llt.solve(dense.b);

  const std::vector<Real> q0(sys.positions().begin(), sys.positions().end());
  const std::vector<Real> v0(sys.velocities().begin(), sys.velocities().end());
  Integrator integrator(IntegratorKind::ImplicitEuler);
  ASSERT_TRUE(integrator.setImplicitSettings({.maxIterations = 200, .relativeTolerance = 1e-12}).ok());
  integrator.step(sys, h);
  const ImplicitEulerStats& stats = integrator.lastImplicitStats();
  EXPECT_TRUE(stats.converged);
  EXPECT_FALSE(stats.direct);  // springs couple the particles
  EXPECT_TRUE(stats.blockPreconditioner);
  EXPECT_LE(stats.relativeResidual, 1e-12);
  EXPECT_LE(stats.iterations, 30);  // CG is exact in n steps (in exact arithmetic)
  // |Δv − Δv*| ≤ cond(A) · residual · |Δv*|; cond(A) of this system is < 10³.
  const Real scale = expected.norm();
  for (std::size_t r = 0; r < dense.free.size(); ++r) {
    const std::size_t i = dense.free[r];
    EXPECT_NEAR(sys.velocities()[i] - v0[i], expected(static_cast<Eigen::Index>(r)), 1e-8 * scale)
        << "coordinate " << i;
    EXPECT_NEAR(sys.positions()[i], q0[i] + h * sys.velocities()[i], 1e-14) << "coordinate " << i;
  }
  for (std::size_t i = 0; i < 3; ++i) {  // the pinned particle: Δv = 0, it moves on kinematically
    EXPECT_EQ(sys.velocities()[i], v0[i]);
    EXPECT_NEAR(sys.positions()[i], q0[i] + h * v0[i], 1e-15);
  }
  EXPECT_EQ(sys.time(), h);
}

// Without springs the particles are uncoupled: implicit Euler solves each particle's 3 × 3 block directly.
// Its step against Eigen's dense solve of the whole system, assembled from force() and forceDifferential()
// (not from the blocks the direct path reads): 200 particles, so the pass runs over several blocks and a
// partial last one, with every field and quadratic drag (whose blocks are full 3 × 3) and a pinned particle.
TEST(ImplicitEuler, AnUncoupledParticleSystemIsSolvedDirectlyAndMatchesADenseSolve) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  particles::ParticleSystem sys;
  for (int i = 0; i < 200; ++i) {
    sys.particles.add(Vec3(u(rng), 1.0 + u(rng), u(rng)), Vec3(3.0 * u(rng), 3.0 * u(rng), 3.0 * u(rng)),
                      i == 7 ? 0.0 : 0.05 * (1.5 + u(rng)));
  }
  sys.forces.drag.linear = 0.05;
  sys.forces.drag.quadratic = 0.03;
  sys.forces.wind.base = Vec3(2.0, 0.0, 1.0);
  sys.forces.wind.gust = 0.5;
  sys.forces.attractors.push_back({Vec3(0.0, 1.0, 0.0), 0.3, 0.2});
  sys.forces.vortices.push_back({Vec3(0.0), Vec3(0.0, 1.0, 0.0), 0.5, 0.3});
  sys.syncMasses();
  ASSERT_EQ(sys.uncoupledGroupSize(), 3);
  const Real h = 1.0 / 30.0;
  const DenseStep dense = assemble(sys, h);
  const Eigen::VectorXd expected = dense.A.partialPivLu().solve(dense.b);
  const std::vector<Real> q0(sys.positions().begin(), sys.positions().end());
  const std::vector<Real> v0(sys.velocities().begin(), sys.velocities().end());
  Integrator integrator(IntegratorKind::ImplicitEuler);
  integrator.step(sys, h);
  const ImplicitEulerStats& stats = integrator.lastImplicitStats();
  EXPECT_TRUE(stats.direct);
  EXPECT_EQ(stats.iterations, 0);
  for (std::size_t r = 0; r < dense.free.size(); ++r) {
    const std::size_t i = dense.free[r];
    const Real want = expected(static_cast<Eigen::Index>(r));
    EXPECT_NEAR(sys.velocities()[i] - v0[i], want, 1e-13 * (1.0 + std::abs(want))) << "coordinate " << i;
    EXPECT_NEAR(sys.positions()[i], q0[i] + h * sys.velocities()[i], 1e-14) << "coordinate " << i;
  }
  for (std::size_t i = 21; i < 24; ++i) {  // particle 7, pinned: Δv = 0
    EXPECT_EQ(sys.velocities()[i], v0[i]);
    EXPECT_NEAR(sys.positions()[i], q0[i] + h * v0[i], 1e-15);
  }
  EXPECT_EQ(sys.time(), h);
}

// The oscillators are independent coordinates: one step is backward Euler's closed form for ẍ = −ω² x,
// v₁ = (v₀ − h ω² x₀)/(1 + h² ω²), x₁ = x₀ + h v₁.
TEST(ImplicitEuler, TheIndependentOscillatorsStepIsTheClosedFormOfBackwardEuler) {
  OscillatorDesc d;
  d.mass = 0.5;
  d.stiffness = 8.0;
  d.x0 = 0.7;
  d.v0 = -1.3;
  d.copies = 401;  // a partial last block
  HarmonicOscillator osc(d);
  const Real h = 0.05, w2 = d.stiffness / d.mass;
  Integrator integrator(IntegratorKind::ImplicitEuler);
  Real x = d.x0, v = d.v0;
  for (int step = 0; step < 20; ++step) {
    integrator.step(osc, h);
    v = (v - h * w2 * x) / (1.0 + h * h * w2);
    x += h * v;
  }
  EXPECT_TRUE(integrator.lastImplicitStats().direct);
  for (std::size_t i = 0; i < osc.dofCount(); i += 100) {
    EXPECT_NEAR(osc.positions()[i], x, 1e-14) << i;
    EXPECT_NEAR(osc.velocities()[i], v, 1e-14) << i;
  }
}

TEST(ImplicitEuler, OneSpringStepEqualsTheClosedFormSolutionOfItsLinearSystem) {
  // Particle 0 pinned at the origin, particle 1 free at x with velocity v, one spring (k, L, k_d). The
  // free particle's block: A = m I + h K_d + h² K_s with K_s = k (n nᵀ + λ (I − n nᵀ)), K_d = k_d n nᵀ,
  // λ = max(0, 1 − L/l) (spring_network.h), i.e. A = α∥ n nᵀ + α⊥ (I − n nᵀ) with α∥ = m + h k_d + h² k,
  // α⊥ = m + h² k λ, whose inverse is n nᵀ/α∥ + (I − n nᵀ)/α⊥. b = h f₀ − h² K_s v.
  for (const Real restLength : {0.6, 1.4}) {  // stretched (λ > 0) and compressed (λ clamped to 0)
    SCOPED_TRACE(::testing::Message() << "rest length " << restLength);
    particles::ParticleSystem sys;
    sys.particles.add(Vec3(0.0), Vec3(0.0), 0.0);
    const Vec3 x{0.6, -0.7, 0.2}, v{0.3, 1.1, -0.4};
    const Real m = 0.2, k = 800.0, kd = 1.5, h = 0.02;
    sys.particles.add(x, v, m);
    sys.springs.push_back({0, 1, restLength, k, kd});
    sys.syncMasses();
    std::vector<Real> f(6);
    sys.force(0.0, sys.positions(), sys.velocities(), f);
    const Vec3 f0{f[3], f[4], f[5]};
    const Real l = glm::length(x);
    const Vec3 n = x / l;
    const Real lambda = std::max(0.0, 1.0 - restLength / l);
    const Mat3 nn = glm::outerProduct(n, n), I(1.0);
    const Mat3 Ks = k * (nn + lambda * (I - nn));
    const Vec3 b = h * f0 - h * h * (Ks * v);
    const Real alongA = m + h * kd + h * h * k, acrossA = m + h * h * k * lambda;
    const Vec3 dv = glm::dot(n, b) * n / alongA + (b - glm::dot(n, b) * n) / acrossA;

    Integrator integrator(IntegratorKind::ImplicitEuler);
    integrator.step(sys, h);
    // The block preconditioner is A⁻¹ itself here: one iteration. Tolerance: rounding of |Δv| ≈ 1 m/s.
    EXPECT_EQ(integrator.lastImplicitStats().iterations, 1);
    EXPECT_TRUE(integrator.lastImplicitStats().converged);
    EXPECT_VEC3_NEAR(sys.particles.velocity[1], v + dv, 1e-12);
    EXPECT_VEC3_NEAR(sys.particles.position[1], x + h * (v + dv), 1e-12);
    EXPECT_VEC3_NEAR(sys.particles.position[0], Vec3(0.0), 0.0);
  }
}

TEST(ImplicitEuler, AnIterationCapBelowWhatTheToleranceNeedsIsReportedAsNotConverged) {
  particles::ParticleSystem sys = thirtyDofSystem();
  Integrator integrator(IntegratorKind::ImplicitEuler);
  ASSERT_TRUE(integrator.setImplicitSettings({.maxIterations = 2, .relativeTolerance = 1e-10}).ok());
  integrator.step(sys, 1.0 / 60.0);
  const ImplicitEulerStats& stats = integrator.lastImplicitStats();
  EXPECT_EQ(stats.iterations, 2);
  EXPECT_FALSE(stats.converged);
  EXPECT_GT(stats.relativeResidual, 1e-10);
  EXPECT_LT(stats.relativeResidual, 1.0);  // two iterations still reduced the residual
}

/// The same system without its Jacobian blocks: implicit Euler falls back to the mass (Jacobi)
/// preconditioner. Forwards everything else to the wrapped system.
class WithoutJacobianBlocks final : public SecondOrderSystem {
 public:
  explicit WithoutJacobianBlocks(particles::ParticleSystem& s) : s_(s) {}
  std::size_t dofCount() const override { return s_.dofCount(); }
  std::span<Real> positions() override { return s_.positions(); }
  std::span<const Real> positions() const override { return std::as_const(s_).positions(); }
  std::span<Real> velocities() override { return s_.velocities(); }
  std::span<const Real> velocities() const override { return std::as_const(s_).velocities(); }
  std::span<const Real> inverseMasses() const override { return s_.inverseMasses(); }
  void force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const override {
    s_.force(t, q, v, out);
  }
  void forceDifferential(Real t, std::span<const Real> q, std::span<const Real> v, std::span<const Real> dq,
                         std::span<const Real> dv, std::span<Real> out) override {
    s_.forceDifferential(t, q, v, dq, dv, out);
  }

 private:
  particles::ParticleSystem& s_;
};

TEST(ImplicitEuler, TheBlockPreconditionerNeedsFewerIterationsThanTheMassOnAStiffBeamAndBothMeetTheTolerance) {
  // The stiff-spring scene's beam (10 × 3 × 3 lattice, k = 1e5 N/m, 0.05 kg, one end pinned) at its step.
  springs::LatticeDesc beam{Vec3(-1.0, 2.0, -0.2), 10, 3, 3, 0.2, 0.05, 1e5, 1.0, true, false};
  particles::ParticleSystem block;
  ASSERT_TRUE(springs::appendLattice(beam, block).ok());
  for (std::size_t i = 0; i < 9; ++i) block.particles.inverseMass[i] = 0.0;
  block.syncMasses();
  particles::ParticleSystem mass = block;
  WithoutJacobianBlocks massOnly(mass);
  Integrator withBlocks(IntegratorKind::ImplicitEuler), withMass(IntegratorKind::ImplicitEuler);
  int blockIterations = 0, massIterations = 0;
  for (int step = 0; step < 60; ++step) {
    withBlocks.step(block, 1.0 / 120.0);
    withMass.step(massOnly, 1.0 / 120.0);
    ASSERT_TRUE(withBlocks.lastImplicitStats().converged) << "step " << step;
    ASSERT_TRUE(withMass.lastImplicitStats().converged) << "step " << step;
    EXPECT_FALSE(withMass.lastImplicitStats().blockPreconditioner);
    blockIterations += withBlocks.lastImplicitStats().iterations;
    massIterations += withMass.lastImplicitStats().iterations;
  }
  EXPECT_LT(blockIterations, massIterations);
  // Both solved the same systems to 1e-10: the beams agree to far better than a micrometre.
  for (std::size_t i = 0; i < block.particles.size(); ++i) {
    EXPECT_VEC3_NEAR(block.particles.position[i], mass.particles.position[i], 1e-6);
  }
}

}  // namespace
}  // namespace pba::ode
