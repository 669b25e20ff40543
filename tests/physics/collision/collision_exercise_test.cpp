// Exercise tests of COLL-1 and COLL-2, against reference-only code: GJK/EPA on the same spheres
// (physics/collision/gjk.h), the plane's closed form, and the projections of all eight corners of each box.
#include <cmath>
#include <random>

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

}  // namespace
}  // namespace pba::collision
