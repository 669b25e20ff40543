// OrbitCamera: rays, projection round trips, framing and invariants (pure math, no window).
#include "graphics/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using pba::graphics::OrbitCamera;

namespace {

constexpr float kW = 1280.0f, kH = 720.0f;

OrbitCamera randomCamera(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  OrbitCamera c;
  c.target = glm::vec3(u(rng), u(rng), u(rng)) * 5.0f;
  c.yaw = 3.0f * u(rng);
  c.pitch = 1.5f * u(rng);
  c.distance = 2.0f + 10.0f * std::abs(u(rng));
  c.clampState();
  return c;
}

}  // namespace

TEST(OrbitCamera, RayThroughScreenCentreIsTheViewDirection) {
  std::mt19937 rng(1);
  for (int i = 0; i < 50; ++i) {
    const OrbitCamera c = randomCamera(rng);
    const auto ray = c.ray(kW / 2, kH / 2, kW, kH);
    EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(ray.direction, glm::normalize(c.target - c.eye())), 1.0f, 1e-5f) << "seed 1, case " << i;
    EXPECT_NEAR(glm::distance(ray.origin, c.eye()), 0.0f, 1e-4f);
  }
}

TEST(OrbitCamera, ProjectOfAPointOnTheCursorRayRoundTripsToTheCursorPixel) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> px(0.0f, kW), py(0.0f, kH), depth(0.5f, 20.0f);
  for (int i = 0; i < 200; ++i) {
    const OrbitCamera c = randomCamera(rng);
    const glm::vec2 cursor(px(rng), py(rng));
    const auto ray = c.ray(cursor.x, cursor.y, kW, kH);
    const auto s = c.project(ray.origin + depth(rng) * ray.direction, kW, kH);
    ASSERT_TRUE(s.visible) << "seed 2, case " << i;
    // float round trip through view and projection matrices: 1e-3 px at 1280x720.
    EXPECT_NEAR(s.pixel.x, cursor.x, 1e-3f) << "case " << i;
    EXPECT_NEAR(s.pixel.y, cursor.y, 1e-3f) << "case " << i;
  }
}

TEST(OrbitCamera, ProjectRoundTripIsWithinAThousandthOfAPixelNearTheTarget) {
  OrbitCamera c;  // default camera, points near the target: the accuracy the picking code relies on
  for (float x : {10.0f, 333.3f, 640.0f, 1100.5f}) {
    for (float y : {5.0f, 360.0f, 700.25f}) {
      const auto ray = c.ray(x, y, kW, kH);
      const auto s = c.project(ray.origin + c.distance * ray.direction, kW, kH);
      EXPECT_NEAR(s.pixel.x, x, 1e-3f);
      EXPECT_NEAR(s.pixel.y, y, 1e-3f);
    }
  }
}

TEST(OrbitCamera, PointsBehindTheEyeAreNotVisible) {
  OrbitCamera c;
  const auto s = c.project(c.eye() - 3.0f * c.forward(), kW, kH);
  EXPECT_FALSE(s.visible);
}

TEST(OrbitCamera, FrameMakesAllEightCornersProjectInsideTheViewport) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), size(0.001f, 50.0f);
  for (int i = 0; i < 100; ++i) {
    OrbitCamera c = randomCamera(rng);
    c.keepAboveGround = false;  // boxes anywhere, some under the ground: the framing math alone
    const glm::vec3 centre = glm::vec3(u(rng), u(rng), u(rng)) * 10.0f;
    const glm::vec3 half(size(rng), size(rng), size(rng));
    const float aspect = (i % 2) ? kW / kH : 0.5f;  // landscape and portrait
    const float h = kW / aspect;
    c.frame(centre - half, centre + half, aspect);
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 corner = centre + half * glm::vec3((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
      const auto s = c.project(corner, kW, h);
      EXPECT_TRUE(s.visible) << "seed 3, case " << i << ", corner " << k;
    }
  }
}

TEST(OrbitCamera, FrameOfADegenerateBoxIsFiniteAndVisible) {
  OrbitCamera c;
  const glm::vec3 p(1.0f, 2.0f, 3.0f);
  c.frame(p, p);  // zero size: must not divide by zero (traps are on)
  EXPECT_TRUE(std::isfinite(c.distance));
  EXPECT_GT(c.distance, 0.0f);
  EXPECT_TRUE(c.project(p, kW, kH).visible);
  c.frame(glm::vec3(1.0f), glm::vec3(-1.0f));  // inverted box is treated as its proper box
  EXPECT_TRUE(c.project(glm::vec3(1.0f), kW, kH).visible);
}

