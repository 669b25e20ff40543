// Coursework 2, public tests (docs/course/coursework-2-cloth-meets-rigid.md). The instructor's held-out
// tests check the same behaviour with other masses, sizes, seeds and speeds.
#include <gtest/gtest.h>

#include "physics/coursework/ball_on_cloth.h"
#include "support/expect_helpers.h"

namespace pba::coursework {
namespace {

TEST(CW2_1_BallContact, PenetratingParticleEndsOnTheSphereAndMomentumIsKept) {
  const Vec3 xp(0.1, 0.05, 0.0), xb(0.0);
  const Real wp = 4.0, wb = 1.0, r = 0.2;
  const BallContact k = ballParticleContact(xp, wp, xb, wb, r);
  EXPECT_NEAR(glm::length((xp + k.particle) - (xb + k.ball)), r, 1e-12);
  EXPECT_VEC3_NEAR(k.particle / wp + k.ball / wb, Vec3(0.0), 1e-12);
  // Both move along the line of centres, apart.
  EXPECT_GT(glm::dot(k.particle, xp - xb), 0.0);
  EXPECT_LT(glm::dot(k.ball, xp - xb), 0.0);
}

TEST(CW2_1_BallContact, OnlyPointsInsideAreMoved) {
  const BallContact outside = ballParticleContact(Vec3(0.3, 0.0, 0.0), 1.0, Vec3(0.0), 1.0, 0.2);
  EXPECT_VEC3_NEAR(outside.particle, Vec3(0.0), 0.0);
  EXPECT_VEC3_NEAR(outside.ball, Vec3(0.0), 0.0);
  // Just inside, equal masses: each moves half of the 0.01 m overlap.
  const BallContact inside = ballParticleContact(Vec3(0.19, 0.0, 0.0), 1.0, Vec3(0.0), 1.0, 0.2);
  EXPECT_VEC3_NEAR(inside.particle, Vec3(0.005, 0.0, 0.0), 1e-12);
  EXPECT_VEC3_NEAR(inside.ball, Vec3(-0.005, 0.0, 0.0), 1e-12);
}

TEST(CW2_1_BallContact, ImmovableBallMovesOnlyTheParticle) {
  const BallContact k = ballParticleContact(Vec3(0.0, 0.15, 0.0), 2.0, Vec3(0.0), 0.0, 0.2);
  EXPECT_VEC3_NEAR(k.ball, Vec3(0.0), 0.0);
  EXPECT_VEC3_NEAR(k.particle, Vec3(0.0, 0.05, 0.0), 1e-12);
}

TEST(CW2_2_CoupledStep, BallAloneFallsAsSymplecticEuler) {
  BallOnClothDesc desc;
  desc.ballStart = Vec3(5.0, 3.0, 0.0);  // far from the cloth
  desc.damping = 0.0;
  auto scene = buildBallOnCloth(desc);
  ASSERT_TRUE(scene) << scene.error();
  const Real h = 0.01, g = 9.81;
  const int steps = 50;
  for (int k = 0; k < steps; ++k) stepBallOnCloth(scene.value(), h);
  // Symplectic Euler: v_k = −k g h, y_k = y_0 − g h² k(k+1)/2 (the summed recurrence).
  EXPECT_NEAR(scene.value().ball.velocity.y, -steps * g * h, 1e-10);
  EXPECT_NEAR(scene.value().ball.position.y, 3.0 - g * h * h * steps * (steps + 1) / 2.0, 1e-10);
}

TEST(CW2_2_CoupledStep, TrampolineCatchesTheBall) {
  auto built = buildBallOnCloth(BallOnClothDesc{});
  ASSERT_TRUE(built) << built.error();
  BallOnCloth& scene = built.value();
  const Real h = 1.0 / 240.0;
  for (int k = 0; k < 4 * 240; ++k) stepBallOnCloth(scene, h);  // 4 s
  // Caught: above the floor the cloth hangs over, below where it fell from, nearly at rest, sagging the cloth.
  EXPECT_GT(scene.ball.position.y, 0.0);
  EXPECT_LT(scene.ball.position.y, 1.0 + 0.2);
  EXPECT_LT(glm::length(scene.ball.velocity), 0.1);
  EXPECT_GT(deepestBallPenetration(scene), -0.01);  // within one margin of the surface, never deeper
}

}  // namespace
}  // namespace pba::coursework
