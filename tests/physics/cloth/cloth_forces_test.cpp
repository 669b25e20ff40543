// Spring forces of the mass-spring cloth and their analytic Jacobians against central differences.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "cloth_test_support.h"
#include "physics/cloth/forces.h"
#include "support/expect_helpers.h"

namespace pba::cloth {
namespace {

/// Force on both ends of one spring of `kind` (elastic + damping) at (x, v).
std::array<Vec3, 2> springForce(const Link& link, const ClothMaterial& m, const std::array<Vec3, 2>& x,
                                const std::array<Vec3, 2>& v) {
  std::array<Vec3, 2> f{Vec3(0.0), Vec3(0.0)};
  const Link local{0, 1, link.restLength, link.kind};
  accumulateSpringForces(std::span(&local, 1), m, x, v, true, f);
  return f;
}

ClothMaterial distinctStiffness() {
  ClothMaterial m;
  m.stretchStiffness = 800.0;
  m.shearStiffness = 300.0;
  m.bendStiffness = 40.0;
  m.springDamping = 0.7;
  return m;
}

// Central differences: truncation O(k ε²/l²), rounding O(1e-16 k/ε): ε = 1e-6 gives ≈ 1e-8 relative.
constexpr Real kStep = 1e-6;

TEST(SpringJacobian, MatchesCentralDifferencesForEverySpringKindStretchedAndCompressed) {
  const ClothMaterial m = distinctStiffness();
  std::mt19937 rng(14);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  SpringJacobianSettings exact;
  exact.clampCompressedLateral = false;  // the exact Jacobian, for the comparison
  for (LinkKind kind : {LinkKind::Stretch, LinkKind::Shear, LinkKind::Bend}) {
    for (Real rest : {0.5, 2.0}) {  // the random pair is ~1.4 m apart: stretched, then compressed
      for (int trial = 0; trial < 20; ++trial) {
        const std::array<Vec3, 2> x{Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)) + Vec3(1.0, 0.0, 0.0)};
        const std::array<Vec3, 2> v{Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng))};
        const Link link{0, 1, rest, kind};
        std::vector<SpringJacobian> J;
        springJacobians(std::span(&link, 1), m, x, exact, J);
        const Mat3 K = stiffnessBlock(J[0]), D = dampingBlock(J[0]);
        for (int a = 0; a < 3; ++a) {
          // ∂f_i/∂x_j column a (damping's x-dependence excluded: evaluate at v = 0).
          std::array<Vec3, 2> xp = x, xm = x;
          xp[1][a] += kStep;
          xm[1][a] -= kStep;
          const std::array<Vec3, 2> zero{Vec3(0.0), Vec3(0.0)};
          const Vec3 dfdx = (springForce(link, m, xp, zero)[0] - springForce(link, m, xm, zero)[0]) / (2.0 * kStep);
          EXPECT_VEC3_NEAR(K[a], dfdx, 1e-6 * m.stretchStiffness);
          // ∂f_i/∂x_i = −K_s.
          xp = x;
          xm = x;
          xp[0][a] += kStep;
          xm[0][a] -= kStep;
          const Vec3 dfdxi = (springForce(link, m, xp, zero)[0] - springForce(link, m, xm, zero)[0]) / (2.0 * kStep);
          EXPECT_VEC3_NEAR(-K[a], dfdxi, 1e-6 * m.stretchStiffness);
          // ∂f_i/∂v_j column a (no truncation error: the force is linear in v).
          std::array<Vec3, 2> vp = v, vm = v;
          vp[1][a] += kStep;
          vm[1][a] -= kStep;
          const Vec3 dfdv = (springForce(link, m, x, vp)[0] - springForce(link, m, x, vm)[0]) / (2.0 * kStep);
          EXPECT_VEC3_NEAR(D[a], dfdv, 1e-6);  // rounding of ~10³ N forces over ε = 10⁻⁶
        }
      }
    }
  }
}

