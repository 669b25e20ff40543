// CLOTH-2: the XPBD distance constraint (Macklin et al. 2016) and what stands on it: PBD/XPBD cloth and
// chains. Reference values: closed forms (a compliant constraint at rest stretches like a spring of
// stiffness 1/α), geometry, and conservation.
#include <cmath>

#include <gtest/gtest.h>

#include "cloth_test_support.h"
#include "physics/cloth/xpbd.h"
#include "support/expect_helpers.h"

namespace pba::cloth {
namespace {

using testing::chainExtension;
using testing::hangingChain;
using testing::meshGrid;
using testing::run;

ClothSolverSettings positionBased(ClothSolverKind kind, int substeps, int iterations) {
  ClothSolverSettings s;
  s.kind = kind;
  s.substeps = substeps;
  s.iterations = iterations;
  return s;
}

TEST(CLOTH_2_XpbdDistance, WithZeroComplianceOneProjectionRestoresTheLengthSplitByInverseMass) {
  const Vec3 xi(0.0, 0.0, 0.0), xj(2.0, 0.0, 0.0);  // 2 m apart, rest length 1.5
  const DistanceCorrection c = xpbdDistanceCorrection(xi, xj, 1.0, 3.0, 1.5, 0.0, 0.01, 0.0);
  EXPECT_NEAR(glm::length((xi + c.deltaI) - (xj + c.deltaJ)), 1.5, 1e-14);
  // The lighter particle j (w = 3) moves three times as far: 0.125 and 0.375 m towards each other.
  EXPECT_VEC3_NEAR(c.deltaI, Vec3(0.125, 0.0, 0.0), 1e-14);
  EXPECT_VEC3_NEAR(c.deltaJ, Vec3(-0.375, 0.0, 0.0), 1e-14);
  // Momentum-like balance: m_i Δx_i + m_j Δx_j = 0.
  EXPECT_VEC3_NEAR(c.deltaI / 1.0 + c.deltaJ / 3.0, Vec3(0.0), 1e-15);
}

TEST(CLOTH_2_XpbdDistance, ComplianceSoftensTheCorrectionByTheScaledComplianceAndAccumulatesLambda) {
  // One particle (w = 1) on a pinned one, stretched by 0.1 m; α = 10⁻³ m/N, h = 0.01 s: α̃ = 10 (1/kg).
  const Vec3 xi(0.0), xj(1.1, 0.0, 0.0);
  const Real h = 0.01, alpha = 1e-3;
  const DistanceCorrection first = xpbdDistanceCorrection(xi, xj, 0.0, 1.0, 1.0, alpha, h, 0.0);
  EXPECT_NEAR(first.deltaLambda, -0.1 / 11.0, 1e-15);  // Δλ = −C/(w + α̃)
  EXPECT_VEC3_NEAR(first.deltaI, Vec3(0.0), 0.0);      // pinned
  EXPECT_VEC3_NEAR(first.deltaJ, Vec3(-0.1 / 11.0, 0.0, 0.0), 1e-15);
  // Iterating with the accumulated λ converges to C + α̃ λ = 0 with the particle where w·λ moved it.
  Vec3 x = xj;
  Real lambda = 0.0;
  for (int k = 0; k < 60; ++k) {
    const DistanceCorrection c = xpbdDistanceCorrection(xi, x, 0.0, 1.0, 1.0, alpha, h, lambda);
    x += c.deltaJ;
    lambda += c.deltaLambda;
  }
  const Real C = glm::length(x - xi) - 1.0;
  EXPECT_NEAR(C + alpha / (h * h) * lambda, 0.0, 1e-12);
  EXPECT_NEAR(C, 0.1 * 10.0 / 11.0, 1e-12);  // the fixed point: C = C₀ α̃/(w + α̃)
}

TEST(CLOTH_2_XpbdDistance, MovesOnlyTheFreeEndAndNothingForCoincidentOrPinnedPairs) {
  const DistanceCorrection same = xpbdDistanceCorrection(Vec3(1.0), Vec3(1.0), 1.0, 1.0, 0.5, 0.0, 0.01, 0.0);
  EXPECT_EQ(same.deltaI, Vec3(0.0));
  const DistanceCorrection pinned =
      xpbdDistanceCorrection(Vec3(0.0), Vec3(2.0, 0.0, 0.0), 0.0, 0.0, 1.0, 0.0, 0.01, 0.0);
  EXPECT_EQ(pinned.deltaJ, Vec3(0.0));
  // i pinned, j free and compressed to 0.5 m of a 1 m rest length: j alone moves the whole 0.5 m out.
  const DistanceCorrection one = xpbdDistanceCorrection(Vec3(0.0), Vec3(0.0, 0.5, 0.0), 0.0, 2.0, 1.0, 0.0, 0.01, 0.0);
  EXPECT_EQ(one.deltaI, Vec3(0.0));
  EXPECT_VEC3_NEAR(one.deltaJ, Vec3(0.0, 0.5, 0.0), 1e-15);
}

/// Extension of every link of a hanging XPBD chain at rest, for one solver setting.
std::vector<Real> staticStretch(ClothSolverKind kind, Real compliance, int substeps, int iterations) {
  ClothMaterial m;
  m.stretchCompliance = compliance;
  const int n = 6;
  Cloth c = hangingChain(n, 0.2, 0.1, 2.0, m);
  ClothEnvironment env;
  env.massDamping = 3.0;  // settles within the run
  ClothSolver solver;
  run(c, solver, env, {}, positionBased(kind, substeps, iterations), 1.0 / 60.0, 480);
  std::vector<Real> e;
  for (int k = 0; k + 1 < n; ++k) e.push_back(chainExtension(c, static_cast<std::size_t>(k)));
  return e;
}

TEST(CLOTH_2_XpbdChain, StaticStretchMatchesTheClosedFormAndNotTheIterationOrSubstepCount) {
  // A compliant constraint carries the tension T = C/α at rest: link s from the bottom holds s m g,
  // so C_s = α s m g — a spring of stiffness 1/α. This holds once the sweeps of a substep converge,
  // which they do quickly while α̃ = α/h² is large against the inverse masses (here w/α̃ ≤ 0.07); with
  // stiffer constraints one sweep per substep leaves an error of order w h²/α (workbook, XPBD).
  const Real m = 0.2, g = kStandardGravity;
  for (Real alpha : {5e-3, 2e-2}) {
    for (const auto& [substeps, iterations] : {std::pair{10, 1}, std::pair{2, 5}, std::pair{30, 2}}) {
      const std::vector<Real> e = staticStretch(ClothSolverKind::Xpbd, alpha, substeps, iterations);
      for (std::size_t k = 0; k < e.size(); ++k) {
        const Real s = static_cast<Real>(e.size() - k);  // particles below link k
        const Real expected = alpha * s * m * g;
        EXPECT_NEAR(e[k], expected, 0.01 * expected)
            << "α " << alpha << ", " << substeps << " substeps × " << iterations << " iterations, link " << k;
      }
    }
  }
}

TEST(CLOTH_2_PbdChain, StretchDependsOnTheIterationCountUnlikeXpbd) {
  // PBD with stiffness s < 1 per projection: the more iterations, the stiffer (the workbook's contrast).
  ClothSolverSettings pbd = positionBased(ClothSolverKind::Pbd, 1, 1);
  pbd.pbdStiffness = 0.5;
  auto topLink = [&](int iterations) {
    ClothMaterial mat;
    Cloth c = hangingChain(6, 0.05, 0.1, 2.0, mat);
    ClothEnvironment env;
    env.massDamping = 3.0;
    ClothSolver solver;
    ClothSolverSettings s = pbd;
    s.iterations = iterations;
    run(c, solver, env, {}, s, 1.0 / 60.0, 480);
    return chainExtension(c, 0);
  };
  const Real few = topLink(2), many = topLink(20);
  EXPECT_GT(few, 0.0);
  EXPECT_GT(few, 3.0 * many) << "2 iterations: " << few << " m, 20 iterations: " << many << " m";
}

TEST(CLOTH_2_XpbdCloth, EnergyNeverGrowsAndPinsStayExactlyWhereTheyAre) {
  // Inextensible edges (α = 0: no elastic energy to count) and no bending: the isometric bending
  // projection is CLOTH-6, which this test must not run.
  ClothMaterial m;
  m.stretchCompliance = 0.0;
  Cloth c = meshGrid(16, 1.0, 1.5, GridPins::TopCorners, m);
  const Vec3 a = c.position[c.pins[0].particle], b = c.position[c.pins[1].particle];
  ClothEnvironment env;
  ClothSolverSettings s = positionBased(ClothSolverKind::Xpbd, 10, 1);
  s.bending = BendingModel::None;
  ClothSolver solver;
  const Real e0 = clothEnergy(c, env, s.kind, s.bending);
  Real t = 0.0, lowest = 10.0;
  for (int f = 0; f < 180; ++f) {
    solver.step(c, env, {}, s, 1.0 / 60.0, t);
    t += 1.0 / 60.0;
    ASSERT_LE(clothEnergy(c, env, s.kind, s.bending), e0 + 0.01 * std::abs(e0)) << "frame " << f;
    lowest = std::min(lowest, c.position.back().y);
  }
  EXPECT_EQ(c.position[c.pins[0].particle], a);
  EXPECT_EQ(c.position[c.pins[1].particle], b);
  // It hangs: the free corners fell, and the edges are barely stretched (the most, 6.7 %, next to the two
  // pinned particles that carry the whole cloth: one sweep per substep propagates their pull slowly).
  EXPECT_LT(lowest, 1.0);
  EXPECT_LT(edgeStrain(c).max, 0.1);
  EXPECT_LT(edgeStrain(c).mean, 0.01);
}

TEST(CLOTH_2_XpbdCloth, SmallStepsGiveLessStretchThanIterationsAtTheSameCost) {
  // Macklin et al. 2019: at a fixed budget of substeps × iterations, substeps win.
  ClothMaterial m;  // inextensible: α = 0
  auto maxStrain = [&](int substeps, int iterations) {
    Cloth c = meshGrid(24, 1.0, 1.5, GridPins::TopCorners, m);
    ClothSolver solver;
    ClothSolverSettings s = positionBased(ClothSolverKind::Xpbd, substeps, iterations);
    s.bending = BendingModel::None;  // isometric bending is CLOTH-6
    run(c, solver, ClothEnvironment{}, {}, s, 1.0 / 60.0, 90);
    return edgeStrain(c).max;
  };
  const Real substeps = maxStrain(20, 1), iterations = maxStrain(1, 20);
  EXPECT_LT(substeps, 0.5 * iterations) << "20×1: " << substeps << ", 1×20: " << iterations;
}

}  // namespace
}  // namespace pba::cloth
