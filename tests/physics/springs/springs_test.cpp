// Mass-spring tests that do not depend on the PART-4 exercise: momentum conservation, the analytic
// Jacobian (stiffness with its compression clamp, damping, diagonal blocks) against finite differences of
// the spring energy and of Rayleigh's dissipation function, builders and their validation.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "physics/ode/integrators.h"
#include "physics/springs/builders.h"
#include "physics/springs/spring_network.h"
#include "support/expect_helpers.h"

namespace pba::springs {
namespace {

particles::ParticleSystem freeLattice(std::uint64_t seed) {
  particles::ParticleSystem sys;
  LatticeDesc desc;
  desc.nx = desc.ny = desc.nz = 4;
  desc.stiffness = 200.0;
  desc.damping = 0.3;
  (void)appendLattice(desc, sys);
  sys.forces.gravity = Vec3(0.0);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<Real> u(-0.5, 0.5);
  for (std::size_t i = 0; i < sys.particles.size(); ++i) {
    sys.particles.velocity[i] = Vec3(u(rng), u(rng), u(rng));
    sys.particles.position[i] += 0.02 * Vec3(u(rng), u(rng), u(rng));
    sys.particles.inverseMass[i] = 1.0 / (0.01 * (1.5 + u(rng)));  // unequal masses
  }
  sys.syncMasses();
  return sys;
}

TEST(SpringNetwork, FreeNetworkConservesMomentumUnderEveryIntegrator) {
  for (ode::IntegratorKind kind : ode::kAllIntegrators) {
    particles::ParticleSystem sys = freeLattice(17);
    const Vec3 p0 = sys.momentum();
    ode::Integrator integrator(kind);
    for (int i = 0; i < 100; ++i) integrator.step(sys, 1e-3);
    // Internal forces cancel in pairs: only rounding remains (|p| ~ 0.1 kg·m/s, 100 steps). Implicit
    // Euler's exact Δv conserves momentum too, but its block-preconditioned CG iterates do not lie in the
    // momentum-free subspace: it conserves momentum to its solve's residual (relative 1e-10 of |b|, per
    // step), observed 9e-12 after 100 steps.
    const Real tolerance = kind == ode::IntegratorKind::ImplicitEuler ? 1e-10 : 1e-12;
    EXPECT_VEC3_NEAR(sys.momentum(), p0, tolerance);
  }
}

/// −∂²Φ/∂a∂b along the coordinate directions e_a and e_b, by the mixed central difference
/// [Φ(+,+) − Φ(+,−) − Φ(−,+) + Φ(−,−)] / (4 ε²): the (a, b) entry of the Jacobian −∂²Φ of a force that
/// is minus the gradient of Φ. Truncation O(ε²), rounding O(1e-16 Φ/ε²).
template <typename Potential>
Real minusMixedSecondDifference(Potential&& phi, std::vector<Real> at, std::size_t a, std::size_t b, Real eps) {
  auto shifted = [&](Real sa, Real sb) {
    std::vector<Real> p = at;
    p[a] += sa;
    p[b] += sb;
    return phi(p);
  };
  return -(shifted(eps, eps) - shifted(eps, -eps) - shifted(-eps, eps) + shifted(-eps, -eps)) / (4.0 * eps * eps);
}

/// The analytic differential applied to e_b: column b of K (dv = 0) or of D (dx = 0).
std::vector<Real> differentialColumn(std::span<const Spring> springs, const std::vector<Vec3>& x, std::size_t b,
                                     bool velocity) {
  std::vector<Vec3> d(x.size(), Vec3(0.0)), zero(x.size(), Vec3(0.0)), out(x.size(), Vec3(0.0));
  d[b / 3][static_cast<int>(b % 3)] = 1.0;
  accumulateSpringDifferential(springs, x, velocity ? zero : d, velocity ? d : zero, out);
  std::vector<Real> column(3 * x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int c = 0; c < 3; ++c) column[3 * i + static_cast<std::size_t>(c)] = out[i][c];
  return column;
}

std::vector<Real> flatten(const std::vector<Vec3>& x) {
  std::vector<Real> f;
  for (const Vec3& p : x) f.insert(f.end(), {p.x, p.y, p.z});
  return f;
}
std::vector<Vec3> unflatten(const std::vector<Real>& f) {
  std::vector<Vec3> x(f.size() / 3);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = Vec3(f[3 * i], f[3 * i + 1], f[3 * i + 2]);
  return x;
}

TEST(SpringNetwork, TheStiffnessJacobianOfStretchedSpringsIsMinusTheHessianOfTheSpringEnergy) {
  // Independent reference: the spring energy Σ k (l − L)²/2 (springPotentialEnergy), differentiated twice
  // by mixed central differences, for every entry of K on a stretched lattice (every (1 − L/l) > 0, so the
  // definiteness clamp is inactive and K is the exact Jacobian of the elastic force −∇U).
  particles::ParticleSystem sys = freeLattice(4);
  for (Vec3& x : sys.particles.position) x *= 1.1;
  sys.particles.position.resize(8);  // the first 8 particles and their springs: 24 × 24 entries
  std::vector<Spring> springs;
  for (const Spring& s : sys.springs)
    if (s.i < 8 && s.j < 8) springs.push_back(s);
  ASSERT_GT(springs.size(), 8u);
  const std::vector<Vec3>& x = sys.particles.position;
  auto energy = [&](const std::vector<Real>& f) { return springPotentialEnergy(springs, unflatten(f)); };
  const std::vector<Real> at = flatten(x);
  for (std::size_t b = 0; b < at.size(); ++b) {
    const std::vector<Real> column = differentialColumn(springs, x, b, false);
    for (std::size_t a = 0; a < at.size(); ++a) {
      // k ≈ 200 N/m, U ≈ 2 J, springs 0.22 m, ε = 3e-5 m: truncation ≈ k (2ε/l)²/12 ≈ 1e-5 N/m (observed
      // 1.5e-4 at ε = 1e-4), rounding ≈ 1e-16 U/ε² ≈ 3e-7 N/m.
      EXPECT_NEAR(column[a], minusMixedSecondDifference(energy, at, a, b, 3e-5), 5e-5) << "entry " << a << ", " << b;
    }
  }
}

TEST(SpringNetwork, UnderCompressionTheLateralStiffnessIsClampedToZeroAndTheAxialOneIsExact) {
  // One spring compressed to l = 0.6 L. The energy's Hessian along the spring is k; across it
  // k (1 − L/l) < 0 (a compressed spring buckles sideways: K_s would be indefinite). The Jacobian keeps
  // the axial part and clamps the lateral one to 0 (Choi & Ko 2002), which the differences confirm.
  const std::vector<Spring> springs{{0, 1, 1.0, 300.0, 0.0}};
  const Vec3 n = glm::normalize(Vec3(1.0, 2.0, -0.5));
  const std::vector<Vec3> x{Vec3(0.1, 0.2, 0.3), Vec3(0.1, 0.2, 0.3) + 0.6 * n};
  // Directional second differences along u (on particle 1): −d²U/dε² = uᵀ K_true u.
  auto exactCurvature = [&](const Vec3& u) {
    const Real eps = 1e-4;
    auto at = [&](Real s) {
      std::vector<Vec3> p = x;
      p[1] += s * u;
      return springPotentialEnergy(springs, p);
    };
    return (at(eps) - 2.0 * at(0.0) + at(-eps)) / (eps * eps);
  };
  auto analytic = [&](const Vec3& u) {  // uᵀ (∂F₁/∂x₁) u = −uᵀ K_s u
    std::vector<Vec3> d{Vec3(0.0), u}, zero(2, Vec3(0.0)), out(2, Vec3(0.0));
    accumulateSpringDifferential(springs, x, d, zero, out);
    return glm::dot(u, out[1]);
  };
  const Vec3 across = glm::normalize(glm::cross(n, Vec3(0.0, 0.0, 1.0)));
  EXPECT_NEAR(-analytic(n), exactCurvature(n), 1e-3);          // axial: k = 300 N/m, exact
  EXPECT_NEAR(exactCurvature(across), 300.0 * (1.0 - 1.0 / 0.6), 1e-3);  // the true lateral stiffness < 0
  EXPECT_NEAR(analytic(across), 0.0, 1e-12);                  // clamped to 0
}

TEST(SpringNetwork, TheDampingJacobianIsMinusTheHessianOfTheRayleighDissipationFunction) {
  // The damping force of a spring derives from Rayleigh's dissipation function
  // R(v) = Σ k_d (r̂·(v_j − v_i))²/2 as F = −∂R/∂v, so ∂F/∂v = −∂²R/∂v²: compared entry by entry (mixed
  // central differences of R, exact for a quadratic up to rounding) with the analytic differential.
  particles::ParticleSystem sys = freeLattice(6);
  sys.particles.position.resize(6);
  std::vector<Spring> springs;
  for (const Spring& s : sys.springs)
    if (s.i < 6 && s.j < 6) springs.push_back(s);
  const std::vector<Vec3>& x = sys.particles.position;
  auto rayleigh = [&](const std::vector<Real>& f) {
    const std::vector<Vec3> v = unflatten(f);
    Real r = 0.0;
    for (const Spring& s : springs) {
      const Real rate = glm::dot(glm::normalize(x[s.j] - x[s.i]), v[s.j] - v[s.i]);
      r += 0.5 * s.damping * rate * rate;
    }
    return r;
  };
  const std::vector<Real> at(3 * x.size(), 0.1);
  for (std::size_t b = 0; b < at.size(); ++b) {
    const std::vector<Real> column = differentialColumn(springs, x, b, true);
    for (std::size_t a = 0; a < at.size(); ++a) {
      EXPECT_NEAR(column[a], minusMixedSecondDifference(rayleigh, at, a, b, 1e-3), 1e-9) << "entry " << a << ", " << b;
    }
  }
}

TEST(SpringNetwork, TheDiagonalJacobianBlocksAreTheDifferentialsDiagonalBlocks) {
  // What implicit Euler's preconditioner reads (accumulateSpringJacobianDiagonal) against the matrix-free
  // differential probed coordinate by coordinate, on a lattice with stretched and compressed springs.
  particles::ParticleSystem sys = freeLattice(9);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<Real> u(0.7, 1.3);
  for (Spring& s : sys.springs) s.restLength *= u(rng);
  const std::vector<Vec3>& x = sys.particles.position;
  std::vector<Mat3> dfdx(x.size(), Mat3(0.0)), dfdv(x.size(), Mat3(0.0));
  accumulateSpringJacobianDiagonal(sys.springs, x, dfdx, dfdv);
  for (std::size_t b = 0; b < 3 * x.size(); ++b) {
    const std::vector<Real> k = differentialColumn(sys.springs, x, b, false);
    const std::vector<Real> d = differentialColumn(sys.springs, x, b, true);
    const std::size_t i = b / 3;
    const int c = static_cast<int>(b % 3);
    for (int r = 0; r < 3; ++r) {
      EXPECT_NEAR(dfdx[i][c][r], k[3 * i + static_cast<std::size_t>(r)], 1e-10) << "particle " << i;
      EXPECT_NEAR(dfdv[i][c][r], d[3 * i + static_cast<std::size_t>(r)], 1e-12) << "particle " << i;
    }
  }
}

TEST(Builders, BuildTheRequestedTopology) {
  particles::ParticleSystem sys;
  RopeDesc rope;
  rope.segments = 8;
  rope.bending = true;
  ASSERT_TRUE(appendRope(rope, sys).ok());
  EXPECT_EQ(sys.particles.size(), 9u);
  EXPECT_EQ(sys.springs.size(), 8u + 7u);
  EXPECT_EQ(sys.particles.inverseMass[0], 0.0);  // pinned start
  LatticeDesc lattice;
  lattice.nx = 3;
  lattice.ny = 2;
  lattice.nz = 2;
  lattice.shear = false;
  const auto first = appendLattice(lattice, sys);
  ASSERT_TRUE(first.ok());
  EXPECT_EQ(first.value(), 9u);
  EXPECT_EQ(sys.particles.size(), 9u + 12u);
  // Structural springs of a 3×2×2 grid: 2·2·2 + 3·1·2 + 3·2·1 = 20.
  EXPECT_EQ(sys.springs.size(), 15u + 20u);
  BlobDesc blob;
  ASSERT_TRUE(appendBlob(blob, sys).ok());
  EXPECT_EQ(sys.dofCount(), 3 * sys.particles.size());
  for (const Spring& s : sys.springs) EXPECT_GT(s.restLength, 0.0);
}

TEST(Builders, ValidationNamesTheOffendingField) {
  particles::ParticleSystem sys;
  RopeDesc rope;
  rope.segments = 0;
  EXPECT_NE(appendRope(rope, sys).error().find("rope.segments"), std::string::npos);
  rope = RopeDesc{};
  rope.stiffness = -1.0;
  EXPECT_NE(appendRope(rope, sys).error().find("rope.stiffness"), std::string::npos);
  LatticeDesc lattice;
  lattice.spacing = std::nan("");
  EXPECT_NE(appendLattice(lattice, sys).error().find("lattice.spacing"), std::string::npos);
  BlobDesc blob;
  blob.neighbours = 1000;
  EXPECT_NE(appendBlob(blob, sys).error().find("blob.neighbours"), std::string::npos);
  EXPECT_TRUE(sys.particles.empty());
}

}  // namespace
}  // namespace pba::springs
