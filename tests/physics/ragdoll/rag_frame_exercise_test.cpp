// Exercise tests of RAG-5 (fitFrame, tetrahedron.cpp): the box's frame from its four particles. The
// particles are built here from a known rotation R, a translation t and, for the deformed cases, a known
// symmetric positive stretch P (x = t + R P r): the polar factor of R P is R by definition, so the
// expected rotation is the one the test chose, never a second polar decomposition.
#include <array>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "physics/ragdoll/tetrahedron.h"
#include "support/expect_helpers.h"
#include "support/random_rotation.h"

namespace pba::ragdoll {
namespace {

std::array<Vec3, 4> placed(const std::array<Vec3, 4>& rest, const Vec3& t, const Mat3& m) {
  std::array<Vec3, 4> x{};
  for (int i = 0; i < 4; ++i) x[i] = t + m * rest[i];
  return x;
}

// |q · expected| = 1 up to the quaternion sign (q and −q are the same rotation).
void expectSameRotation(const Quat& q, const Quat& expected, Real tolerance) {
  EXPECT_NEAR(glm::length(q), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(glm::dot(q, expected)), 1.0, tolerance);
  const Mat3 a = glm::mat3_cast(q), b = glm::mat3_cast(expected);
  for (int c = 0; c < 3; ++c) EXPECT_VEC3_NEAR(a[c], b[c], 10.0 * std::sqrt(tolerance));
}

TEST(RAG_5_BoxFrame, ARigidlyMovedTetrahedronGivesBackItsRotationAndCentre) {
  std::mt19937_64 rng(51);
  std::normal_distribution<Real> n(0.0, 1.0);
  const std::array<Vec3, 4> rest = tetrahedronOffsets(Vec3(0.2, 0.4, 0.1));
  const Mat3 inv = restEdgesInverse(rest);
  for (int trial = 0; trial < 50; ++trial) {
    SCOPED_TRACE(trial);
    const Quat q = test::randomRotation(rng);
    const Vec3 t(n(rng), n(rng), n(rng));
    const collision::Transform f = fitFrame(placed(rest, t, glm::mat3_cast(q)), inv);
    EXPECT_VEC3_NEAR(f.position, t, 1e-12);
    expectSameRotation(f.rotation, q, 1e-12);
  }
}

TEST(RAG_5_BoxFrame, AStretchedBoneKeepsOnlyTheRotationOfItsDeformation) {
  // P = 1 + εS with S symmetric and ε up to 5 %: a bone after relaxation is off by about 1 %.
  std::mt19937_64 rng(52);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  const std::array<Vec3, 4> rest = tetrahedronOffsets(Vec3(0.05, 0.3, 0.12));
  const Mat3 inv = restEdgesInverse(rest);
  for (int trial = 0; trial < 50; ++trial) {
    SCOPED_TRACE(trial);
    Mat3 s(0.0);
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k <= c; ++k) s[c][k] = s[k][c] = u(rng);
    const Mat3 stretch = Mat3(1.0) + 0.05 * s / 3.0;  // entries ≤ 0.05/3: eigenvalues stay within 1 ± 0.05
    const Quat q = test::randomRotation(rng);
    const Vec3 t(u(rng), u(rng), u(rng));
    const std::array<Vec3, 4> x = placed(rest, t, glm::mat3_cast(q) * stretch);
    const collision::Transform f = fitFrame(x, inv);
    EXPECT_VEC3_NEAR(f.position, 0.25 * (x[0] + x[1] + x[2] + x[3]), 1e-12);
    expectSameRotation(f.rotation, q, 1e-12);
  }
}

TEST(RAG_5_BoxFrame, AnInvertedTetrahedronStillGivesAProperRotation) {
  // x = t + R D r with D = diag(−1, 1, 1): the polar factor R D has determinant −1; flipping its first
  // axis gives R, a proper rotation (det +1).
  std::mt19937_64 rng(53);
  const std::array<Vec3, 4> rest = tetrahedronOffsets(Vec3(0.3, 0.2, 0.25));
  const Mat3 inv = restEdgesInverse(rest);
  const Mat3 mirror(Vec3(-1.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0), Vec3(0.0, 0.0, 1.0));
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE(trial);
    const Quat q = test::randomRotation(rng);
    const collision::Transform f = fitFrame(placed(rest, Vec3(0.0, 1.0, 0.0), glm::mat3_cast(q) * mirror), inv);
    EXPECT_NEAR(glm::determinant(glm::mat3_cast(f.rotation)), 1.0, 1e-12);
    expectSameRotation(f.rotation, q, 1e-12);
  }
}

}  // namespace
}  // namespace pba::ragdoll
