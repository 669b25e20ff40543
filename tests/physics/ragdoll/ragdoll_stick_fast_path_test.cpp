// RAG-1's fast path (framework/physics/ragdoll/stick_fast_path.h) against the scalar route it replaces, on
// random sticks and on a crowd of tetrahedral bones laid out as the particle ragdoll lays them out (four
// particles and six sticks per bone, bones one after another). The fast kernel does RAG-1's IEEE
// operations in the same order, two runs of sticks with disjoint particles at a time, so the positions
// must agree to the bit. In the hand-out the fast path runs the scalar route and this holds trivially.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "physics/ragdoll/stick_fast_path.h"
#include "support/same_bits.h"

namespace pba::ragdoll {
namespace {

void expectSameRelaxation(const std::vector<Stick>& sticks, const std::vector<Vec3>& x, const std::vector<Real>& w,
                          int sweeps) {
  std::vector<Vec3> scalar = x, fast = x;
  relaxSticksScalar(sticks, scalar, w, sweeps);
  relaxSticksFast(sticks, fast, w, sweeps);
  EXPECT_TRUE(test::sameBits(scalar, fast));
}

TEST(StickFastPath, MatchesTheScalarRelaxationToTheBitOnRandomSticks) {
  std::mt19937 rng(1204);
  std::uniform_real_distribution<Real> coordinate(-1.0, 1.0), weight(0.1, 4.0), rest(0.05, 1.0);
  for (int trial = 0; trial < 60; ++trial) {
    const int particles = 2 + trial % 40;
    std::vector<Vec3> x;
    std::vector<Real> w;
    for (int p = 0; p < particles; ++p) {
      x.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
      w.push_back(p % 5 == 2 ? 0.0 : weight(rng));  // pinned ends, and sticks with both ends pinned
    }
    if (particles > 3) x[1] = x[3];  // coincident ends: RAG-1 leaves them
    std::uniform_int_distribution<int> pick(0, particles - 1);
    std::vector<Stick> sticks(static_cast<std::size_t>(1 + 2 * trial));
    for (Stick& s : sticks) s = {pick(rng), pick(rng), rest(rng)};
    SCOPED_TRACE("trial " + std::to_string(trial));
    expectSameRelaxation(sticks, x, w, 3);
  }
}

TEST(StickFastPath, MatchesTheScalarRelaxationToTheBitOnACrowdOfBones) {
  // 241 bones (an odd count leaves one unpaired run), four particles each, the six sticks of a
  // tetrahedron in the ragdoll's order; every eleventh bone fixed (w = 0); one bone shares a particle with
  // the next (the kernel must then fall back to one stick at a time there). Shaken off their rest lengths.
  constexpr int kPairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  const Vec3 corner[4] = {Vec3(0.0), Vec3(0.3, 0.0, 0.0), Vec3(0.0, 0.2, 0.0), Vec3(0.0, 0.0, 0.1)};
  std::mt19937 rng(77);
  std::uniform_real_distribution<Real> shake(-0.02, 0.02);
  std::vector<Vec3> x;
  std::vector<Real> w;
  std::vector<Stick> sticks;
  for (int bone = 0; bone < 241; ++bone) {
    const int first = static_cast<int>(x.size());
    for (const Vec3& c : corner) {
      x.push_back(Vec3(0.5 * bone, 0.0, 0.0) + c + Vec3(shake(rng), shake(rng), shake(rng)));
      w.push_back(bone % 11 == 0 ? 0.0 : 4.0 / 3.0);
    }
    for (const auto& e : kPairs) {
      const int b = bone == 100 && e[1] == 3 ? first + 4 : first + e[1];  // bone 100 reaches into bone 101
      sticks.push_back({first + e[0], b, glm::length(corner[e[0]] - corner[e[1]])});
    }
  }
  expectSameRelaxation(sticks, x, w, 5);
}

}  // namespace
}  // namespace pba::ragdoll
