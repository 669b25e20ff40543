// Narrow phase against the general query: every special pair test must find the same normal and
// separation as GJK (cores apart) / EPA (cores overlapping) on the same shapes, over 10,000 random poses
// per pair. "Where both apply": round pairs always (both compute the exact signed distance); polytope
// pairs when they penetrate (a separating-axis value is the distance only when overlapping). The
// separating axis test prefers faces over edges and A's faces over B's within kAxisTolerance = 0.5 mm,
// so a polytope pair may report a separation at most that much deeper than EPA; those cases are counted
// and must stay rare (under 5 %).
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "physics/collision/gjk.h"
#include "physics/collision/narrow_phase.h"
#include "support/expect_helpers.h"
#include "support/portable_random.h"

namespace pba::collision {
namespace {

using pba::test::standardNormal;
using pba::test::uniform;

using PairFn = std::function<Manifold(const Shape&, const Transform&, const Shape&, const Transform&, Real)>;

struct Agreement {
  int cases = 0, compared = 0, exact = 0, preferredFace = 0;
};

Transform randomPose(std::mt19937_64& rng, Real spread) {
  // The same poses for a seed on every system (support/portable_random.h).
  auto u = [&] { return uniform(rng, -spread, spread); };
  auto n = [&] { return standardNormal(rng); };
  // One draw per statement: the order in which function arguments are evaluated differs between
  // compilers, the order of declarations does not.
  const Real px = u(), py = u(), pz = u();
  const Real w = n(), x = n(), y = n(), z = n();
  const Vec3 position(px, py, pz);
  return {position, glm::normalize(Quat(w, x, y, z))};
}

std::vector<Vec3> randomHullPoints(std::mt19937_64& rng, Real size) {
  std::vector<Vec3> p;
  for (int i = 0; i < 12; ++i) {
    const Real x = standardNormal(rng), y = standardNormal(rng), z = standardNormal(rng);
    p.push_back(size * glm::normalize(Vec3(x, y, z)) * (0.6 + 0.4 * std::abs(standardNormal(rng))));
  }
  return p;
}

Agreement compareWithGjk(const Shape& a, const Shape& b, const PairFn& pair, bool polytopes, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Real margin = 0.5;
  Agreement r;
  for (int i = 0; i < 10000; ++i) {
    const Transform pa = randomPose(rng, 0.3), pb = randomPose(rng, 0.9);
    const SignedDistance ref = signedDistance(makeProxy(a), pa, makeProxy(b), pb);
    const Manifold m = pair(a, pa, b, pb, margin);
    ++r.cases;
    if (ref.separation < margin - 1e-9) {
      EXPECT_GT(m.count, 0) << "seed " << seed << " case " << i << ": GJK separation " << ref.separation;
    }
    if (m.count == 0 || (polytopes && ref.separation >= 0.0)) continue;
    ++r.compared;
    const Real ds = m.separation - ref.separation;
    const Real dn = glm::length(m.normal - ref.normal);
    if (std::abs(ds) <= 1e-6 && dn <= 1e-6) {
      ++r.exact;
    } else if (polytopes && ds <= 0.0 && ds >= -5e-4 - 1e-9) {
      ++r.preferredFace;
    } else {
      ADD_FAILURE() << "seed " << seed << " case " << i << ": separation " << m.separation << " vs " << ref.separation
                    << ", normal differs by " << dn;
      if (r.compared - r.exact - r.preferredFace > 5) break;
    }
    // No contact point is deeper than the pair. Clipped points measure their depth along the reference
    // face's normal, which may differ from the pair's normal by up to 2.6° (a feature counts as flat
    // within that angle), hence the tolerance.
    for (int k = 0; k < m.count; ++k)
      EXPECT_GE(m.points[k].separation, m.separation - 1e-3 * std::abs(m.separation) - 1e-9);
  }
  return r;
}

void expectMostlyExact(const Agreement& r, const char* name) {
  std::printf("%s: %d poses, %d compared, %d within 1e-6, %d preferred a face within 0.5 mm\n", name, r.cases,
              r.compared, r.exact, r.preferredFace);
  EXPECT_GT(r.compared, 1000) << name;
  EXPECT_GE(r.exact, 0.95 * r.compared) << name;
}

const PairFn kDispatch = [](const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin) {
  std::vector<Manifold> out;
  NarrowPhaseScratch scratch;
  collide(a, pa, b, pb, margin, out, scratch);
  return out.empty() ? Manifold{} : out[0];
};
const PairFn kPolytopes = [](const Shape& a, const Transform& pa, const Shape& b, const Transform& pb, Real margin) {
  NarrowPhaseScratch scratch;
  return collidePolytopes(a, pa, b, pb, margin, scratch);
};

TEST(NarrowPhaseAgreesWithGjkEpa, SphereSphere) {
  expectMostlyExact(compareWithGjk(makeSphere(0.4).value(), makeSphere(0.25).value(), collideSpheres, false, 1),
                    "sphere-sphere");
}
TEST(NarrowPhaseAgreesWithGjkEpa, SphereCapsule) {
  expectMostlyExact(
      compareWithGjk(makeSphere(0.3).value(), makeCapsule(0.5, 0.2).value(), collideSphereCapsule, false, 2),
      "sphere-capsule");
}
TEST(NarrowPhaseAgreesWithGjkEpa, CapsuleCapsule) {
  expectMostlyExact(
      compareWithGjk(makeCapsule(0.4, 0.15).value(), makeCapsule(0.6, 0.2).value(), collideCapsules, false, 3),
      "capsule-capsule");
}
TEST(NarrowPhaseAgreesWithGjkEpa, SphereBox) {
  expectMostlyExact(
      compareWithGjk(makeSphere(0.3).value(), makeBox(Vec3(0.4, 0.2, 0.6)).value(), collideSphereBox, false, 4),
      "sphere-box");
}
// Capsule-box goes through the general query (collideConvex is GJK/EPA plus contact features), so GJK
// cannot be its reference. This one is built from closed forms instead. A capsule is its segment grown
// by its radius r, so its signed distance to the box is the segment's minus r. Segment apart from the
// box: the distance from a point to a box is a clamp in the box's frame, convex along the segment, so a
// golden-section search finds the closest point. Segment through the box: the segment's penetration
// depth is the smallest overlap over the face normals of box ⊕ (−segment), which are the box's three
// axes and the segment's direction crossed with each of them (a zonotope has no other faces).
Real pointBoxDistance(const Vec3& p, const Shape& box, const Transform& pose) {
  const Vec3 local = pose.applyInverse(p);
  return glm::length(local - glm::clamp(local, -box.halfExtents, box.halfExtents));
}

Real segmentBoxDistance(const Vec3& p0, const Vec3& p1, const Shape& box, const Transform& pose) {
  const Real golden = 0.5 * (std::sqrt(5.0) - 1.0);
  Real lo = 0.0, hi = 1.0;
  auto at = [&](Real t) { return pointBoxDistance(p0 + t * (p1 - p0), box, pose); };
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const Real t1 = hi - golden * (hi - lo), t2 = lo + golden * (hi - lo);
    if (at(t1) <= at(t2))
      hi = t2;
    else
      lo = t1;
  }
  return std::min({at(0.0), at(1.0), at(0.5 * (lo + hi))});
}

Real segmentBoxPenetration(const Vec3& p0, const Vec3& p1, const Shape& box, const Transform& pose) {
  const Vec3 axes[3] = {pose.rotate({1, 0, 0}), pose.rotate({0, 1, 0}), pose.rotate({0, 0, 1})};
  std::vector<Vec3> normals(axes, axes + 3);
  for (const Vec3& e : axes) {
    const Vec3 n = glm::cross(p1 - p0, e);
    if (glm::length(n) > 1e-9) normals.push_back(glm::normalize(n));
  }
  Real depth = std::numeric_limits<Real>::infinity();
  for (const Vec3& n : normals) {
    Real boxExtent = 0.0;
    for (int k = 0; k < 3; ++k) boxExtent += box.halfExtents[k] * std::abs(glm::dot(axes[k], n));
    const Real c = glm::dot(pose.position, n);
    const Real s0 = std::min(glm::dot(p0, n), glm::dot(p1, n)), s1 = std::max(glm::dot(p0, n), glm::dot(p1, n));
    depth = std::min(depth, std::min(s1 - (c - boxExtent), (c + boxExtent) - s0));
  }
  return depth;
}

TEST(NarrowPhaseAgreesWithClosedForms, CapsuleBox) {
  const Shape capsule = makeCapsule(0.4, 0.15).value(), box = makeBox(Vec3(0.4, 0.2, 0.6)).value();
  std::mt19937_64 rng(5);
  const Real margin = 0.5;
  int compared = 0, apart = 0, through = 0;
  NarrowPhaseScratch scratch;
  for (int i = 0; i < 10000; ++i) {
    const Transform pa = randomPose(rng, 0.3), pb = randomPose(rng, 0.9);
    const Vec3 p0 = pa.apply({0.0, -capsule.halfHeight, 0.0}), p1 = pa.apply({0.0, capsule.halfHeight, 0.0});
    const Real gap = segmentBoxDistance(p0, p1, box, pb);
    if (gap > 0.0 && gap < 1e-6) continue;  // grazing: neither closed form is well conditioned
    const Real expected = gap > 0.0 ? gap - capsule.radius : -(segmentBoxPenetration(p0, p1, box, pb) + capsule.radius);
    std::vector<Manifold> out;
    collide(capsule, pa, box, pb, margin, out, scratch);
    if (expected < margin - 1e-9) {
      ASSERT_FALSE(out.empty()) << "case " << i << ": expected separation " << expected;
    }
    if (out.empty()) continue;
    ++compared;
    ++(gap > 0.0 ? apart : through);
    EXPECT_NEAR(out[0].separation, expected, 1e-6) << "case " << i << (gap > 0.0 ? " (segment apart)" : " (through)");
  }
  std::printf("capsule-box: %d compared with closed forms, %d with the segment apart, %d through the box\n", compared,
              apart, through);
  EXPECT_GT(apart, 1000);
  EXPECT_GT(through, 100);
}
TEST(NarrowPhaseAgreesWithGjkEpa, BoxBox) {
  expectMostlyExact(
      compareWithGjk(makeBox(Vec3(0.3, 0.5, 0.2)).value(), makeBox(Vec3(0.4, 0.2, 0.6)).value(), collideBoxes, true, 6),
      "box-box");
}
// The deepest of the 15 separating axes of two boxes (their 3 + 3 face normals and 9 edge cross
// products), as the separating axis theorem defines it: the reference for the pose below.
Real boxBoxSatSeparation(const Shape& a, const Transform& pa, const Shape& b, const Transform& pb) {
  const Vec3 ra[3] = {pa.rotate({1, 0, 0}), pa.rotate({0, 1, 0}), pa.rotate({0, 0, 1})};
  const Vec3 rb[3] = {pb.rotate({1, 0, 0}), pb.rotate({0, 1, 0}), pb.rotate({0, 0, 1})};
  const Vec3 d = pb.position - pa.position;
  auto along = [&](Vec3 axis) {
    axis = glm::normalize(axis);
    Real extent = 0.0;
    for (int k = 0; k < 3; ++k)
      extent += a.halfExtents[k] * std::abs(glm::dot(ra[k], axis)) + b.halfExtents[k] * std::abs(glm::dot(rb[k], axis));
    return std::abs(glm::dot(d, axis)) - extent;
  };
  Real best = -std::numeric_limits<Real>::infinity();
  for (int k = 0; k < 3; ++k) best = std::max({best, along(ra[k]), along(rb[k])});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (glm::length(glm::cross(ra[i], rb[j])) > 1e-9) best = std::max(best, along(glm::cross(ra[i], rb[j])));
  return best;
}

// A pose that libc++'s random draws found: the true axis is an edge pair, B's face is 0.20 mm deeper and
// A's face 0.57 mm deeper. Each preference alone is within kAxisTolerance (0.5 mm), but preferring B's
// face over the edge and then A's face over B's chained them past it. A face may be preferred only
// within the tolerance of the best axis of all.
TEST(NarrowPhaseAgreesWithGjkEpa, ChainedFacePreferencesStayWithinTheTolerance) {
  const Shape a = makeBox(Vec3(0.3, 0.5, 0.2)).value(), b = makeBox(Vec3(0.4, 0.2, 0.6)).value();
  const Transform pa{Vec3(-0x1.6276922cf3fbbp-3, 0x1.d70f03ad8ebc2p-3, -0x1.d9d3c93e746c6p-4),
                     Quat(-0x1.65a008d3b0ecap-4, -0x1.46c97bc749c77p-1, -0x1.30611a4af4749p-1, -0x1.ecc8c868e41d4p-2)};
  const Transform pb{Vec3(0x1.31ed683e6801ep-2, 0x1.4345de9e27623p-1, 0x1.2697d5b9dec64p-3),
                     Quat(0x1.45cde6131ea16p-4, 0x1.39451310b74ecp-1, 0x1.2067a6f3c0627p-1, 0x1.195f2bbb3bfaap-1)};
  const Real sat = boxBoxSatSeparation(a, pa, b, pb);
  const Manifold m = collideBoxes(a, pa, b, pb, 0.5);
  ASSERT_GT(m.count, 0);
  EXPECT_LE(m.separation, sat);                // never shallower than the true depth
  EXPECT_GE(m.separation, sat - 5e-4 - 1e-9);  // and deeper by at most kAxisTolerance
}

TEST(NarrowPhaseAgreesWithGjkEpa, BoxHullAndHullHull) {
  std::mt19937_64 rng(7);
  const Shape hullA = makeHull(randomHullPoints(rng, 0.4)).value();
  const Shape hullB = makeHull(randomHullPoints(rng, 0.5)).value();
  expectMostlyExact(compareWithGjk(makeBox(Vec3(0.3, 0.5, 0.2)).value(), hullA, kPolytopes, true, 8), "box-hull");
  expectMostlyExact(compareWithGjk(hullA, hullB, kPolytopes, true, 9), "hull-hull");
}
TEST(NarrowPhaseAgreesWithGjkEpa, RoundShapesAgainstHullsThroughTheDispatcher) {
  std::mt19937_64 rng(10);
  const Shape hull = makeHull(randomHullPoints(rng, 0.5)).value();
  expectMostlyExact(compareWithGjk(makeSphere(0.3).value(), hull, kDispatch, false, 11), "sphere-hull");
  expectMostlyExact(compareWithGjk(hull, makeCapsule(0.3, 0.2).value(), kDispatch, false, 12), "hull-capsule");
  expectMostlyExact(compareWithGjk(makeBox(Vec3(0.3, 0.3, 0.1)).value(), makeSphere(0.3).value(), kDispatch, false, 13),
                    "box-sphere");
}

TEST(BoxBoxManifold, ABoxRestingFlatOnABoxHasFourPointsAtItsCorners) {
  const Shape ground = makeBox(Vec3(5.0, 0.5, 5.0)).value();
  const Shape crate = makeBox(Vec3(0.5, 0.25, 0.5)).value();
  const Transform pg{Vec3(0.0, -0.5, 0.0), Quat(1, 0, 0, 0)};
  const Real gap = -0.01;  // 1 cm penetration
  const Transform pc{Vec3(0.0, 0.25 + gap, 0.0), glm::angleAxis(0.3, kUp)};
  const Manifold m = collideBoxes(ground, pg, crate, pc, 0.02);
  ASSERT_EQ(m.count, 4);
  EXPECT_VEC3_NEAR(m.normal, kUp, 1e-12);
  EXPECT_NEAR(m.separation, gap, 1e-12);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(m.points[i].separation, gap, 1e-12);
    EXPECT_NEAR(m.points[i].point.y, 0.5 * gap, 1e-12);  // midway between the surfaces
    const Vec3 local = pc.applyInverse(m.points[i].point);
    EXPECT_NEAR(std::abs(local.x), 0.5, 1e-9);
    EXPECT_NEAR(std::abs(local.z), 0.5, 1e-9);
  }
  // The ids stay the same when the crate moves a little (warm starting relies on it).
  const Manifold moved = collideBoxes(ground, pg, crate, {pc.position + Vec3(0.01, 0.0, 0.0), pc.rotation}, 0.02);
  ASSERT_EQ(moved.count, 4);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(moved.points[i].id, m.points[i].id);
}

