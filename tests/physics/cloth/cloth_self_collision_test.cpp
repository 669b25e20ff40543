// Self-collision's near list (self_collision.h): sweeping only the pairs that can come into contact gives
// the positions of sweeping every pair of the frame, bit for bit, including when a particle goes too far
// and the list is rebuilt or the sweep undone and run again. The reference is the same class sweeping the
// whole frame list. No exercise code: pair sweeps and the explicit mass-spring solver only.
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "cloth_test_support.h"
#include "physics/cloth/self_collision.h"

namespace pba::cloth {
namespace {

bool sameBits(std::span<const Vec3> a, std::span<const Vec3> b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

/// A loose random cluster of particles 1 cm thick; every third one pinned.
struct Cluster {
  std::vector<Vec3> x, rest;
  std::vector<Real> w;
};
Cluster randomCluster(std::uint32_t seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(0.0, 0.08);
  Cluster c;
  for (int k = 0; k < n; ++k) {
    c.x.emplace_back(u(rng), u(rng), u(rng));
    c.rest.emplace_back(1.0 * k, 0.0, 0.0);  // no two are neighbours at rest
    c.w.push_back(k % 3 == 0 ? 0.0 : 50.0);
  }
  return c;
}

TEST(SelfCollision, NearListSweepsEqualFullSweepsWhileParticlesMove) {
  // Each substep moves the free particles by up to 0.5 cm along each axis, past the skin, so the near list
  // is rebuilt before sweeps and, when contacts push particles far, undone and swept again.
  const Real thickness = 0.01, reach = 0.03;
  std::size_t rebuilds = 0, untracked = 0;
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    Cluster a = randomCluster(seed, 120);
    Cluster b = a;
    SelfCollision near, full;
    near.buildPairs(a.x, a.rest, thickness, reach);
    full.buildPairs(b.x, b.rest, thickness, reach, false);
    std::mt19937 rng(seed + 100);
    std::uniform_real_distribution<Real> kick(-0.005, 0.005);
    for (int substep = 0; substep < 6; ++substep) {
      const std::vector<Vec3> previous = a.x;
      const Real scale = substep % 2 == 0 ? 1.0 : 0.05;  // some small steps, which keep the list
      for (std::size_t i = 0; i < a.x.size(); ++i) {
        if (a.w[i] == 0.0) continue;
        const Vec3 k(scale * kick(rng), scale * kick(rng), scale * kick(rng));
        a.x[i] += k;
        b.x[i] += k;
      }
      const SelfCollisionStats sa = near.solve(a.x, previous, a.w, thickness, 0.1);
      const SelfCollisionStats sb = full.solve(b.x, previous, b.w, thickness, 0.1);
      ASSERT_TRUE(sameBits(a.x, b.x)) << "seed " << seed << ", substep " << substep;
      EXPECT_EQ(sa.contacts, sb.contacts);
      EXPECT_EQ(sa.deepest, sb.deepest);
      EXPECT_LT(near.nearPairs(), full.framePairs());
    }
    rebuilds += near.nearBuilds();
    untracked += near.untracked();
  }
  EXPECT_GT(rebuilds, 20u);  // the moves forced rebuilds after the first list of each seed
  EXPECT_GT(untracked, 0u);  // and particles out of the list
}

TEST(SelfCollision, ParticlesPushedFarWithinOneSweepBringTheirPairsIn) {
  // Free particles 2 and 3 are 2.945 cm apart when the near list is built (beyond thickness + skin =
  // 1.5 cm, so their pair is left out) and each overlaps a pinned particle (0, 1) almost completely: the
  // sweep pushes them 0.985 cm towards each other, into contact, which only the repeated sweep sees.
  const Real thickness = 0.01;
  std::vector<Vec3> x{{0.0, 0.0, 0.0}, {0.0, 0.02975, 0.0}, {0.0, 0.00015, 0.0}, {0.0, 0.0296, 0.0}};
  const std::vector<Vec3> rest{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {3.0, 0.0, 0.0}};
  const std::vector<Real> w{0.0, 0.0, 1.0, 1.0};
  std::vector<Vec3> y = x;
  SelfCollision near, full;
  near.buildPairs(x, rest, thickness, 0.03);
  full.buildPairs(y, rest, thickness, 0.03, false);
  EXPECT_EQ(full.framePairs(), 6u);  // every pair is within the reach
  const std::vector<Vec3> previous = x;
  const SelfCollisionStats s = near.solve(x, previous, w, thickness, 0.0);
  const SelfCollisionStats reference = full.solve(y, previous, w, thickness, 0.0);
  EXPECT_EQ(reference.contacts, 3u);  // (0, 2), (1, 3), then (2, 3)
  EXPECT_EQ(s.contacts, 3u);
  EXPECT_EQ(near.untracked(), 2u);  // 2 and 3 went too far inside the sweep: their pairs joined the list
  EXPECT_TRUE(sameBits(x, y));
  EXPECT_LT(x[2].y, 0.01);  // pushed back down by particle 3
}

TEST(SelfCollision, NearListGivesTheSolversPositionsBitForBit) {
  // The two-sheet scene of AFallingSheetNeverPassesThroughAPinnedOne, shorter, through the whole solver.
  Cloth a = testing::stackedSheets(9, 0.02, 0.06).cloth;
  Cloth b = a;
  ClothSolverSettings s;
  s.kind = ClothSolverKind::Explicit;
  s.substeps = 80;
  s.selfCollision = true;
  ClothSolverSettings reference = s;
  reference.selfCollisionNearList = false;
  ClothSolver solverA, solverB;
  Real t = 0.0;
  for (int f = 0; f < 45; ++f) {
    solverA.step(a, ClothEnvironment{}, {}, s, 1.0 / 60.0, t);
    solverB.step(b, ClothEnvironment{}, {}, reference, 1.0 / 60.0, t);
    t += 1.0 / 60.0;
    ASSERT_TRUE(sameBits(a.position, b.position)) << "frame " << f;
    ASSERT_TRUE(sameBits(a.velocity, b.velocity)) << "frame " << f;
  }
  EXPECT_LT(solverA.selfCollision().nearPairs(), solverB.selfCollision().framePairs());
}

}  // namespace
}  // namespace pba::cloth
