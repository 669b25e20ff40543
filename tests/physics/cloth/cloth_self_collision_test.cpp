// Self-collision's Verlet list (self_collision.h): every pair of non-neighbouring particles closer than the
// thickness when a sweep starts is in the list that sweep visits, while particles move, the list is kept
// or built again, and contacts push particles far. The reference is a brute-force loop over all pairs,
// written here. Also: TMP's published sweep and the Verlet list both keep two sheets apart through the
// whole solver. No exercise code: pair sweeps and the explicit mass-spring solver only.
#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "cloth_test_support.h"
#include "physics/cloth/self_collision.h"

namespace pba::cloth {
namespace {

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
    c.rest.emplace_back(0.004 * k, 0.0, 0.0);  // neighbours at rest: the particles up to 3 apart in index
    c.w.push_back(k % 3 == 0 ? 0.0 : 50.0);
  }
  return c;
}

/// Every pair (i < j), not neighbours at rest (kSelfNeighbourFactor), closer than the thickness: all pairs
/// tried, with the definitions of the header.
std::set<std::array<std::uint32_t, 2>> touchingPairs(const Cluster& c, Real thickness) {
  std::set<std::array<std::uint32_t, 2>> pairs;
  const Real neighbour = kSelfNeighbourFactor * thickness;
  for (std::uint32_t i = 0; i < c.x.size(); ++i) {
    for (std::uint32_t j = i + 1; j < c.x.size(); ++j) {
      if (glm::length(c.rest[i] - c.rest[j]) < neighbour) continue;
      if (glm::length(c.x[i] - c.x[j]) < thickness) pairs.insert({i, j});
    }
  }
  return pairs;
}

TEST(SelfCollision, TheVerletListHoldsEveryTouchingPairAtEverySweep) {
  // Each substep moves the free particles by up to 0.5 cm along each axis, past half the skin, or by
  // 1/20 of that, which keeps the list; the sweeps' contacts push particles further.
  const Real thickness = 0.01;
  std::size_t builds = 0, kept = 0, checked = 0;
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    Cluster a = randomCluster(seed, 120);
    SelfCollision self;
    self.buildPairs(a.x, a.rest, thickness, 0.03);
    std::mt19937 rng(seed + 100);
    std::uniform_real_distribution<Real> kick(-0.005, 0.005);
    for (int substep = 0; substep < 8; ++substep) {
      const std::vector<Vec3> previous = a.x;
      const Real scale = substep % 2 == 0 ? 1.0 : 0.05;
      for (std::size_t i = 0; i < a.x.size(); ++i) {
        if (a.w[i] != 0.0) a.x[i] += scale * Vec3(kick(rng), kick(rng), kick(rng));
      }
      const auto touching = touchingPairs(a, thickness);
      const std::size_t buildsBefore = self.nearBuilds();
      self.solve(a.x, previous, a.w, thickness, 0.1);
      (self.nearBuilds() > buildsBefore ? builds : kept) += 1;
      const auto list = self.nearList();
      for (const auto& p : touching) {
        ASSERT_NE(std::find(list.begin(), list.end(), p), list.end())
            << "seed " << seed << ", substep " << substep << ": pair " << p[0] << ", " << p[1] << " missing";
        ++checked;
      }
      for (const auto& p : list) EXPECT_LT(p[0], p[1]);
    }
  }
  EXPECT_GT(checked, 500u);  // the clusters touch a lot
  EXPECT_GT(builds, 20u);    // the large moves built lists again
  EXPECT_GT(kept, 5u);       // and some small ones kept them
}

TEST(SelfCollision, ACommonDisplacementDoesNotCountAgainstTheSkin) {
  // The same cluster, jitter and contacts twice: at rest, and moving 3 cm a substep as a whole (four
  // skins). Only motion relative to the common displacement counts against the skin, so both build the
  // list equally often (measured once per substep on the old criterion, every substep), and every
  // touching pair is in it at every sweep.
  const Real thickness = 0.01;
  std::size_t builds[2] = {0, 0};
  for (const int moving : {0, 1}) {
    Cluster a = randomCluster(7, 120);
    SelfCollision self;
    self.buildPairs(a.x, a.rest, thickness, 0.03);
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> kick(-0.0005, 0.0005);
    for (int substep = 0; substep < 8; ++substep) {
      const std::vector<Vec3> previous = a.x;
      for (std::size_t i = 0; i < a.x.size(); ++i) {
        const Vec3 jitter(kick(rng), kick(rng), kick(rng));
        if (a.w[i] != 0.0) a.x[i] += jitter;
        a.x[i] += Vec3(0.0, -0.03 * moving, 0.0);  // the pinned ones are carried too (a moving pin)
      }
      const auto touching = touchingPairs(a, thickness);
      self.solve(a.x, previous, a.w, thickness, 0.0);
      const auto list = self.nearList();
      for (const auto& p : touching)
        ASSERT_NE(std::find(list.begin(), list.end(), p), list.end()) << "moving " << moving << ", substep " << substep;
    }
    builds[moving] = self.nearBuilds();
  }
  EXPECT_EQ(builds[1], builds[0]);
  EXPECT_LT(builds[1], 9u);  // 1 + 8 if the common motion counted
}