TEST(OrbitCamera, RotateClampsPitchAwayFromThePolesAndKeepsDistance) {
  OrbitCamera c;
  const float d = c.distance;
  const glm::vec3 target = c.target;
  c.rotate(0.0f, 1e6f);
  EXPECT_LE(c.pitch, OrbitCamera::kMaxPitch);
  c.rotate(0.0f, -1e6f);
  EXPECT_GE(c.pitch, -OrbitCamera::kMaxPitch);
  c.rotate(123.0f, 45.0f);
  EXPECT_NEAR(glm::distance(c.eye(), c.target), d, 1e-4f);
  EXPECT_EQ(c.target, target);
  EXPECT_TRUE(std::isfinite(glm::length(c.view()[0])));
}

TEST(OrbitCamera, PanMovesTheTargetInTheScreenPlaneAndTheTargetFollowsTheCursor) {
  OrbitCamera c;
  const glm::vec3 before = c.target;
  const glm::vec3 forward = c.forward();
  const float d = c.distance;
  c.pan(100.0f, -40.0f, glm::vec2(kW, kH));
  EXPECT_NEAR(glm::dot(c.target - before, forward), 0.0f, 1e-5f);
  EXPECT_FLOAT_EQ(c.distance, d);
  // The old target now sits where the cursor was dragged to: centre + (100, -40) pixels.
  const auto s = c.project(before, kW, kH);
  EXPECT_NEAR(s.pixel.x, kW / 2 + 100.0f, 1e-2f);
  EXPECT_NEAR(s.pixel.y, kH / 2 - 40.0f, 1e-2f);
  c.pan(5.0f, 5.0f, glm::vec2(0.0f, 0.0f));  // zero viewport: no division by zero
  EXPECT_TRUE(std::isfinite(c.target.x + c.target.y + c.target.z));
}

TEST(OrbitCamera, ZoomIsMultiplicativeAndClamped) {
  OrbitCamera c;
  const float d = c.distance;
  c.zoom(1.0f);
  EXPECT_LT(c.distance, d);
  c.zoom(-1.0f);
  EXPECT_NEAR(c.distance, d, 1e-4f);
  c.zoom(1e4f);
  EXPECT_GE(c.distance, OrbitCamera::kMinDistance);
  c.zoom(-1e4f);
  EXPECT_LE(c.distance, OrbitCamera::kMaxDistance);
}

TEST(OrbitCamera, DegenerateViewportAndAspectGiveFiniteMatrices) {
  OrbitCamera c;
  const glm::mat4 p = c.projection(0.0f);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(std::isfinite(glm::length(p[i])));
  const auto ray = c.ray(0.0f, 0.0f, 0.0f, 0.0f);
  EXPECT_TRUE(std::isfinite(glm::length(ray.direction)));
}

// Issue 15: orbiting (or panning) below the ground showed a grey screen that neither F nor R
// recovered. Whatever the drags, the eye stays above the ground plane y = 0 (the grid).
TEST(OrbitCamera, NoOrbitPanOrZoomTakesTheEyeBelowTheGround) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  OrbitCamera c;
  for (int i = 0; i < 2000; ++i) {
    switch (i % 3) {
      case 0:
        c.rotate(400.0f * u(rng), 400.0f * u(rng));
        break;
      case 1:
        c.pan(300.0f * u(rng), 300.0f * u(rng), glm::vec2(kW, kH));
        break;
      default:
        c.zoom(5.0f * u(rng));
        break;
    }
    ASSERT_GE(c.eye().y, c.groundHeight + 0.99f * c.minEyeHeight()) << "seed 15, step " << i;
    ASSERT_GE(c.target.y, c.groundHeight) << "seed 15, step " << i;
  }
}

TEST(OrbitCamera, DraggingStraightDownStopsAtTheGroundNotBelowIt) {
  OrbitCamera c;
  c.target = glm::vec3(0.0f, 0.5f, 0.0f);
  c.distance = 6.0f;
  c.rotate(0.0f, -5000.0f);  // far past the horizon
  // eye.y = 0.5 + 6 sin(pitch) = the smallest allowed height, 1 % of the distance.
  EXPECT_NEAR(c.eye().y, 0.06f, 1e-4f);
  EXPECT_LT(c.pitch, 0.0f) << "a target above the ground may still be seen from slightly below its height";
}

TEST(OrbitCamera, WithoutTheGroundRuleThePitchReachesTheLowerPole) {
  OrbitCamera c;
  c.keepAboveGround = false;
  c.rotate(0.0f, -5000.0f);
  EXPECT_FLOAT_EQ(c.pitch, -OrbitCamera::kMaxPitch);
}
