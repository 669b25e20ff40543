// Closest points, ray casts, GJK and time of impact against independent references: dense sampling,
// root finding on a signed distance along the ray, the separating-plane certificate of a distance.
#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "physics/collision/closest_points.h"
#include "physics/collision/gjk.h"
#include "physics/collision/raycast.h"
#include "physics/collision/toi.h"
#include "support/expect_helpers.h"
#include "support/fp_traps.h"

namespace pba::collision {
namespace {

TEST(ClosestPoints, OnASegmentMatchesDenseSampling) {
  std::mt19937_64 rng(1);
  std::normal_distribution<Real> n(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3 a(n(rng), n(rng), n(rng)), b(n(rng), n(rng), n(rng)), p(n(rng), n(rng), n(rng));
    Real best = 1e9;
    for (int k = 0; k <= 20000; ++k) best = std::min(best, glm::length(p - (a + (k / 20000.0) * (b - a))));
    // Sampling at 1/20000 of the segment finds the distance to within (|b − a|/20000)²-ish.
    EXPECT_NEAR(glm::length(p - closestPointOnSegment(p, a, b)), best, 1e-6) << "trial " << trial;
  }
}

TEST(ClosestPoints, BetweenSegmentsAgreesWithGjkOnTheSegmentsAsCores) {
  std::mt19937_64 rng(2);
  std::normal_distribution<Real> n(0.0, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3 p1(n(rng), n(rng), n(rng)), q1(n(rng), n(rng), n(rng)), p2(n(rng), n(rng), n(rng)),
        q2(n(rng), n(rng), n(rng));
    const SegmentPair c = closestPointsSegments(p1, q1, p2, q2);
    ConvexProxy s1, s2;
    s1.inlinePoints = {p1, q1, q1};
    s1.count = 2;
    s2.inlinePoints = {p2, q2, q2};
    s2.count = 2;
    const DistanceResult g = gjkDistance(s1, Transform{}, s2, Transform{});
    EXPECT_NEAR(glm::length(c.onFirst - c.onSecond), g.distance, 1e-9) << "trial " << trial;
  }
}

TEST(ClosestPoints, OnATriangleMatchesDenseSamplingOfItsArea) {
  std::mt19937_64 rng(3);
  std::normal_distribution<Real> n(0.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    const Vec3 a(n(rng), n(rng), n(rng)), b(n(rng), n(rng), n(rng)), c(n(rng), n(rng), n(rng)),
        p(2 * n(rng), 2 * n(rng), 2 * n(rng));
    Real best = 1e9;
    const int m = 600;
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j)
        best = std::min(best, glm::length(p - (a + (i / Real(m)) * (b - a) + (j / Real(m)) * (c - a))));
    EXPECT_NEAR(glm::length(p - closestPointOnTriangle(p, a, b, c)), best, 2e-3 * glm::length(b - a) + 1e-9)
        << "trial " << trial;
    EXPECT_LE(glm::length(p - closestPointOnTriangle(p, a, b, c)), best + 1e-12);
  }
}

TEST(ClosestPoints, OnABoxClampsEachCoordinate) {
  EXPECT_VEC3_NEAR(closestPointOnBox(Vec3(2.0, -0.1, -3.0), Vec3(1.0, 0.5, 0.5)), Vec3(1.0, -0.1, -0.5), 0.0);
}

// The first root of the signed distance function along the ray, by marching and bisection: an
// independent reference for any shape whose signed distance is easy to write.
template <typename Sdf>
std::optional<Real> firstRoot(const Sdf& sdf, const Ray& ray, Real maxT) {
  const int steps = 4000;
  Real t0 = 0.0, f0 = sdf(ray.origin);
  if (f0 <= 0.0) return std::nullopt;
  for (int i = 1; i <= steps; ++i) {
    Real t1 = maxT * i / steps;
    const Real f1 = sdf(pointAt(ray, t1));
    if (f1 <= 0.0) {
      for (int k = 0; k < 80; ++k) {
        const Real mid = 0.5 * (t0 + t1);
        if (sdf(pointAt(ray, mid)) > 0.0)
          t0 = mid;
        else
          t1 = mid;
      }
      return 0.5 * (t0 + t1);
    }
    t0 = t1, f0 = f1;
  }
  return std::nullopt;
}

Ray randomRay(std::mt19937_64& rng) {
  std::normal_distribution<Real> n(0.0, 1.0);
  const Vec3 origin = 4.0 * glm::normalize(Vec3(n(rng), n(rng), n(rng)));
  const Vec3 aim(0.3 * n(rng), 0.3 * n(rng), 0.3 * n(rng));
  return {origin, glm::normalize(aim - origin)};
}

TEST(RayCast, EveryShapeMatchesTheRootOfItsSignedDistance) {
  std::mt19937_64 rng(4);
  const Shape capsule = makeCapsule(0.6, 0.3).value();
  const Shape box = makeBox(Vec3(0.4, 0.7, 0.2)).value();
  std::vector<Vec3> pts;
  std::normal_distribution<Real> n(0.0, 1.0);
  for (int i = 0; i < 20; ++i) pts.push_back(0.8 * glm::normalize(Vec3(n(rng), n(rng), n(rng))));
  const Shape hull = makeHull(pts).value();
  auto capsuleSdf = [&](const Vec3& p) {
    return glm::length(p - closestPointOnSegment(p, Vec3(0, -0.6, 0), Vec3(0, 0.6, 0))) - 0.3;
  };
  auto boxSdf = [&](const Vec3& p) {
    const Vec3 q = glm::abs(p) - box.halfExtents;
    return glm::length(glm::max(q, Vec3(0.0))) + std::min(std::max({q.x, q.y, q.z}), 0.0);
  };
  auto hullSdf = [&](const Vec3& p) {  // sign is enough for the root: the largest plane distance
    Real d = -1e9;
    for (const HullFace& f : hull.hull->faces) d = std::max(d, glm::dot(f.normal, p) - f.offset);
    return d;
  };
  int hits = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Ray ray = randomRay(rng);
    const struct {
      const Shape* shape;
      std::function<Real(const Vec3&)> sdf;
    } cases[] = {{&capsule, capsuleSdf}, {&box, boxSdf}, {&hull, hullSdf}};
    for (const auto& c : cases) {
      const std::optional<RayHit> hit = rayCast(*c.shape, Transform{}, ray, 10.0);
      const std::optional<Real> root = firstRoot(c.sdf, ray, 10.0);
      ASSERT_EQ(hit.has_value(), root.has_value()) << shapeKindName(c.shape->kind) << " trial " << trial;
      if (!hit) continue;
      ++hits;
      EXPECT_NEAR(hit->t, *root, 1e-9) << shapeKindName(c.shape->kind) << " trial " << trial;
      EXPECT_LT(glm::dot(hit->normal, ray.direction), 0.0);
    }
  }
  EXPECT_GT(hits, 200);
}