TEST(PlaneManifold, HoldsTheDeepestVerticesOfATiltedBoxAndTheSphereBottom) {
  const Shape box = makeBox(Vec3(0.5, 0.5, 0.5)).value();
  const Transform tilted{Vec3(0.0, 0.6, 0.0), glm::angleAxis(0.4, Vec3(0, 0, 1)) * glm::angleAxis(0.3, Vec3(1, 0, 0))};
  NarrowPhaseScratch scratch;
  const Manifold m = collideConvexPlane(box, tilted, Transform{}, 10.0, scratch);
  // Reference: heights of all 8 corners.
  Real lowest = 1e9;
  for (int i = 0; i < 8; ++i)
    lowest = std::min(lowest, tilted.apply(Vec3(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5)).y);
  EXPECT_EQ(m.count, 4);
  EXPECT_NEAR(m.separation, lowest, 1e-12);
  EXPECT_NEAR(m.deepest(), lowest, 1e-12);
  EXPECT_VEC3_NEAR(m.normal, -kUp, 0.0);  // from the box (A) to the plane (B)
  const Manifold s =
      collideConvexPlane(makeSphere(0.3).value(), {Vec3(1.0, 0.25, 2.0), Quat(1, 0, 0, 0)}, Transform{}, 0.1, scratch);
  ASSERT_EQ(s.count, 1);
  EXPECT_NEAR(s.separation, -0.05, 1e-15);
  EXPECT_VEC3_NEAR(s.points[0].point, Vec3(1.0, -0.025, 2.0), 1e-15);
}

