// CLOTH-6: the isometric bending constraint of XPBD (Bergou et al. 2006; Macklin et al. 2016) on one
// stencil. Expected values by invariants and closed forms, never by a second projection: C is linear,
// so the constraint's own definition (Σ K_k x_k, as cloth_builder_test checks it) tells whether a call
// solved it; the weights sum to zero, so the mass-weighted centre stays; a linear constraint with
// compliance settles in one call at C = α̃/(S + α̃) × its start value, S = Σ w_k K_k². The stencil comes
// from the library's builder (reference-only code); no solver runs (the cloth sweeps also run CLOTH-2).
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "physics/cloth/cloth.h"
#include "physics/cloth/xpbd.h"
#include "support/expect_helpers.h"

namespace pba::cloth {
namespace {

/// Two triangles sharing the edge (0,0,0)–(1,0,0), opposite vertices on both sides (flat at rest).
Cloth flatPair() {
  const TriangleMesh pair{{{0, 0, 0}, {1, 0, 0}, {0.3, 1, 0}, {0.6, -1, 0}}, {{0, 1, 2}, {1, 0, 3}}};
  Cloth c = buildCloth(pair, ClothMaterial{}).value();
  EXPECT_EQ(c.bending.size(), 1u);
  return c;
}

Vec3 constraintOf(const BendingStencil& s, const std::vector<Vec3>& x) {
  Vec3 sum(0.0);
  for (int k = 0; k < 4; ++k) sum += s.weight[k] * x[s.vertex[k]];
  return sum;
}

/// The rest pair with its fourth particle folded by phi [rad] about the shared edge (the x axis).
std::vector<Vec3> folded(const Cloth& c, Real phi) {
  std::vector<Vec3> x = c.restPosition;
  const Vec3 o = x[3];
  x[3] = Vec3(o.x, o.y * std::cos(phi), -o.y * std::sin(phi));
  return x;
}

TEST(CLOTH_6_IsometricBending, WithZeroComplianceOneCallUnfoldsThePairExactly) {
  const Cloth c = flatPair();
  const BendingStencil& s = c.bending[0];
  for (Real phi : {0.3, -0.8, 1.5}) {
    std::vector<Vec3> x = folded(c, phi);
    ASSERT_GT(glm::length(constraintOf(s, x)), 0.1);
    const std::vector<Real> w{1.0, 2.0, 0.5, 1.0};  // unequal masses
    Vec3 lambda(0.0);
    projectIsometricBending(s, x, w, 0.0, 0.01, lambda);
    EXPECT_LT(glm::length(constraintOf(s, x)), 1e-12) << "fold " << phi;
    EXPECT_GT(glm::length(lambda), 0.0);
  }
}

TEST(CLOTH_6_IsometricBending, MovesEachParticleAlongItsWeightTimesItsInverseMassAndKeepsTheCentreOfMass) {
  const Cloth c = flatPair();
  const BendingStencil& s = c.bending[0];
  const std::vector<Vec3> before = folded(c, 0.7);
  std::vector<Vec3> x = before;
  const std::vector<Real> w{1.0, 4.0, 0.5, 2.0};
  Vec3 lambda(0.0);
  projectIsometricBending(s, x, w, 0.0, 0.01, lambda);
  // The weights sum to zero (a rigid motion leaves C alone), so Σ m_k Δx_k = 0: the centre of mass stays.
  Vec3 momentum(0.0);
  for (int k = 0; k < 4; ++k) momentum += (x[k] - before[k]) / w[k];
  EXPECT_VEC3_NEAR(momentum, Vec3(0.0), 1e-12);
  // Every correction is its particle's w_k K_k times one common vector: the multiplier's change, here λ.
  for (int k = 0; k < 4; ++k) {
    const std::uint32_t v = s.vertex[k];
    {
      SCOPED_TRACE(::testing::Message() << "particle " << v);
      EXPECT_VEC3_NEAR(x[v] - before[v], w[v] * s.weight[k] * lambda, 1e-12);
    }
  }
  EXPECT_GT(glm::length(x[3] - before[3]), 1e-3);
}

TEST(CLOTH_6_IsometricBending, PinnedParticlesNeverMoveAndAFlatPairIsLeftAlone) {
  const Cloth c = flatPair();
  const BendingStencil& s = c.bending[0];
  // Pin the shared edge: only the opposite vertices move, and still the pair unfolds.
  std::vector<Vec3> x = folded(c, 0.9);
  const std::vector<Vec3> before = x;
  const std::vector<Real> pinnedEdge{0.0, 0.0, 1.0, 1.0};
  Vec3 lambda(0.0);
  projectIsometricBending(s, x, pinnedEdge, 0.0, 0.01, lambda);
  EXPECT_EQ(x[0], before[0]);
  EXPECT_EQ(x[1], before[1]);
  EXPECT_LT(glm::length(constraintOf(s, x)), 1e-12);
  // A flat pair, rotated and moved rigidly: nothing to correct.
  const Quat q = glm::angleAxis(0.7, glm::normalize(Vec3(1.0, 2.0, -0.5)));
  std::vector<Vec3> flat = c.restPosition;
  for (Vec3& p : flat) p = q * p + Vec3(3.0, -1.0, 2.0);
  const std::vector<Vec3> flatBefore = flat;
  Vec3 flatLambda(0.0);
  projectIsometricBending(s, flat, std::vector<Real>{1.0, 1.0, 1.0, 1.0}, 0.0, 0.01, flatLambda);
  for (int k = 0; k < 4; ++k) EXPECT_VEC3_NEAR(flat[k], flatBefore[k], 1e-12);
  // Everything pinned and no compliance: nothing moves, the multiplier stays.
  std::vector<Vec3> stuck = folded(c, 0.9);
  Vec3 stuckLambda(0.0);
  projectIsometricBending(s, stuck, std::vector<Real>{0.0, 0.0, 0.0, 0.0}, 0.0, 0.01, stuckLambda);
  EXPECT_EQ(stuck[3], folded(c, 0.9)[3]);
  EXPECT_EQ(stuckLambda, Vec3(0.0));
}

TEST(CLOTH_6_IsometricBending, WithComplianceItSettlesInOneCallWhereCPlusScaledComplianceTimesLambdaVanishes) {
  const Cloth c = flatPair();
  const BendingStencil& s = c.bending[0];
  const std::vector<Real> w{1.0, 2.0, 0.5, 1.0};
  Real stiffness = 0.0;  // S = Σ w_k K_k²: the inverse "mass" the constraint sees
  for (int k = 0; k < 4; ++k) stiffness += w[s.vertex[k]] * s.weight[k] * s.weight[k];
  const Real h = 0.01;
  for (Real alpha : {1e-4, 1e-2, 1.0}) {
    std::vector<Vec3> x = folded(c, 0.6);
    const Vec3 c0 = constraintOf(s, x);
    const Real alphaTilde = alpha / (h * h);
    Vec3 lambda(0.0);
    projectIsometricBending(s, x, w, alpha, h, lambda);
    // A linear constraint in series with its compliance: C shrinks by α̃ / (S + α̃) in one call...
    const Vec3 c1 = constraintOf(s, x);
    {
      SCOPED_TRACE(::testing::Message() << "α " << alpha);
      EXPECT_VEC3_NEAR(c1, c0 * (alphaTilde / (stiffness + alphaTilde)), 1e-12 * glm::length(c0));
    }
    // ...where XPBD's condition C + α̃ λ = 0 holds, so a second call (λ carried over) changes nothing.
    {
      SCOPED_TRACE(::testing::Message() << "α " << alpha);
      EXPECT_VEC3_NEAR(c1 + alphaTilde * lambda, Vec3(0.0), 1e-10 * glm::length(c0));
    }
    const std::vector<Vec3> settled = x;
    const Vec3 lambdaSettled = lambda;
    projectIsometricBending(s, x, w, alpha, h, lambda);
    for (int k = 0; k < 4; ++k) EXPECT_VEC3_NEAR(x[k], settled[k], 1e-12);
    EXPECT_VEC3_NEAR(lambda, lambdaSettled, 1e-9 * glm::length(lambdaSettled));
  }
}

}  // namespace
}  // namespace pba::cloth