TEST(SpringJacobian, ClampedBlockIsSymmetricPositiveSemidefiniteUnderCompression) {
  const ClothMaterial m = distinctStiffness();
  const std::array<Vec3, 2> x{Vec3(0.0), Vec3(0.3, 0.4, 0.0)};  // length 0.5 < rest 1: compressed
  const Link link{0, 1, 1.0, LinkKind::Stretch};
  std::vector<SpringJacobian> J;
  springJacobians(std::span(&link, 1), m, x, SpringJacobianSettings{}, J);
  const Mat3 K = stiffnessBlock(J[0]);
  EXPECT_EQ(J[0].lateral, 0.0);
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) EXPECT_DOUBLE_EQ(K[a][b], K[b][a]);
  }
  // Only the axial stiffness remains: K = k n nᵀ, eigenvalues k, 0, 0.
  const Vec3 n(0.6, 0.8, 0.0);
  EXPECT_VEC3_NEAR(K * n, m.stretchStiffness * n, 1e-12);
  EXPECT_VEC3_NEAR(K * Vec3(0.0, 0.0, 1.0), Vec3(0.0), 1e-12);
}

TEST(SpringForces, AreMinusTheGradientOfTheSpringEnergyOnAClothAndConserveMomentum) {
  ClothMaterial m = distinctStiffness();
  Cloth c = testing::meshGrid(4, 1.0, 1.0, GridPins::None, m);
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(-0.05, 0.05);
  for (Vec3& x : c.position) x += Vec3(u(rng), u(rng), u(rng));
  std::vector<Vec3> f(c.size(), Vec3(0.0)), v(c.size(), Vec3(0.0));
  accumulateSpringForces(c.springs, m, c.position, v, false, f);
  Vec3 total(0.0);
  for (std::size_t i = 0; i < c.size(); ++i) {
    total += f[i];
    for (int a = 0; a < 3; ++a) {
      std::vector<Vec3> xp = c.position, xm = c.position;
      xp[i][a] += kStep;
      xm[i][a] -= kStep;
      const Real dE = (springEnergy(c.springs, m, xp) - springEnergy(c.springs, m, xm)) / (2.0 * kStep);
      EXPECT_NEAR(f[i][a], -dE, 1e-6) << "particle " << i << " axis " << a;
    }
  }
  EXPECT_VEC3_NEAR(total, Vec3(0.0), 1e-10);
}

TEST(ExternalForces, GravityAndMassDampingActOnFreeParticlesOnly) {
  Cloth c = testing::meshGrid(3, 1.0, 1.0, GridPins::TopCorners);
  ClothEnvironment env;
  env.massDamping = 0.5;
  for (Vec3& v : c.velocity) v = Vec3(1.0, 0.0, 0.0);
  std::vector<Vec3> f(c.size(), Vec3(0.0));
  accumulateExternalForces(c, env, 0.0, c.position, c.velocity, f);
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Vec3 expected = c.inverseMass[i] == 0.0 ? Vec3(0.0) : c.mass[i] * (env.gravity - 0.5 * c.velocity[i]);
    EXPECT_VEC3_NEAR(f[i], expected, 1e-15);
  }
}

TEST(ExplicitStabilityLimit, BoundsTheStepAtWhichSymplecticEulerOnTheClothStaysBounded) {
  ClothMaterial m;
  m.stretchStiffness = m.shearStiffness = 1e4;
  m.bendStiffness = 1e3;
  m.springDamping = 0.0;
  const Cloth c = testing::meshGrid(8, 0.5, 1.0, GridPins::None, m);
  const Real limit = explicitStabilityLimit(c);
  // Gershgorin bound ω_max² ≤ max 2 Σk/m: 2/ω from it is a lower bound of the true limit. Check both
  // sides: a kick decays or stays bounded at half the bound, blows up at 4× the true ceiling 2/√(λ_max).
  auto grows = [&](Real h) {
    Cloth s = c;
    s.velocity[10] = Vec3(0.0, 0.0, 0.1);
    ClothEnvironment env;
    env.gravity = Vec3(0.0);
    ClothSolverSettings settings;
    settings.kind = ClothSolverKind::Explicit;
    settings.substeps = 1;
    ClothSolver solver;
    const Real e0 = clothEnergy(s, env, settings.kind);
    for (int k = 0; k < 400; ++k) {
      solver.step(s, env, {}, settings, h, k * h);
      if (!(clothEnergy(s, env, settings.kind) < 1e6 * e0)) return true;
    }
    return false;
  };
  pba::testing::FloatingPointTrapsOff traps;  // the unstable run overflows on purpose
  EXPECT_FALSE(grows(0.5 * limit));
  EXPECT_TRUE(grows(8.0 * limit));
}

}  // namespace
}  // namespace pba::cloth
