// CLOTH-5's fast path (framework/physics/cloth/implicit_fast_path.h) against the scalar routes it replaces,
// on random springs and on a stretched, moving grid cloth:
//  - the product does implicitSystemProduct's IEEE operations in its order (the factors grouped as it
//    groups them, springs in their order), so the two must agree to the bit;
//  - the preconditioner sums each diagonal block from the springs directly, where the probed one reads it
//    off products on unit vectors (in another order of summation): the blocks agree to rounding, and their
//    inverses to that rounding magnified by the block's condition number, which the bound includes.
// In the hand-out both fast functions run the scalar routes and this holds trivially.
#include <cmath>
#include <cstring>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cloth_test_support.h"
#include "physics/cloth/implicit.h"
#include "physics/cloth/implicit_fast_path.h"

namespace pba::cloth {
namespace {

struct SystemInput {
  std::vector<SpringJacobian> springs;
  std::vector<Real> mass;
  Real massDamping = 0.0, h = 0.0;
};

bool sameBits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

Real frobenius(const Mat3& m) {
  Real s = 0.0;
  for (int c = 0; c < 3; ++c) s += glm::dot(m[c], m[c]);
  return std::sqrt(s);
}

SystemInput randomSystem(std::mt19937& rng, std::size_t particles, std::size_t springs) {
  std::uniform_real_distribution<Real> unit(-1.0, 1.0), positive(0.01, 1.0);
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(particles - 1));
  SystemInput in;
  for (std::size_t p = 0; p < particles; ++p) in.mass.push_back(positive(rng) * 1e-3);
  for (std::size_t s = 0; s < springs; ++s) {
    SpringJacobian J;
    J.i = pick(rng);
    do J.j = pick(rng);
    while (J.j == J.i);
    if (s % 17 == 5) {  // a spring of zero length: no direction, no blocks
      in.springs.push_back(J);
      continue;
    }
    J.direction = glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)));
    J.stiffness = positive(rng) * 1e5;
    J.lateral = s % 3 == 0 ? 0.0 : positive(rng) * J.stiffness;  // some compressed (clamped at 0)
    J.damping = s % 4 == 0 ? 0.0 : positive(rng);
    in.springs.push_back(J);
  }
  in.massDamping = positive(rng);
  in.h = positive(rng) * 0.02;
  return in;
}

std::vector<Vec3> randomVectors(std::mt19937& rng, std::size_t n) {
  std::uniform_real_distribution<Real> unit(-1.0, 1.0);
  std::vector<Vec3> y(n);
  for (Vec3& v : y) v = Vec3(unit(rng), unit(rng), unit(rng));
  return y;
}

void expectSameProducts(const SystemInput& in, std::mt19937& rng, int vectors) {
  ImplicitSystem system;
  system.bind(in.springs, in.mass, in.massDamping, in.h);
  prepareImplicitSystemFast(system);
  for (int v = 0; v < vectors; ++v) {
    const std::vector<Vec3> y = randomVectors(rng, in.mass.size());
    std::vector<Vec3> scalar(y.size()), fast(y.size());
    implicitSystemProduct(in.springs, in.mass, in.massDamping, in.h, y, scalar);
    implicitSystemProductFast(system, y, fast);
    for (std::size_t i = 0; i < y.size(); ++i) {
      ASSERT_TRUE(sameBits(scalar[i], fast[i]))
          << "vector " << v << ", particle " << i << ": scalar (" << scalar[i].x << ", " << scalar[i].y << ", "
          << scalar[i].z << "), fast (" << fast[i].x << ", " << fast[i].y << ", " << fast[i].z << ")";
    }
  }
}

void expectSamePreconditioners(const SystemInput& in) {
  ImplicitSystem system;
  system.bind(in.springs, in.mass, in.massDamping, in.h);
  prepareImplicitSystemFast(system);
  const ParticleOperator A = [&](std::span<const Vec3> y, std::span<Vec3> out) {
    implicitSystemProduct(in.springs, in.mass, in.massDamping, in.h, y, out);
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const SpringJacobian& J : in.springs) pairs.emplace_back(J.i, J.j);
  std::uint32_t colours = 0;
  const std::vector<std::uint32_t> colour = colourParticles(in.mass.size(), pairs, &colours);
  std::vector<Mat3> probed, fast;
  std::vector<Vec3> in1, out1, in2, out2;
  probedBlockJacobi(A, colour, colours, probed, in1, out1);
  implicitBlockJacobiFast(system, A, colour, colours, fast, in2, out2);
  ASSERT_EQ(probed.size(), fast.size());
  for (std::size_t i = 0; i < probed.size(); ++i) {
    // Rounding of the block, relative 10⁻¹⁵ or so, reaches the inverse magnified by the block's condition
    // number κ = |B| |B⁻¹| (Frobenius norms): the bound is 10⁻¹² κ |B⁻¹|.
    const Real inverseNorm = frobenius(probed[i]), kappa = frobenius(glm::inverse(probed[i])) * inverseNorm;
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) {
        ASSERT_NEAR(fast[i][c][r], probed[i][c][r], 1e-12 * kappa * inverseNorm)
            << "particle " << i << ", entry " << r << c << ", condition number " << kappa;
      }
    }
  }
}

TEST(ImplicitFastPath, ProductMatchesTheScalarProductToTheBitOnRandomSprings) {
  std::mt19937 rng(20261205);
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial) + ", seed 20261205");
    expectSameProducts(randomSystem(rng, 5 + static_cast<std::size_t>(trial) * 7, 40 + trial * 31), rng, 3);
  }
}

TEST(ImplicitFastPath, PreconditionerMatchesTheProbedOneOnRandomSprings) {
  std::mt19937 rng(20261206);
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial) + ", seed 20261206");
    expectSamePreconditioners(randomSystem(rng, 5 + static_cast<std::size_t>(trial) * 7, 40 + trial * 31));
  }
}

TEST(ImplicitFastPath, MatchesTheScalarRoutesOnAStretchedMovingCloth) {
  ClothMaterial m;
  m.stretchStiffness = 1e5;
  m.shearStiffness = 1e3;
  m.bendStiffness = 30.0;
  m.springDamping = 0.02;
  Cloth c = testing::meshGrid(16, 1.0, 1.0, GridPins::TopCorners, m);
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(-0.004, 0.004);
  for (std::size_t i = 0; i < c.size(); ++i) c.position[i] = 1.01 * c.restPosition[i] + Vec3(u(rng), u(rng), u(rng));
  SystemInput in;
  springJacobians(c.springs, c.material, c.position, SpringJacobianSettings{}, in.springs);
  in.mass = c.mass;
  in.massDamping = 0.3;
  in.h = 1.0 / 60.0;
  expectSameProducts(in, rng, 4);
  expectSamePreconditioners(in);
}

}  // namespace
}  // namespace pba::cloth
