// Face clipping (polytope_contact.h): a reference square clips incident polygons. Expected points from
// closed forms (polygons inside the reference face keep their vertices; a larger square is cut to the
// reference square widened by the clip tolerance) and, for more than four kept points, from a brute-force
// list of candidates reduced by reduceToFour (the clipping keeps at most four points directly, in order,
// and must pick the same ones reduceToFour would).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "physics/collision/polytope_contact.h"
#include "support/expect_helpers.h"

namespace pba::collision {
namespace {

constexpr Real kTolerance = 5e-4;  // [m] polytope_contact.cpp's kClipTolerance

// The square |x|, |z| ≤ 1 at y = 0, counter-clockwise about +y (its outward normal).
ClipPolygon referenceSquare() {
  ClipPolygon p;
  p.push(Vec3(-1.0, 0.0, 1.0), 0);
  p.push(Vec3(1.0, 0.0, 1.0), 1);
  p.push(Vec3(1.0, 0.0, -1.0), 2);
  p.push(Vec3(-1.0, 0.0, -1.0), 3);
  return p;
}

// A regular polygon of `sides` vertices of radius r about (0, y, 0), the heights given per vertex.
ClipPolygon polygon(int sides, Real r, const std::vector<Real>& heights) {
  ClipPolygon p;
  for (int i = 0; i < sides; ++i) {
    const Real a = 2.0 * kPi * i / sides;
    p.push(Vec3(r * std::cos(a), heights[i], r * std::sin(a)), static_cast<std::uint32_t>(i));
  }
  return p;
}

TEST(FaceClip, AnInnerSquareKeepsItsFourVerticesInOrderMidwayToTheFace) {
  const ClipPolygon inc = polygon(4, 0.5, {-0.1, -0.1, -0.1, -0.1});
  const Manifold m = detail::clipAgainstPolygon(referenceSquare(), kUp, inc, 0.0, false, 0.0, 0, 0);
  ASSERT_EQ(m.count, 4);
  EXPECT_VEC3_NEAR(m.normal, kUp, 0.0);
  EXPECT_DOUBLE_EQ(m.separation, -0.1);
  for (int i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(m.points[i].separation, -0.1);
    EXPECT_VEC3_NEAR(m.points[i].point, Vec3(inc.p[i].x, -0.05, inc.p[i].z), 1e-15);  // y: s − s/2
    EXPECT_EQ(m.points[i].id, detail::faceContactId(false, 0, 0, static_cast<std::uint32_t>(i)));
  }
}

TEST(FaceClip, PointsBeyondTheMarginAreDroppedButTheDeepestCountsForTheSeparation) {
  // Two vertices 0.1 below the face, two 0.1 above; margin 0.05 keeps the lower two.
  const ClipPolygon inc = polygon(4, 0.5, {-0.1, 0.1, -0.1, 0.1});
  const Manifold m = detail::clipAgainstPolygon(referenceSquare(), kUp, inc, 0.0, true, 0.05, 0, 0);
  ASSERT_EQ(m.count, 2);
  EXPECT_VEC3_NEAR(m.normal, -kUp, 0.0);  // flipped: the reference is shape B
  EXPECT_DOUBLE_EQ(m.separation, -0.1);
  EXPECT_VEC3_NEAR(m.points[0].point, Vec3(0.5, -0.05, 0.0), 1e-15);
  EXPECT_VEC3_NEAR(m.points[1].point, Vec3(-0.5, -0.05, 0.0), 1e-15);
}

TEST(FaceClip, ALargerSquareIsCutToTheReferenceFaceWidenedByTheTolerance) {
  ClipPolygon inc;
  for (const Vec3& v : {Vec3(-2, -0.2, 2), Vec3(2, -0.2, 2), Vec3(2, -0.2, -2), Vec3(-2, -0.2, -2)})
    inc.push(v, static_cast<std::uint32_t>(inc.n));
  const Manifold m = detail::clipAgainstPolygon(referenceSquare(), kUp, inc, 0.0, false, 0.0, 0, 0);
  ASSERT_EQ(m.count, 4);
  const Real e = 1.0 + kTolerance;
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(std::abs(m.points[i].point.x), e, 1e-12);
    EXPECT_NEAR(std::abs(m.points[i].point.z), e, 1e-12);
    EXPECT_NEAR(m.points[i].point.y, -0.1, 1e-15);
  }
}

TEST(FaceClip, MoreThanFourKeptPointsAreReducedAsReduceToFourReducesTheBruteForceList) {
  // Octagons inside the face (nothing clipped): every vertex within the margin is a candidate.
  for (const std::vector<Real>& heights : {std::vector<Real>{-0.1, -0.3, -0.2, -0.1, -0.25, -0.05, -0.15, -0.2},
                                           std::vector<Real>{-0.1, 0.3, -0.2, -0.1, 0.25, -0.05, -0.15, 0.2}}) {
    const ClipPolygon inc = polygon(8, 0.7, heights);
    const Manifold m = detail::clipAgainstPolygon(referenceSquare(), kUp, inc, 0.0, false, 0.0, 2, 5);
    ManifoldPoint candidates[8];
    int count = 0;
    Real deepest = 1e30;
    for (int i = 0; i < inc.n; ++i) {
      const Real s = inc.p[i].y;
      deepest = std::min(deepest, s);
      if (s <= 0.0)
        candidates[count++] = {inc.p[i] - 0.5 * s * kUp, s,
                               detail::faceContactId(false, 2, 5, static_cast<std::uint32_t>(i))};
    }
    Manifold expected;
    reduceToFour(candidates, count, kUp, expected);
    ASSERT_EQ(m.count, expected.count) << count << " candidates";
    EXPECT_DOUBLE_EQ(m.separation, deepest);
    for (int i = 0; i < m.count; ++i) {
      EXPECT_EQ(m.points[i].id, expected.points[i].id) << i;
      EXPECT_EQ(m.points[i].point, expected.points[i].point) << i;
      EXPECT_EQ(m.points[i].separation, expected.points[i].separation) << i;
    }
  }
}

}  // namespace
}  // namespace pba::collision