TEST(MeshManifold, ABoxOnATwoTriangleFloorMatchesThePlane) {
  TriangleMesh mesh =
      buildTriangleMesh({{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}}, {{0, 2, 1}, {0, 3, 2}}).value();
  const Shape floor = makeMesh(std::move(mesh));
  const Shape box = makeBox(Vec3(0.4, 0.3, 0.2)).value();
  const Transform pose{Vec3(0.3, 0.29, -0.2), glm::angleAxis(0.2, kUp)};
  std::vector<Manifold> out;
  NarrowPhaseScratch scratch;
  collide(box, pose, floor, Transform{}, 0.02, out, scratch);
  ASSERT_FALSE(out.empty());
  int points = 0;
  for (const Manifold& m : out) {
    EXPECT_VEC3_NEAR(m.normal, -kUp, 1e-9);
    for (int i = 0; i < m.count; ++i) {
      EXPECT_NEAR(m.points[i].separation, -0.01, 1e-9);
      ++points;
    }
  }
  EXPECT_GE(points, 4);  // the box straddles the diagonal: each triangle holds some of its corners
}

TEST(MeshManifold, RejectsBadTrianglesNamingTheField) {
  EXPECT_NE(
      buildTriangleMesh({{0, 0, 0}, {1, 0, 0}}, {{0, 1, 2}}, "terrain").error().find("terrain.triangles[0]: index 2"),
      std::string::npos);
  EXPECT_NE(buildTriangleMesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}).error().find("degenerate"),
            std::string::npos);
}

}  // namespace
}  // namespace pba::collision
