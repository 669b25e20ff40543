// The highest angular frequency of a spring network (physics/springs/stability.h) against closed forms
// (one spring, a chain's 2√(k/m) bound) and against Eigen's dense symmetric eigensolver on a lattice whose
// stiffness matrix the test assembles itself from the spring directions (k n nᵀ blocks at rest).
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "physics/springs/builders.h"
#include "physics/springs/stability.h"

namespace pba::springs {
namespace {

TEST(SpringStability, OneSpringBetweenTwoMassesVibratesAtSqrtOfKOverTheReducedMass) {
  const std::vector<Vec3> x{Vec3(0.0), Vec3(0.3, 0.4, 0.0)};
  const std::vector<Spring> springs{{0, 1, 0.5, 250.0, 0.0}};
  const std::vector<Real> w{1.0 / 2.0, 1.0 / 3.0};  // masses 2 and 3 kg: reduced mass 6/5 kg
  EXPECT_NEAR(highestAngularFrequency(springs, x, w), std::sqrt(250.0 / 1.2), 1e-9);
}

TEST(SpringStability, APinnedEndLeavesSqrtOfKOverMAndAllPinnedLeavesZero) {
  const std::vector<Vec3> x{Vec3(0.0), Vec3(0.0, -1.0, 0.0)};
  const std::vector<Spring> springs{{0, 1, 1.0, 400.0, 0.0}};
  EXPECT_NEAR(highestAngularFrequency(springs, x, std::vector<Real>{0.0, 1.0 / 0.25}), std::sqrt(400.0 / 0.25), 1e-9);
  EXPECT_EQ(highestAngularFrequency(springs, x, std::vector<Real>{0.0, 0.0}), 0.0);
}

TEST(SpringStability, ALongFreeChainApproachesTwoSqrtKOverMFromBelow) {
  // Free chain of N equal masses: ω_max = 2√(k/m) sin((N−1)π/(2N)) (the chain's highest normal mode).
  const int count = 40;
  std::vector<Vec3> x;
  std::vector<Spring> springs;
  for (int i = 0; i < count; ++i) x.emplace_back(0.1 * i, 0.0, 0.0);
  for (int i = 0; i + 1 < count; ++i)
    springs.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1), 0.1, 1000.0, 0.0});
  const std::vector<Real> w(count, 1.0 / 0.05);
  const Real exact = 2.0 * std::sqrt(1000.0 / 0.05) * std::sin((count - 1) * kPi / (2.0 * count));
  EXPECT_NEAR(highestAngularFrequency(springs, x, w, 100000, 1e-15), exact, 1e-6 * exact);
}

TEST(SpringStability, LatticeMatchesTheDenseEigensolverOfMInverseHalfKMInverseHalf) {
  particles::ParticleSystem sys;
  LatticeDesc desc;
  desc.nx = 4;
  desc.ny = 3;
  desc.nz = 2;
  desc.stiffness = 5e4;
  ASSERT_TRUE(appendLattice(desc, sys));
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> mass(0.02, 0.2);
  std::vector<Real> w(sys.particles.size());
  for (Real& wi : w) wi = 1.0 / mass(rng);
  w[0] = w[1] = 0.0;  // two pinned particles
  const std::vector<Vec3>& x = sys.particles.position;
  const Eigen::Index n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (const Spring& s : sys.springs) {
    const Vec3 d = glm::normalize(x[s.j] - x[s.i]);  // at rest: no lateral term
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const Real v = s.stiffness * d[a] * d[b];
        k(3 * s.i + a, 3 * s.i + b) += v, k(3 * s.j + a, 3 * s.j + b) += v;
        k(3 * s.i + a, 3 * s.j + b) -= v, k(3 * s.j + a, 3 * s.i + b) -= v;
      }
  }
  Eigen::VectorXd scale(3 * n);
  for (Eigen::Index i = 0; i < 3 * n; ++i) scale(i) = std::sqrt(w[static_cast<size_t>(i / 3)]);
  const Eigen::MatrixXd s = scale.asDiagonal() * k * scale.asDiagonal();
  const Real exact = std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(s).eigenvalues().maxCoeff());
  const Real omega = highestAngularFrequency(sys.springs, x, w, 100000, 1e-15);
  EXPECT_NEAR(omega, exact, 1e-6 * exact);
  // The chain estimate with the lightest mass is not an upper bound here: shear and bending add stiffness.
  EXPECT_GT(omega, 0.0);
}

}  // namespace
}  // namespace pba::springs
