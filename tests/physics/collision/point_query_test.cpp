// Point queries (collision/point_query.h) against closed forms: points placed at a chosen distance along a
// chosen direction from a rotated plane, a sphere, the side and the end of a capsule's segment, and a box's
// face, edge and corner; a hull's against GJK (outside) and EPA (inside) between it and a point. The box's distance in its frame is CLOTH-7 (its own tests are in
// tests/physics/cloth/cloth_box_exercise_test.cpp): the box cases here check only the pose around it and
// skip in the hand-out while it is a stub.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "physics/collision/gjk.h"
#include "physics/collision/point_query.h"
#include "support/expect_helpers.h"

namespace pba::collision {
namespace {

const Quat kTilt = glm::angleAxis(0.7, glm::normalize(Vec3(1.0, 2.0, -0.5)));

TEST(PointQuery, APointAboveARotatedPlaneIsAtItsHeightAlongTheRotatedY) {
  const Transform pose{Vec3(0.3, -0.2, 1.0), kTilt};
  const Vec3 n = kTilt * Vec3(0.0, 1.0, 0.0);
  const Vec3 inPlane = kTilt * Vec3(2.0, 0.0, -1.5);  // any offset within the plane
  for (const Real d : {0.25, -0.1}) {                 // above and below (inside the half-space)
    const SurfacePoint s = surfacePoint(makePlane(), pose, pose.position + inPlane + d * n);
    EXPECT_NEAR(s.distance, d, 1e-14);
    EXPECT_VEC3_NEAR(s.normal, n, 1e-15);
  }
}

TEST(PointQuery, APointOnASpheresRayIsAtItsDistanceFromTheSurfaceAlongTheRay) {
  const Shape sphere = makeSphere(0.4).value();
  const Transform pose{Vec3(1.0, 2.0, 3.0), kTilt};  // a sphere's rotation changes nothing
  const Vec3 u = glm::normalize(Vec3(-1.0, 0.5, 2.0));
  for (const Real d : {0.3, -0.15}) {
    const SurfacePoint s = surfacePoint(sphere, pose, pose.position + (0.4 + d) * u);
    EXPECT_NEAR(s.distance, d, 1e-14);
    EXPECT_VEC3_NEAR(s.normal, u, 1e-14);
  }
  // The centre has no direction: as deep as it gets, with the fallback +y.
  const SurfacePoint centre = surfacePoint(sphere, pose, pose.position);
  EXPECT_EQ(centre.distance, -0.4);
  EXPECT_EQ(centre.normal, Vec3(0.0, 1.0, 0.0));
}

TEST(PointQuery, BesideACapsulesSegmentTheNormalIsPerpendicularAndBeyondItsEndItIsTheEndSpheres) {
  const Real h = 0.5, r = 0.2;
  const Shape capsule = makeCapsule(h, r).value();
  const Transform pose{Vec3(-0.3, 0.8, 0.1), kTilt};
  const Vec3 axis = kTilt * Vec3(0.0, 1.0, 0.0);
  const Vec3 side = kTilt * glm::normalize(Vec3(1.0, 0.0, -2.0));  // perpendicular to the axis
  // Beside the segment, 0.3 m along the axis from the centre: distance along the perpendicular.
  for (const Real d : {0.1, -0.05}) {
    const SurfacePoint s = surfacePoint(capsule, pose, pose.position + 0.3 * axis + (r + d) * side);
    EXPECT_NEAR(s.distance, d, 1e-14);
    EXPECT_VEC3_NEAR(s.normal, side, 1e-14);
  }
  // Beyond the lower end: the ball of radius r about the end point, in any direction of that half-space.
  const Vec3 end = pose.position - h * axis;
  const Vec3 out = glm::normalize(-axis + 0.6 * side);
  const SurfacePoint e = surfacePoint(capsule, pose, end + (r + 0.07) * out);
  EXPECT_NEAR(e.distance, 0.07, 1e-14);
  EXPECT_VEC3_NEAR(e.normal, out, 1e-14);
  EXPECT_VEC3_NEAR(capsuleAxisPoint(posed(capsule, pose), end + 0.3 * out), end, 1e-15);
}

TEST(PointQuery, BeyondARotatedBoxsEdgeAndCornerTheDistanceIsEuclideanInTheWorld) {
  const Vec3 half(0.4, 0.25, 0.3);
  const Shape box = makeBox(half).value();
  const Transform pose{Vec3(0.5, 1.0, -0.2), kTilt};
  // The corner (+, −, +): an outward direction with the corner's signs, 0.2 m out.
  const Vec3 corner(half.x, -half.y, half.z), cornerOut = glm::normalize(Vec3(2.0, -1.0, 0.5));
  const SurfacePoint c = surfacePoint(box, pose, pose.apply(corner + 0.2 * cornerOut));
  EXPECT_NEAR(c.distance, 0.2, 1e-14);
  EXPECT_VEC3_NEAR(c.normal, kTilt * cornerOut, 1e-14);
  // The edge along z at x = −a, y = +b: an offset perpendicular to z, 0.1 m out.
  const Vec3 edge(-half.x, half.y, -0.1), edgeOut = glm::normalize(Vec3(-1.0, 3.0, 0.0));
  const SurfacePoint e = surfacePoint(box, pose, pose.apply(edge + 0.1 * edgeOut));
  EXPECT_NEAR(e.distance, 0.1, 1e-14);
  EXPECT_VEC3_NEAR(e.normal, kTilt * edgeOut, 1e-14);
}

TEST(PointQuery, AHullsDistanceIsGjkOutsideAndEpaInsideWithTheNormalAlongTheClosestPoints) {
  // An irregular hull (a squashed, skewed octahedron with a cut corner) at a pose; points all around it.
  const Shape hull = makeHull({{0.5, 0.0, 0.0},
                               {-0.4, 0.1, 0.0},
                               {0.0, 0.3, 0.1},
                               {0.1, -0.35, 0.0},
                               {0.0, 0.0, 0.45},
                               {0.05, 0.0, -0.3},
                               {0.3, 0.2, 0.2}})
                         .value();
  const Transform pose{Vec3(0.2, 0.9, -0.4), kTilt};
  ConvexProxy point;  // a point: one vertex, no radius
  point.count = 1;
  const ConvexProxy body = makeProxy(hull);
  std::mt19937 random(5);
  std::uniform_real_distribution<Real> u(-0.5, 0.5);
  int inside = 0, outside = 0;
  for (int k = 0; k < 600; ++k) {
    const Vec3 x = pose.position + Vec3(u(random), u(random), u(random));
    const SurfacePoint s = surfacePoint(hull, pose, x);
    const SignedDistance reference = signedDistance(body, pose, point, Transform{x, Quat(1.0, 0.0, 0.0, 0.0)});
    ASSERT_TRUE(reference.valid);
    SCOPED_TRACE(::testing::Message() << "point " << k << " separation " << reference.separation);
    EXPECT_NEAR(s.distance, reference.separation, 1e-9);
    EXPECT_NEAR(glm::length(s.normal), 1.0, 1e-12);
    // The normal leads from the hull to the point (GJK's and EPA's normal from A to B).
    if (std::abs(reference.separation) > 1e-6) EXPECT_VEC3_NEAR(s.normal, reference.normal, 1e-7);
    ++(s.distance < 0.0 ? inside : outside);
  }
  EXPECT_GT(inside, 20);
  EXPECT_GT(outside, 200);
}

TEST(PointQuery, MeshesHaveNoPointQueryAndTheCheckNamesTheField) {
  EXPECT_TRUE(checkPointQueryShape(makePlane(), "c").ok());
  EXPECT_TRUE(checkPointQueryShape(makeSphere(1.0).value(), "c").ok());
  EXPECT_TRUE(checkPointQueryShape(makeCapsule(1.0, 0.5).value(), "c").ok());
  EXPECT_TRUE(checkPointQueryShape(makeBox(Vec3(0.5)).value(), "c").ok());
  EXPECT_TRUE(checkPointQueryShape(makeHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}).value(), "c").ok());
  Shape mesh;
  mesh.kind = ShapeKind::Mesh;  // the check reads the kind only
  const Status m = checkPointQueryShape(mesh, "drape.colliders[1].shape");
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.error().rfind("drape.colliders[1].shape: a mesh", 0), 0u) << m.error();
}

}  // namespace
}  // namespace pba::collision