TEST(SelfCollision, ParticlesPushedTogetherByOneSweepAreSeparatedByTheNext) {
  // Free particles 2 and 3 are 2.945 cm apart when the list is built (beyond thickness + skin = 1.75 cm,
  // so their pair is left out) and each overlaps a pinned particle (0, 1) almost completely: the sweep
  // pushes them 0.985 cm towards each other, into contact. They moved more than half the skin, so the
  // next sweep builds the list again and separates them.
  const Real thickness = 0.01;
  std::vector<Vec3> x{{0.0, 0.0, 0.0}, {0.0, 0.02975, 0.0}, {0.0, 0.00015, 0.0}, {0.0, 0.0296, 0.0}};
  const std::vector<Vec3> rest{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {3.0, 0.0, 0.0}};
  const std::vector<Real> w{0.0, 0.0, 1.0, 1.0};
  SelfCollision self;
  self.buildPairs(x, rest, thickness, 0.03);
  const std::vector<Vec3> previous = x;
  EXPECT_EQ(self.solve(x, previous, w, thickness, 0.0).contacts, 2u);  // (0, 2) and (1, 3)
  EXPECT_LT(glm::length(x[3] - x[2]), thickness);                      // now 2 and 3 touch
  EXPECT_EQ(self.nearBuilds(), 1u);
  const Real apart = glm::length(x[3] - x[2]);
  self.solve(x, previous, w, thickness, 0.0);
  EXPECT_EQ(self.nearBuilds(), 2u);
  const auto list = self.nearList();
  EXPECT_NE(std::find(list.begin(), list.end(), std::array<std::uint32_t, 2>{2, 3}), list.end());
  EXPECT_GT(glm::length(x[3] - x[2]), apart);  // pushed apart (0 and 1 push back: Gauss–Seidel)
}

TEST(SelfCollision, FurtherSweepsVisitOnlyThePairsTheFullSweepFoundInContact) {
  // Pair (0, 1): pinned 0, free 1, overlapping. Pair (2, 3): free, 8 mm apart beyond the thickness.
  const Real thickness = 0.01;
  std::vector<Vec3> x{{0.0, 0.0, 0.0}, {0.0, 0.006, 0.0}, {0.1, 0.0, 0.0}, {0.1, 0.018, 0.0}};
  const std::vector<Vec3> rest{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {3.0, 0.0, 0.0}};
  const std::vector<Real> w{0.0, 1.0, 1.0, 1.0};
  SelfCollision self;
  self.buildPairs(x, rest, thickness, 0.03);
  const std::vector<Vec3> previous = x;
  EXPECT_EQ(self.solve(x, previous, w, thickness, 0.0).contacts, 1u);
  EXPECT_NEAR(x[1].y, thickness, 1e-15);
  // Something (a collider, another pair) pushes 1 back into 0 and 3 towards 2.
  x[1].y = 0.007;
  x[3].y = 0.009;
  EXPECT_EQ(self.solve(x, previous, w, thickness, 0.0, true).contacts, 1u);  // (0, 1) only
  EXPECT_NEAR(x[1].y, thickness, 1e-15);
  EXPECT_EQ(x[3].y, 0.009);                                            // (2, 3) was not in contact
  EXPECT_EQ(self.solve(x, previous, w, thickness, 0.0).contacts, 1u);  // a full sweep finds it
  EXPECT_NEAR(x[3].y - x[2].y, thickness, 1e-15);
}

TEST(SelfCollision, TheListOutlivesTheFrameUntilTheRestShapeChanges) {
  const Real thickness = 0.01;
  Cluster a = randomCluster(3, 60);
  a.w.assign(a.w.size(), 0.0);  // all pinned: the sweeps move nothing
  SelfCollision self;
  self.buildPairs(a.x, a.rest, thickness, 0.03);
  self.solve(a.x, a.x, a.w, thickness, 0.0);
  EXPECT_EQ(self.nearBuilds(), 1u);
  self.buildPairs(a.x, a.rest, thickness, 0.03);  // the next frame, nothing moved
  self.solve(a.x, a.x, a.w, thickness, 0.0);
  EXPECT_EQ(self.nearBuilds(), 0u);  // counted per frame: the list was kept
  a.rest[5].x += 1.0;                // tearing or another cloth: other neighbours
  self.buildPairs(a.x, a.rest, thickness, 0.03);
  self.solve(a.x, a.x, a.w, thickness, 0.0);
  EXPECT_EQ(self.nearBuilds(), 1u);
}

TEST(SelfCollision, BothPairListsKeepTwoSheetsApartThroughTheSolver) {
  // The two-sheet scene of AFallingSheetNeverPassesThroughAPinnedOne, shorter, with the Verlet list and
  // with TMP's sweep of the frame's pairs: no pair passes within half the thickness, and the Verlet list
  // sweeps far fewer pairs.
  for (const bool verlet : {true, false}) {
    testing::StackedSheets sheets = testing::stackedSheets(9, 0.02, 0.06);
    Cloth& c = sheets.cloth;
    ClothSolverSettings s;
    s.kind = ClothSolverKind::Explicit;
    s.substeps = 80;
    s.selfCollision = true;
    s.selfCollisionNearList = verlet;
    ClothSolver solver;
    particles::SpatialHash hash;
    Real t = 0.0;
    std::size_t largestList = 0;
    for (int f = 0; f < 45; ++f) {
      solver.step(c, ClothEnvironment{}, {}, s, 1.0 / 60.0, t);
      t += 1.0 / 60.0;
      ASSERT_EQ(countSelfIntersections(c.position, c.restPosition, sheets.material.thickness, hash), 0u)
          << (verlet ? "Verlet list" : "TMP") << ", frame " << f;
      largestList =
          std::max(largestList, verlet ? solver.selfCollision().nearPairs() : solver.selfCollision().framePairs());
    }
    for (std::size_t i = sheets.upperFirst; i < c.size(); ++i) EXPECT_GT(c.position[i].y, 1.5 + 0.5 * 0.02);
    if (verlet) {
      EXPECT_LT(largestList, 400u);
    } else {
      EXPECT_GT(largestList, 400u);
    }
  }
}

}  // namespace
}  // namespace pba::cloth
