// The dynamic AABB tree keeps its invariants under random inserts, removes and moves, and every broad
// phase reports exactly the brute-force pair set.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "physics/collision/broad_phase.h"

namespace pba::collision {
namespace {

Aabb boxAt(const Vec3& c, Real r) { return {c - Vec3(r), c + Vec3(r)}; }

TEST(DynamicTree, StaysValidAndBalancedUnderRandomInsertRemoveAndMove) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<Real> u(-10.0, 10.0), step(-0.3, 0.3);
  DynamicTree tree(0.1);
  std::vector<int> live;
  std::vector<Vec3> where;
  for (int round = 0; round < 3000; ++round) {
    const int op = static_cast<int>(rng() % 3);
    if (op == 0 || live.size() < 10) {
      where.emplace_back(u(rng), u(rng), u(rng));
      live.push_back(tree.createProxy(boxAt(where.back(), 0.5), static_cast<int>(where.size()) - 1));
    } else if (op == 1) {
      const std::size_t k = rng() % live.size();
      tree.destroyProxy(live[k]);
      live.erase(live.begin() + static_cast<long>(k));
    } else {
      const std::size_t k = rng() % live.size();
      Vec3& c = where[tree.userData(live[k])];
      c += Vec3(step(rng), step(rng), step(rng));
      tree.moveProxy(live[k], boxAt(c, 0.5));
    }
    ASSERT_TRUE(tree.validate()) << "seed 8, round " << round;
  }
  EXPECT_EQ(tree.proxyCount(), static_cast<int>(live.size()));
  EXPECT_LE(tree.height(), 2 * static_cast<int>(std::ceil(std::log2(live.size()))) + 2);
  // A query finds exactly the overlapping fat boxes.
  const Aabb q = boxAt(Vec3(0.0), 3.0);
  std::vector<int> found, expected;
  tree.query(q, [&](int p) {
    found.push_back(p);
    return true;
  });
  for (int p : live)
    if (overlaps(tree.fatAabb(p), q)) expected.push_back(p);
  std::sort(found.begin(), found.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(found, expected);
}

TEST(BroadPhase, TreeAndSweepAndPruneReportTheBruteForcePairsOverRandomMoves) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<Real> u(0.0, 12.0), step(-0.2, 0.2), size(0.2, 0.8);
  const int n = 400;
  std::vector<Vec3> c(n);
  std::vector<Real> r(n);
  BroadPhase tree(BroadPhaseKind::Tree), sap(BroadPhaseKind::SweepAndPrune), brute(BroadPhaseKind::BruteForce);
  std::vector<int> pt(n), ps(n), pb(n);
  for (int i = 0; i < n; ++i) {
    c[i] = Vec3(u(rng), u(rng), u(rng));
    r[i] = size(rng);
    const bool isStatic = i % 10 == 0;
    pt[i] = tree.add(boxAt(c[i], r[i]), i, isStatic);
    ps[i] = sap.add(boxAt(c[i], r[i]), i, isStatic);
    pb[i] = brute.add(boxAt(c[i], r[i]), i, isStatic);
  }
  std::vector<std::pair<int, int>> a, b, e;
  for (int round = 0; round < 30; ++round) {
    for (int i = 0; i < n; ++i) {
      if (i % 10 == 0) continue;  // static
      c[i] += Vec3(step(rng), step(rng), step(rng));
      tree.move(pt[i], boxAt(c[i], r[i]));
      sap.move(ps[i], boxAt(c[i], r[i]));
      brute.move(pb[i], boxAt(c[i], r[i]));
    }
    tree.findPairs(a);
    sap.findPairs(b);
    brute.findPairs(e);
    ASSERT_EQ(a, e) << "tree, seed 9, round " << round;
    ASSERT_EQ(b, e) << "sap, seed 9, round " << round;
    // No static–static pair, every pair overlaps.
    for (const auto& [x, y] : e) {
      EXPECT_FALSE(x % 10 == 0 && y % 10 == 0);
      EXPECT_TRUE(overlaps(brute.fatAabb(pb[x]), brute.fatAabb(pb[y])));
    }
  }
  EXPECT_GT(e.size(), 100u);
}

}  // namespace
}  // namespace pba::collision
