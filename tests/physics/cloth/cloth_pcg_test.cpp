// The filtered PCG of Baraff & Witkin §5.3 against Eigen's direct solve, and the probed preconditioner.
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "physics/cloth/pcg.h"
#include "support/expect_helpers.h"

namespace pba::cloth {
namespace {

/// A random symmetric positive definite 3n × 3n matrix with block sparsity of a chain with skips
/// (particle i coupled to i ± 1 and i ± 2), like a spring network plus a mass diagonal.
Eigen::MatrixXd randomSpdSystem(int n, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < std::min(n, i + 3); ++j) {
      // A positive semidefinite coupling B Bᵀ between i and j: [[C, −C], [−C, C]].
      Eigen::Matrix3d B;
      for (int a = 0; a < 9; ++a) B(a / 3, a % 3) = u(rng);
      const Eigen::Matrix3d C = B * B.transpose();
      A.block<3, 3>(3 * i, 3 * i) += C;
      A.block<3, 3>(3 * j, 3 * j) += C;
      A.block<3, 3>(3 * i, 3 * j) -= C;
      A.block<3, 3>(3 * j, 3 * i) -= C;
    }
    A.block<3, 3>(3 * i, 3 * i) += 0.5 * Eigen::Matrix3d::Identity();  // the "mass": makes it definite
  }
  return A;
}

ParticleOperator denseOperator(const Eigen::MatrixXd& A) {
  return [&A](std::span<const Vec3> y, std::span<Vec3> out) {
    Eigen::VectorXd v(3 * y.size());
    for (std::size_t i = 0; i < y.size(); ++i) v.segment<3>(3 * i) << y[i].x, y[i].y, y[i].z;
    const Eigen::VectorXd r = A * v;
    for (std::size_t i = 0; i < y.size(); ++i) out[i] = Vec3(r(3 * i), r(3 * i + 1), r(3 * i + 2));
  };
}

/// S as a dense 3n × 3n matrix.
Eigen::MatrixXd filterMatrix(std::span<const ParticleFilter> filter) {
  const auto n = static_cast<int>(filter.size());
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      Vec3 e(0.0);
      e[a] = 1.0;
      const Vec3 col = applyFilter(filter[i], e);
      S.block<3, 1>(3 * i, 3 * i + a) << col.x, col.y, col.z;
    }
  }
  return S;
}

TEST(FilteredPcg, MatchesEigensDirectSolveOfTheConstrainedSystem) {
  std::mt19937 rng(1998);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  const int n = 40;
  const Eigen::MatrixXd A = randomSpdSystem(n, rng);
  std::vector<Vec3> b(n), z(n), x(n, Vec3(0.0));
  std::vector<ParticleFilter> filter(n);
  for (int i = 0; i < n; ++i) {
    b[i] = Vec3(u(rng), u(rng), u(rng));
    z[i] = Vec3(u(rng), u(rng), u(rng));
    const Vec3 p = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    const Vec3 q = glm::normalize(glm::cross(p, Vec3(0.3, 1.0, -0.2)));
    switch (i % 5) {  // every kind of constraint
      case 1:
        filter[i] = {ParticleFilter::Kind::OneDirection, p, Vec3(0.0)};
        break;
      case 2:
        filter[i] = {ParticleFilter::Kind::TwoDirections, p, q};
        break;
      case 3:
        filter[i] = {ParticleFilter::Kind::Fixed, Vec3(0.0), Vec3(0.0)};
        break;
      default:
        break;
    }
  }
  // Reference: x = S y + (I − S) z with y the solution of the free part: S A (S y + (I−S) z) = S b,
  // solved as the SPD system (S A S + (I − S)) y = S (b − A (I − S) z) by Eigen's LDLᵀ.
  const Eigen::MatrixXd S = filterMatrix(filter);
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(3 * n, 3 * n);
  Eigen::VectorXd bv(3 * n), zv(3 * n);
  for (int i = 0; i < n; ++i) {
    bv.segment<3>(3 * i) << b[i].x, b[i].y, b[i].z;
    zv.segment<3>(3 * i) << z[i].x, z[i].y, z[i].z;
  }
  const Eigen::VectorXd y = (S * A * S + (I - S)).ldlt().solve(S * (bv - A * (I - S) * zv));
  const Eigen::VectorXd expected = S * y + (I - S) * zv;

  PcgSettings settings;
  settings.tolerance = 1e-12;
  PcgWorkspace w;
  for (bool preconditioned : {false, true}) {
    std::vector<Mat3> inverse;
    if (preconditioned) {
      std::vector<std::uint32_t> colour(n);
      for (int i = 0; i < n; ++i) colour[i] = static_cast<std::uint32_t>(i % 3);  // i ± 1, i ± 2 differ
      std::vector<Vec3> in, out;
      probedBlockJacobi(denseOperator(A), colour, 3, inverse, in, out);
    }
    std::fill(x.begin(), x.end(), Vec3(0.0));
    const PcgStats stats = filteredPcg(denseOperator(A), b, filter, z, inverse, settings, x, w);
    EXPECT_TRUE(stats.converged);
    EXPECT_LE(stats.iterations, 3 * n);
    for (int i = 0; i < n; ++i) {
      // |x − x*| ≤ cond(A) · ε |x*|-ish; the systems here have cond ≈ 10²: 1e-9 is ample.
      SCOPED_TRACE(i);
      EXPECT_VEC3_NEAR(x[i], Vec3(expected(3 * i), expected(3 * i + 1), expected(3 * i + 2)), 1e-9);
    }
  }
}

TEST(ProbedBlockJacobi, RecoversTheDiagonalBlocksOfTheOperator) {
  std::mt19937 rng(5);
  const int n = 12;
  const Eigen::MatrixXd A = randomSpdSystem(n, rng);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = i + 1; j < std::min<std::uint32_t>(n, i + 3); ++j) pairs.emplace_back(i, j);
  }
  std::uint32_t colours = 0;
  const std::vector<std::uint32_t> colour = colourParticles(n, pairs, &colours);
  EXPECT_EQ(colours, 3u);  // a chain with skip-one couplings needs exactly three
  for (const auto& [i, j] : pairs) EXPECT_NE(colour[i], colour[j]);
  std::vector<Mat3> inverse;
  std::vector<Vec3> in, out;
  probedBlockJacobi(denseOperator(A), colour, colours, inverse, in, out);
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix3d expected = A.block<3, 3>(3 * i, 3 * i).inverse();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(inverse[i][c][r], expected(r, c), 1e-10);
    }
  }
}

TEST(FilteredPcg, PrescribedComponentsAreExactlyTheConstraintsValues) {
  const int n = 4;
  std::mt19937 rng(2);
  const Eigen::MatrixXd A = randomSpdSystem(n, rng);
  std::vector<Vec3> b(n, Vec3(1.0)), z(n, Vec3(0.25, -0.5, 2.0)), x(n, Vec3(7.0));
  std::vector<ParticleFilter> filter(n);
  filter[0].kind = ParticleFilter::Kind::Fixed;
  filter[2] = {ParticleFilter::Kind::OneDirection, Vec3(0.0, 1.0, 0.0), Vec3(0.0)};
  PcgWorkspace w;
  filteredPcg(denseOperator(A), b, filter, z, {}, PcgSettings{}, x, w);
  EXPECT_EQ(x[0], z[0]);
  EXPECT_EQ(x[2].y, z[2].y);
}

}  // namespace
}  // namespace pba::cloth
