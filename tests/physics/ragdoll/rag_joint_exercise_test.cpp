// Exercise tests of RAG-6 (moveEmbeddedPoints, exercises.cpp): a point embedded in two bones moved by a
// given delta. Expected values are invariants computed here from the particles before and after: the
// embedded points (Σ c_i x_i, tetrahedron.h) move apart by exactly delta; momentum Σ m_i Δx_i is zero; a
// pinned side stays; every move is along delta in proportion to w_i c_i.
#include <array>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "physics/ragdoll/exercises.h"
#include "support/expect_helpers.h"

namespace pba::ragdoll {
namespace {

struct Bone {
  std::array<Vec3, 4> x{};
  std::array<Real, 4> w{};
  Weights c{};
};

Bone randomBone(std::mt19937_64& rng) {
  std::uniform_real_distribution<Real> u(-1.0, 1.0), mass(0.2, 5.0), weight(-0.3, 1.0);
  Bone b;
  Real sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    b.x[i] = Vec3(u(rng), u(rng), u(rng));
    b.w[i] = 1.0 / mass(rng);
    if (i < 3) sum += (b.c[i] = weight(rng));
  }
  b.c[3] = 1.0 - sum;  // barycentric: Σ c = 1, some negative (points outside the tetrahedron)
  return b;
}

TEST(RAG_6_EmbeddedPoints, MovesBsPointRelativeToAsByExactlyDeltaAndKeepsMomentum) {
  std::mt19937_64 rng(61);
  std::uniform_real_distribution<Real> u(-0.2, 0.2);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE(trial);
    Bone a = randomBone(rng), b = randomBone(rng);
    const Bone a0 = a, b0 = b;
    const Vec3 delta(u(rng), u(rng), u(rng));
    moveEmbeddedPoints({a.x.data(), a.w.data(), a.c}, {b.x.data(), b.w.data(), b.c}, delta);
    const Vec3 moveA = embedded(a.x, a.c) - embedded(a0.x, a.c), moveB = embedded(b.x, b.c) - embedded(b0.x, b.c);
    EXPECT_VEC3_NEAR(moveB - moveA, delta, 1e-12);
    Vec3 momentum(0.0);
    for (int i = 0; i < 4; ++i) momentum += (a.x[i] - a0.x[i]) / a.w[i] + (b.x[i] - b0.x[i]) / b.w[i];
    EXPECT_VEC3_NEAR(momentum, Vec3(0.0), 1e-12);
    // Every particle moves along delta by a length proportional to w_i c_i (one factor for all).
    const Vec3 n = glm::normalize(delta);
    const Real factor = glm::dot(b.x[0] - b0.x[0], n) / (b.w[0] * b.c[0]);
    for (int i = 0; i < 4; ++i) {
      EXPECT_VEC3_NEAR(b.x[i] - b0.x[i], factor * b.w[i] * b.c[i] * n, 1e-12);
      EXPECT_VEC3_NEAR(a.x[i] - a0.x[i], -factor * a.w[i] * a.c[i] * n, 1e-12);
    }
  }
}

TEST(RAG_6_EmbeddedPoints, APinnedOrMissingSideStaysAndTheOtherTakesTheWholeMove) {
  std::mt19937_64 rng(62);
  Bone a = randomBone(rng), b = randomBone(rng);
  a.w = {0.0, 0.0, 0.0, 0.0};  // pinned
  const Bone a0 = a, b0 = b;
  const Vec3 delta(0.05, -0.1, 0.02);
  moveEmbeddedPoints({a.x.data(), a.w.data(), a.c}, {b.x.data(), b.w.data(), b.c}, delta);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(a.x[i], a0.x[i]);
  EXPECT_VEC3_NEAR(embedded(b.x, b.c) - embedded(b0.x, b.c), delta, 1e-12);
  // No A at all (the mouse): B's point moves by delta.
  Bone c = randomBone(rng);
  const Bone c0 = c;
  moveEmbeddedPoints({}, {c.x.data(), c.w.data(), c.c}, delta);
  EXPECT_VEC3_NEAR(embedded(c.x, c.c) - embedded(c0.x, c.c), delta, 1e-12);
}

TEST(RAG_6_EmbeddedPoints, AParticleOfWeightZeroStaysAndAZeroDeltaOrAllPinnedMovesNothing) {
  std::mt19937_64 rng(63);
  Bone a = randomBone(rng), b = randomBone(rng);
  b.c = {0.0, 0.5, 0.5, 0.0};
  const Bone b0 = b;
  moveEmbeddedPoints({a.x.data(), a.w.data(), a.c}, {b.x.data(), b.w.data(), b.c}, Vec3(0.1, 0.0, 0.0));
  EXPECT_EQ(b.x[0], b0.x[0]);
  EXPECT_EQ(b.x[3], b0.x[3]);
  EXPECT_GT(glm::length(b.x[1] - b0.x[1]), 0.0);
  const Bone a1 = a, b1 = b;
  moveEmbeddedPoints({a.x.data(), a.w.data(), a.c}, {b.x.data(), b.w.data(), b.c}, Vec3(0.0));
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(a.x[i], a1.x[i]);
    EXPECT_EQ(b.x[i], b1.x[i]);
  }
  a.w = b.w = {0.0, 0.0, 0.0, 0.0};
  moveEmbeddedPoints({a.x.data(), a.w.data(), a.c}, {b.x.data(), b.w.data(), b.c}, Vec3(0.1, 0.2, 0.3));
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(a.x[i], a1.x[i]);
    EXPECT_EQ(b.x[i], b1.x[i]);
  }
}

}  // namespace
}  // namespace pba::ragdoll
