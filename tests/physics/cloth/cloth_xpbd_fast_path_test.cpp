// CLOTH-2's fast path (framework/physics/cloth/xpbd_fast_path.h) against the scalar route it replaces, on
// random links and on the benchmark's ribbon. The fast kernel does CLOTH-2's IEEE operations in the same
// order, two independent links at a time, so the positions and multipliers must agree to the bit after
// several sweeps. In the hand-out the fast path runs the scalar route and this holds trivially.
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "physics/cloth/forces.h"
#include "physics/cloth/xpbd_fast_path.h"

namespace pba::cloth {
namespace {

struct SweepInput {
  std::vector<Link> links;
  std::vector<Vec3> x;
  std::vector<Real> w;
  std::array<Real, kLinkKinds> alphaTilde{};
};

bool sameBits(const void* a, const void* b, std::size_t bytes) { return std::memcmp(a, b, bytes) == 0; }

void expectSameSweeps(const SweepInput& in, int sweeps) {
  std::vector<Vec3> xScalar = in.x, xFast = in.x;
  std::vector<Real> lambdaScalar(in.links.size(), 0.0), lambdaFast(in.links.size(), 0.0);
  for (int s = 0; s < sweeps; ++s) {
    sweepXpbdLinksScalar(in.links, in.alphaTilde, xScalar, in.w, lambdaScalar);
    sweepXpbdLinksFast(in.links, in.alphaTilde, xFast, in.w, lambdaFast);
  }
  for (std::size_t i = 0; i < xScalar.size(); ++i) {
    ASSERT_TRUE(sameBits(&xScalar[i], &xFast[i], sizeof(Vec3)))
        << "particle " << i << ": scalar (" << xScalar[i].x << ", " << xScalar[i].y << ", " << xScalar[i].z
        << "), fast (" << xFast[i].x << ", " << xFast[i].y << ", " << xFast[i].z << ")";
  }
  ASSERT_TRUE(sameBits(lambdaScalar.data(), lambdaFast.data(), lambdaScalar.size() * sizeof(Real)));
}

TEST(XpbdFastPath, MatchesTheScalarSweepToTheBitOnRandomLinks) {
  std::mt19937 rng(20261204);
  std::uniform_real_distribution<Real> coordinate(-1.0, 1.0), weight(0.1, 3.0), rest(0.05, 1.5);
  for (int trial = 0; trial < 50; ++trial) {
    SweepInput in;
    const std::uint32_t particles = 2 + static_cast<std::uint32_t>(trial % 30);
    for (std::uint32_t p = 0; p < particles; ++p) {
      in.x.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
      in.w.push_back(p % 7 == 3 ? 0.0 : weight(rng));  // some pinned particles, some links with both pinned
    }
    if (particles > 3) in.x[1] = in.x[2];  // a link between coincident particles has no direction
    std::uniform_int_distribution<std::uint32_t> pick(0, particles - 1);
    const int links = 1 + trial * 3;
    for (int l = 0; l < links; ++l) {
      Link link;
      link.i = pick(rng);
      link.j = pick(rng);  // may equal i: a degenerate link CLOTH-2 skips
      link.restLength = rest(rng);
      link.kind = static_cast<LinkKind>(l % static_cast<int>(kLinkKinds));
      in.links.push_back(link);
    }
    for (std::size_t k = 0; k < kLinkKinds; ++k) in.alphaTilde[k] = trial % 3 == 0 ? 0.0 : weight(rng) * 1e-3 * k;
    SCOPED_TRACE("trial " + std::to_string(trial));
    expectSameSweeps(in, 4);
  }
}

TEST(XpbdFastPath, MatchesTheScalarSweepToTheBitOnTheRibbon) {
  // The cloth benchmark's ribbon (bench/cloth_bench.cpp, BM_XpbdRibbonSelfCollision): 30 × 200 with its
  // stretch, shear and bend links, shaken so that every constraint is violated, two corners pinned.
  GridDesc d;
  d.resolutionX = 30;
  d.resolutionY = 200;
  d.width = 0.29;
  d.height = 1.99;
  d.pins = GridPins::TopCorners;
  d.layout = SpringLayout::Mesh;
  ClothMaterial m;
  m.bendLinkCompliance = 100.0;
  const Cloth c = buildClothGrid(d, m).value();
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> shake(-2e-3, 2e-3);
  const Real h = 1.0 / 600.0;
  const std::array<Real, kLinkKinds> alpha = constraintCompliance(m);
  for (const std::vector<Link>* links : {&c.constraints, &c.bendLinks}) {
    SweepInput in;
    in.links = *links;
    in.w = c.inverseMass;
    for (const Vec3& p : c.position) in.x.push_back(p + Vec3(shake(rng), shake(rng), shake(rng)));
    for (std::size_t k = 0; k < kLinkKinds; ++k) in.alphaTilde[k] = alpha[k] / (h * h);
    ASSERT_FALSE(in.links.empty());
    expectSameSweeps(in, 10);
  }
}

}  // namespace
}  // namespace pba::cloth