TEST(RayCast, SphereAndPlaneAndTriangleMatchTheirClosedForms) {
  const Ray ray{Vec3(0.0, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)};
  // Sphere of radius 1 at (0.6, 0, 0): entry at t = 5 − √(1 − 0.36) = 4.2.
  const std::optional<RayHit> s = rayCast(makeSphere(1.0).value(), {Vec3(0.6, 0.0, 0.0), Quat(1, 0, 0, 0)}, ray, 10.0);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->t, 4.2, 1e-12);
  // A plane tilted to face the ray, through (0, 0, −1): t = 6.
  const std::optional<RayHit> p =
      rayCast(makePlane(), {Vec3(0.0, 0.0, -1.0), glm::angleAxis(0.5 * kPi, Vec3(1, 0, 0))}, ray, 10.0);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->t, 6.0, 1e-12);
  EXPECT_VEC3_NEAR(p->normal, Vec3(0.0, 0.0, 1.0), 1e-12);
  const std::optional<RayHit> t = rayCastTriangle(Vec3(-1, -1, 2), Vec3(1, -1, 2), Vec3(0, 1, 2), ray, 10.0);
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->t, 3.0, 1e-12);
  EXPECT_FALSE(rayCastTriangle(Vec3(2, 2, 2), Vec3(3, 2, 2), Vec3(2, 3, 2), ray, 10.0).has_value());
  // Starting inside a solid: no hit (it cannot enter).
  EXPECT_FALSE(rayCast(makeSphere(1.0).value(), Transform{}, {Vec3(0.0), Vec3(1, 0, 0)}, 10.0).has_value());
}

