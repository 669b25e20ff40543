// CLOTH-7: signed distance and outward normal of a box, in its frame and through the point query of a box
// at a pose (the cloth's box colliders ask that query).
// Expected values by construction, not by a second distance function: points are placed at a chosen
// distance along a chosen normal from a face, an edge or a corner (any outward direction in that
// feature's normal cone), or inside at known gaps to the faces; the normal is checked against central
// differences of the returned distance. No projection runs (collide() would also run CLOTH-4).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "physics/collision/point_query.h"
#include "support/expect_helpers.h"

namespace pba::collision {
namespace {

const Vec3 kHalf(0.4, 0.25, 0.3);  // [m]

TEST(CLOTH_7_BoxSurface, AbovePointsOfEachFaceAreAtTheirHeightWithTheFacesNormal) {
  for (int axis = 0; axis < 3; ++axis) {
    for (Real side : {1.0, -1.0}) {
      Vec3 n(0.0);
      n[axis] = side;
      Vec3 onFace(0.1, -0.05, 0.12);  // inside the face's rectangle for every axis
      onFace[axis] = side * kHalf[axis];
      for (Real d : {1e-3, 0.2}) {
        const SurfacePoint s = boxSurface(kHalf, onFace + d * n);
        EXPECT_NEAR(s.distance, d, 1e-14) << "axis " << axis << " side " << side;
        EXPECT_VEC3_NEAR(s.normal, n, 1e-14);
      }
    }
  }
}

TEST(CLOTH_7_BoxSurface, BeyondAnEdgeOrACornerTheDistanceIsEuclideanAlongTheOffset) {
  // A corner: any direction with all components of the corner's signs points into its normal cone.
  const Vec3 corner(kHalf.x, -kHalf.y, kHalf.z);
  const Vec3 cornerNormal = glm::normalize(Vec3(1.0, -2.0, 0.5));
  const SurfacePoint c = boxSurface(kHalf, corner + 0.3 * cornerNormal);
  EXPECT_NEAR(c.distance, 0.3, 1e-14);
  EXPECT_VEC3_NEAR(c.normal, cornerNormal, 1e-14);
  // An edge (along z, at x = −a, y = +b): offsets perpendicular to z with −x and +y parts.
  const Vec3 onEdge(-kHalf.x, kHalf.y, 0.1);
  const Vec3 edgeNormal = glm::normalize(Vec3(-3.0, 1.0, 0.0));
  const SurfacePoint e = boxSurface(kHalf, onEdge + 0.05 * edgeNormal);
  EXPECT_NEAR(e.distance, 0.05, 1e-14);
  EXPECT_VEC3_NEAR(e.normal, edgeNormal, 1e-14);
}

TEST(CLOTH_7_BoxSurface, InsideItLeavesThroughTheNearestFaceWithANegativeDistance) {
  // 0.05 m from the −x face, farther from every other face.
  const SurfacePoint a = boxSurface(kHalf, Vec3(-kHalf.x + 0.05, 0.1, -0.1));
  EXPECT_NEAR(a.distance, -0.05, 1e-14);
  EXPECT_VEC3_NEAR(a.normal, Vec3(-1.0, 0.0, 0.0), 1e-15);
  // The centre: the smallest half extent (y), towards +y.
  const SurfacePoint centre = boxSurface(kHalf, Vec3(0.0));
  EXPECT_NEAR(centre.distance, -kHalf.y, 1e-14);
  EXPECT_VEC3_NEAR(centre.normal, Vec3(0.0, 1.0, 0.0), 1e-15);
  // 0.02 below the −z face's inside, 0.03 from the +y face: z wins.
  const SurfacePoint z = boxSurface(kHalf, Vec3(0.0, kHalf.y - 0.03, -kHalf.z + 0.02));
  EXPECT_NEAR(z.distance, -0.02, 1e-14);
  EXPECT_VEC3_NEAR(z.normal, Vec3(0.0, 0.0, -1.0), 1e-15);
}

TEST(CLOTH_7_BoxSurface, TheNormalIsTheGradientOfTheDistanceAndHasUnitLength) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-0.8, 0.8);
  const Real e = 1e-6;
  int checked = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const SurfacePoint s = boxSurface(kHalf, p);
    ASSERT_TRUE(std::isfinite(s.distance));  // no differences of infinities below
    EXPECT_NEAR(glm::length(s.normal), 1.0, 1e-12);
    // Skip points near the ridges where the inside distance is not differentiable (equal gaps to two
    // faces) and near the box's surface (the inside and outside formulas meet there).
    const Vec3 gap = kHalf - glm::abs(p);
    const Real g0 = std::min({gap.x, gap.y, gap.z});
    const Real g1 = gap.x + gap.y + gap.z - g0 - std::max({gap.x, gap.y, gap.z});
    if (std::abs(s.distance) < 1e-3 || (s.distance < 0.0 && g1 - g0 < 1e-3)) continue;
    Vec3 gradient;
    for (int i = 0; i < 3; ++i) {
      Vec3 step(0.0);
      step[i] = e;
      gradient[i] = (boxSurface(kHalf, p + step).distance - boxSurface(kHalf, p - step).distance) / (2.0 * e);
    }
    {
      SCOPED_TRACE(::testing::Message() << "at " << p.x << ", " << p.y << ", " << p.z);
      EXPECT_VEC3_NEAR(s.normal, gradient, 1e-6);
    }
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

TEST(CLOTH_7_BoxSurface, TheColliderRotatesTheQueryIntoTheBoxAndTheNormalBackOut) {
  const Vec3 center(0.5, 1.0, -0.2);
  const Quat q = glm::angleAxis(0.6, glm::normalize(Vec3(1.0, 1.0, 0.3)));
  const Result<Shape> box = makeBox(kHalf);
  ASSERT_TRUE(box.ok());
  // 0.1 m beyond the box's local +y face, seen in the world.
  const Vec3 x = center + q * Vec3(0.1, kHalf.y + 0.1, -0.05);
  const SurfacePoint s = surfacePoint(box.value(), Transform{center, q}, x);
  EXPECT_NEAR(s.distance, 0.1, 1e-12);
  EXPECT_VEC3_NEAR(s.normal, q * Vec3(0.0, 1.0, 0.0), 1e-12);
}

}  // namespace
}  // namespace pba::collision
