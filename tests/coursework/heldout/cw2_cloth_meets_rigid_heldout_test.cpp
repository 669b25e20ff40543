// Coursework 2, held-out tests: the instructor's, never in the student hand-out. Other masses, sizes,
// random contacts (fixed seeds), momentum without gravity, and a fast ball.
#include <gtest/gtest.h>

#include <cmath>
#include "physics/coursework/ball_on_cloth.h"
#include "support/expect_helpers.h"
#include "support/portable_random.h"

namespace pba::coursework {
namespace {

using pba::test::uniform;

TEST(CW2_1_BallContactHeldOut, RandomContactsLandOnTheSphereAndKeepMomentum) {
  std::mt19937_64 rng(314);
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3 xb(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    const Real r = uniform(rng, 0.05, 0.5);
    const Vec3 dir = glm::normalize(Vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)) + 1e-3);
    const Vec3 xp = xb + dir * (r * uniform(rng, 0.05, 0.999));
    const Real wp = uniform(rng, 0.1, 100.0), wb = uniform(rng, 0.1, 10.0);
    const BallContact k = ballParticleContact(xp, wp, xb, wb, r);
    EXPECT_NEAR(glm::length((xp + k.particle) - (xb + k.ball)), r, 1e-9) << "seed 314, trial " << trial;
    EXPECT_VEC3_NEAR(k.particle / wp + k.ball / wb, Vec3(0.0), 1e-9);
  }
}

TEST(CW2_1_BallContactHeldOut, DegenerateInputsMoveNothingButAGenuineContactDoes) {
  const BallContact genuine = ballParticleContact(Vec3(0.0, 0.0, 0.1), 1.0, Vec3(0.0), 0.0, 0.2);
  EXPECT_VEC3_NEAR(genuine.particle, Vec3(0.0, 0.0, 0.1), 1e-12);
  for (const BallContact& k : {ballParticleContact(Vec3(0.0), 1.0, Vec3(0.0), 1.0, 0.2),           // at the centre
                               ballParticleContact(Vec3(0.1, 0, 0), 0.0, Vec3(0.0), 0.0, 0.2)}) {  // both fixed
    EXPECT_TRUE(std::isfinite(k.particle.x) && std::isfinite(k.ball.x));
    EXPECT_VEC3_NEAR(k.particle, Vec3(0.0), 0.0);
    EXPECT_VEC3_NEAR(k.ball, Vec3(0.0), 0.0);
  }
}

TEST(CW2_1_BallContactHeldOut, PinnedParticlePushesTheWholeCorrectionOntoTheBall) {
  const BallContact k = ballParticleContact(Vec3(0.0, 0.15, 0.0), 0.0, Vec3(0.0), 3.0, 0.2);
  EXPECT_VEC3_NEAR(k.particle, Vec3(0.0), 0.0);
  EXPECT_VEC3_NEAR(k.ball, Vec3(0.0, -0.05, 0.0), 1e-12);
}

TEST(CW2_2_CoupledStepHeldOut, MomentumIsKeptWithoutGravityOrPins) {
  BallOnClothDesc desc;
  desc.resolution = 10;
  desc.gravity = Vec3(0.0);
  desc.damping = 0.0;
  desc.ballStart = Vec3(0.05, 1.5, -0.03);
  desc.ballVelocity = Vec3(0.0, -3.0, 0.0);
  auto built = buildBallOnCloth(desc);
  ASSERT_TRUE(built) << built.error();
  BallOnCloth& scene = built.value();
  for (auto& p : scene.cloth.pins) scene.cloth.inverseMass[p.particle] = 1.0 / 0.01;  // free the corners
  scene.cloth.pins.clear();
  const Vec3 before = totalMomentum(scene);
  for (int k = 0; k < 120; ++k) stepBallOnCloth(scene, 1.0 / 240.0);
  EXPECT_GT(scene.ball.velocity.y, -2.999);  // it hit the cloth
  EXPECT_VEC3_NEAR(totalMomentum(scene), before, 1e-9 * glm::length(before));
}

TEST(CW2_2_CoupledStepHeldOut, HeavierBallSagsTheTrampolineDeeper) {
  Real rest[2];
  for (int m = 0; m < 2; ++m) {
    BallOnClothDesc desc;
    desc.resolution = 16;
    desc.stretchCompliance = 1e-4;
    desc.ballMass = m == 0 ? 0.5 : 4.0;
    auto built = buildBallOnCloth(desc);
    ASSERT_TRUE(built) << built.error();
    for (int k = 0; k < 3 * 240; ++k) stepBallOnCloth(built.value(), 1.0 / 240.0);
    rest[m] = built.value().ball.position.y;
  }
  EXPECT_LT(rest[1], rest[0]);
}

TEST(CW2_2_CoupledStepHeldOut, FastBallStaysFiniteAndNeverEndsDeepInside) {
  BallOnClothDesc desc;
  desc.ballVelocity = Vec3(0.0, -8.0, 0.0);
  desc.ballMass = 2.0;
  auto built = buildBallOnCloth(desc);
  ASSERT_TRUE(built) << built.error();
  BallOnCloth& scene = built.value();
  for (int k = 0; k < 480; ++k) {
    stepBallOnCloth(scene, 1.0 / 240.0);
    ASSERT_TRUE(std::isfinite(scene.ball.position.y)) << "step " << k;
  }
  EXPECT_GT(deepestBallPenetration(scene), -0.01);
  EXPECT_LT(scene.ball.position.y, desc.ballStart.y - 0.5);  // it came down onto the cloth
  EXPECT_LT(glm::length(scene.ball.velocity), 8.0);          // and the cloth took speed off it
}

}  // namespace
}  // namespace pba::coursework