// For convex A and B at distance d with closest points a, b and n = (b − a)/d: max_A n·x = n·a and
// min_B n·x = n·b certify d (the two parallel planes separate the shapes by exactly d).
TEST(Gjk, DistancesBetweenRandomHullsAreCertifiedBySeparatingPlanes) {
  std::mt19937_64 rng(5);
  std::normal_distribution<Real> n(0.0, 1.0);
  int separated = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Vec3> pa, pb;
    for (int i = 0; i < 15; ++i)
      pa.push_back(0.5 * Vec3(n(rng), n(rng), n(rng))), pb.push_back(0.5 * Vec3(n(rng), n(rng), n(rng)));
    const Shape a = makeHull(pa).value(), b = makeHull(pb).value();
    const Transform xa{Vec3(0.0), Quat(1, 0, 0, 0)},
        xb{Vec3(1.5 * n(rng), n(rng), n(rng)), glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng)))};
    const DistanceResult g = gjkDistance(makeProxy(a), xa, makeProxy(b), xb);
    if (g.overlap) continue;
    ++separated;
    const Vec3 dir = (g.pointB - g.pointA) / g.distance;
    Real maxA = -1e9, minB = 1e9;
    for (const Vec3& v : a.hull->vertices) maxA = std::max(maxA, glm::dot(dir, xa.apply(v)));
    for (const Vec3& v : b.hull->vertices) minB = std::min(minB, glm::dot(dir, xb.apply(v)));
    EXPECT_NEAR(maxA, glm::dot(dir, g.pointA), 1e-9) << "trial " << trial;
    EXPECT_NEAR(minB, glm::dot(dir, g.pointB), 1e-9) << "trial " << trial;
  }
  EXPECT_GT(separated, 50);
}

TEST(Epa, FindsTheDepthOfTwoOverlappingBoxesAndStopsOnABodyThatIsNotFinite) {
  // Two unit boxes 0.8 m apart along x overlap by 0.2 m: depth 0.2, normal ±x (closed form).
  const Shape box = makeBox(Vec3(0.5)).value();
  const ConvexProxy p = makeProxy(box);
  const Transform xa{Vec3(0.0), Quat(1, 0, 0, 0)}, xb{Vec3(0.8, 0.1, 0.05), Quat(1, 0, 0, 0)};
  const DistanceResult g = gjkDistance(p, xa, p, xb);
  ASSERT_TRUE(g.overlap);
  const PenetrationResult e = epaPenetration(p, xa, p, xb, g);
  ASSERT_TRUE(e.valid);
  EXPECT_NEAR(e.depth, 0.2, 1e-9);
  EXPECT_NEAR(std::abs(e.normal.x), 1.0, 1e-9);
  // The same call with B at infinity or NaN (a ragdoll's box after a blow-up): no answer, and the
  // call returns (the ragdoll soak once spent minutes in one such EPA call).
  pba::testing::FloatingPointTrapsOff traps;  // the arithmetic on ∞ and NaN is the point
  for (const Real bad : {std::numeric_limits<Real>::infinity(), std::numeric_limits<Real>::quiet_NaN()}) {
    const Transform far{Vec3(bad, 0.1, 0.05), Quat(1, 0, 0, 0)};
    EXPECT_FALSE(epaPenetration(p, xa, p, far, g).valid) << bad;
  }
}

TEST(TimeOfImpact, ASphereFlyingAtABoxStopsWhereItFirstTouches) {
  const Shape ball = makeSphere(0.1).value();
  const Shape wall = makeBox(Vec3(0.05, 1.0, 1.0)).value();
  const Sweep flight{Vec3(-2.0, 0.2, 0.0), Vec3(3.0, 0.2, 0.0), Quat(1, 0, 0, 0), Quat(1, 0, 0, 0)};
  const Sweep still{Vec3(0.0), Vec3(0.0), Quat(1, 0, 0, 0), Quat(1, 0, 0, 0)};
  const Real target = 0.005;
  const ToiResult r = timeOfImpact(ball, flight, wall, still, target, 1e-4);
  ASSERT_EQ(r.state, ToiResult::State::Hit);
  // Contact when the centre is at x = −(0.05 + 0.1 + target): t = (2 − 0.155) / 5.
  EXPECT_NEAR(r.t, (2.0 - 0.155) / 5.0, 1e-4 / 5.0);
  const Sweep miss{Vec3(-2.0, 2.0, 0.0), Vec3(3.0, 2.0, 0.0), Quat(1, 0, 0, 0), Quat(1, 0, 0, 0)};
  EXPECT_EQ(timeOfImpact(ball, miss, wall, still, target, 1e-4).state, ToiResult::State::Separated);
}

}  // namespace
}  // namespace pba::collision
