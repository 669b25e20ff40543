// CLOTH-1: the spring topology of a grid (Provot 1995). Expected values by counting, not by a second
// generator: the number of springs of each kind has a closed form, and each kind has one offset pattern.
#include <cmath>
#include <cstdlib>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "physics/cloth/cloth.h"
#include "physics/cloth/topology.h"

namespace pba::cloth {
namespace {

struct Offset {
  int di, dj;
};

Offset offsetOf(const GridLink& l, int nx) {
  const int pi = static_cast<int>(l.p) % nx, pj = static_cast<int>(l.p) / nx;
  const int qi = static_cast<int>(l.q) % nx, qj = static_cast<int>(l.q) / nx;
  return {std::abs(qi - pi), std::abs(qj - pj)};
}

TEST(CLOTH_1_GridTopology, HasTheClosedFormNumberOfSpringsOfEachKind) {
  for (const auto& [nx, ny] : {std::pair{2, 2}, std::pair{3, 5}, std::pair{7, 4}, std::pair{32, 32}}) {
    const std::vector<GridLink> links = gridSpringTopology(nx, ny);
    std::size_t count[kLinkKinds] = {0, 0, 0};
    for (const GridLink& l : links) ++count[static_cast<int>(l.kind)];
    const auto x = static_cast<std::size_t>(nx), y = static_cast<std::size_t>(ny);
    EXPECT_EQ(count[0], (x - 1) * y + x * (y - 1)) << nx << "×" << ny << " stretch";
    EXPECT_EQ(count[1], 2 * (x - 1) * (y - 1)) << nx << "×" << ny << " shear";
    EXPECT_EQ(count[2], (x - 2) * y + x * (y - 2)) << nx << "×" << ny << " bend";
  }
}

TEST(CLOTH_1_GridTopology, EachKindJoinsTheRightNeighboursOnceAndStaysInTheGrid) {
  const int nx = 6, ny = 5;
  const std::vector<GridLink> links = gridSpringTopology(nx, ny);
  ASSERT_FALSE(links.empty());
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (const GridLink& l : links) {
    ASSERT_LT(l.p, static_cast<std::uint32_t>(nx * ny));
    ASSERT_LT(l.q, static_cast<std::uint32_t>(nx * ny));
    EXPECT_TRUE(seen.emplace(std::min(l.p, l.q), std::max(l.p, l.q)).second)
        << "spring " << l.p << "–" << l.q << " twice";
    const Offset o = offsetOf(l, nx);
    switch (l.kind) {
      case LinkKind::Stretch:
        EXPECT_EQ(o.di + o.dj, 1) << l.p << "–" << l.q;
        break;
      case LinkKind::Shear:
        EXPECT_TRUE(o.di == 1 && o.dj == 1) << l.p << "–" << l.q;
        break;
      case LinkKind::Bend:
        EXPECT_TRUE((o.di == 2 && o.dj == 0) || (o.di == 0 && o.dj == 2)) << l.p << "–" << l.q;
        break;
    }
  }
}

TEST(CLOTH_1_GridTopology, GivesTheGridClothItsSpringsAtTheRestLengthsOfTheirKind) {
  GridDesc d;
  d.resolutionX = 5;
  d.resolutionY = 4;
  d.width = 0.4;   // spacing 0.1 m along û
  d.height = 0.3;  // and along v̂
  d.layout = SpringLayout::Grid;
  const Cloth c = buildClothGrid(d, ClothMaterial{}).value();
  ASSERT_EQ(c.springs.size(), 31u + 24u + 22u);  // 4·4 + 5·3, 2·4·3, 3·4 + 5·2
  for (const Link& s : c.springs) {
    const Real expected = s.kind == LinkKind::Stretch ? 0.1 : s.kind == LinkKind::Shear ? 0.1 * std::sqrt(2.0) : 0.2;
    EXPECT_NEAR(s.restLength, expected, 1e-12);
  }
}

}  // namespace
}  // namespace pba::cloth
