// Exercise tests of COLL-1 to COLL-3, against reference-only code: GJK/EPA on the same spheres
// (physics/collision/gjk.h), the plane's closed form, the projections of all eight corners of each box,
// and for the sort and sweep every pair tested with overlaps() (brute force).
#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "physics/collision/exercises.h"
#include "physics/collision/gjk.h"
#include "support/expect_helpers.h"

namespace pba::collision {
namespace {

TEST(COLL_1_SphereSphere, AgreesWithGjkOnNormalDepthAndPoint) {
  std::mt19937_64 rng(51);
  std::normal_distribution<Real> n(0.0, 0.6);
  std::uniform_real_distribution<Real> r(0.1, 0.8);
  int overlapping = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 ca(n(rng), n(rng), n(rng)), cb(n(rng), n(rng), n(rng));
    const Real ra = r(rng), rb = r(rng);
    const Shape a = makeSphere(ra).value(), b = makeSphere(rb).value();
    const SignedDistance ref =
        signedDistance(makeProxy(a), {ca, Quat(1, 0, 0, 0)}, makeProxy(b), {cb, Quat(1, 0, 0, 0)});
    const std::optional<SphereContact> c = sphereSphereContact(ca, ra, cb, rb);
    ASSERT_EQ(c.has_value(), ref.separation < 0.0) << "seed 51, trial " << trial;
    if (!c) continue;
    ++overlapping;
    SCOPED_TRACE(trial);
    EXPECT_VEC3_NEAR(c->normal, ref.normal, 1e-9);
    EXPECT_NEAR(c->depth, -ref.separation, 1e-9);
    EXPECT_VEC3_NEAR(c->point, 0.5 * (ref.pointA + ref.pointB), 1e-9);
  }
  EXPECT_GT(overlapping, 200);
}

TEST(COLL_1_SpherePlane, FindsDepthNormalAndTheMidpointOnATiltedPlane) {
  const Vec3 normal = glm::normalize(Vec3(0.0, 1.0, 1.0));
  const Vec3 point(1.0, 2.0, 0.0);
  // A sphere of radius 0.5 whose centre is 0.3 above the plane: depth 0.2.
  const Vec3 center = point + Vec3(0.4, 0.0, 0.0) + 0.3 * normal;  // (0.4, 0, 0) lies in the plane
  const std::optional<SphereContact> c = spherePlaneContact(center, 0.5, point, normal);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->depth, 0.2, 1e-12);
  EXPECT_VEC3_NEAR(c->normal, normal, 1e-12);
  EXPECT_VEC3_NEAR(c->point, center - (0.5 - 0.1) * normal, 1e-12);  // halfway between −0.2 and the plane
  EXPECT_FALSE(spherePlaneContact(point + 0.6 * normal, 0.5, point, normal).has_value());
  // Entirely below the plane still touches (solid below), deeper than the radius.
  const std::optional<SphereContact> below = spherePlaneContact(point - 1.0 * normal, 0.5, point, normal);
  ASSERT_TRUE(below.has_value());
  EXPECT_NEAR(below->depth, 1.5, 1e-12);
}

TEST(COLL_2_BoxSeparatingAxis, MatchesTheGapBetweenTheCornersProjections) {
  std::mt19937_64 rng(52);
  std::normal_distribution<Real> n(0.0, 1.0);
  std::uniform_real_distribution<Real> h(0.1, 1.0);
  for (int trial = 0; trial < 1000; ++trial) {
    Obb a{Vec3(n(rng), n(rng), n(rng)), glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng))),
          Vec3(h(rng), h(rng), h(rng))};
    Obb b{Vec3(n(rng), n(rng), n(rng)), glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng))),
          Vec3(h(rng), h(rng), h(rng))};
    const Vec3 axis = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
    auto interval = [&](const Obb& o, Real& lo, Real& hi) {
      lo = 1e9, hi = -1e9;
      for (int i = 0; i < 8; ++i) {
        const Vec3 local(i & 1 ? o.halfExtents.x : -o.halfExtents.x, i & 2 ? o.halfExtents.y : -o.halfExtents.y,
                         i & 4 ? o.halfExtents.z : -o.halfExtents.z);
        const Real p = glm::dot(axis, o.center + o.rotation * local);
        lo = std::min(lo, p), hi = std::max(hi, p);
      }
    };
    Real aLo, aHi, bLo, bHi;
    interval(a, aLo, aHi);
    interval(b, bLo, bHi);
    const Real gap = std::max(bLo - aHi, aLo - bHi);
    EXPECT_NEAR(obbSeparationOnAxis(a, b, axis), gap, 1e-9) << "seed 52, trial " << trial;
  }
}

// Random boxes on three axes, some static: the pairs equal brute force's, each once, none of two statics;
// `order` comes back sorted by the lower bound; a second call after small moves finds brute force's pairs
// again from the previous order.
TEST(COLL_3_SortAndSweep, FindsExactlyTheOverlappingPairsOfBruteForce) {
  std::mt19937_64 rng(53);
  std::uniform_real_distribution<Real> u(0.0, 10.0), size(0.2, 1.5), jitter(-0.3, 0.3);
  std::vector<Aabb> boxes(120);
  std::vector<char> isStatic(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Vec3 lo(u(rng), u(rng), u(rng));
    boxes[i] = {lo, lo + Vec3(size(rng), size(rng), size(rng))};
    isStatic[i] = i % 7 == 0 ? 1 : 0;
  }
  boxes[1] = {boxes[0].max, boxes[0].max + Vec3(1.0)};  // touching at one corner: overlapping
  std::vector<int> order(boxes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(order.size() - 1 - i);
  for (int call = 0; call < 3; ++call) {
    for (int axis = 0; axis < 3; ++axis) {
      std::set<std::pair<int, int>> expected;
      for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
          if (overlaps(boxes[i], boxes[j]) && !(isStatic[i] && isStatic[j]))
            expected.emplace(static_cast<int>(i), static_cast<int>(j));
      std::vector<std::pair<int, int>> pairs;
      sortAndSweep(boxes, isStatic, axis, order, pairs);
      std::set<std::pair<int, int>> found;
      for (auto [a, b] : pairs) found.emplace(std::min(a, b), std::max(a, b));
      SCOPED_TRACE(::testing::Message() << "call " << call << " axis " << axis);
      EXPECT_EQ(found.size(), pairs.size()) << "a pair reported twice";
      EXPECT_EQ(found, expected);
      if (call == 0) {
        EXPECT_TRUE(found.count({0, 1})) << "boxes touching at a corner overlap";
      }
      ASSERT_EQ(order.size(), boxes.size());
      for (std::size_t i = 1; i < order.size(); ++i)
        EXPECT_LE(boxes[order[i - 1]].min[axis], boxes[order[i]].min[axis]);
    }
    for (Aabb& b : boxes) {
      const Vec3 d(jitter(rng), jitter(rng), jitter(rng));
      b = {b.min + d, b.max + d};
    }
  }
}

}  // namespace
}  // namespace pba::collision
