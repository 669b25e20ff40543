// Coursework 3, held-out tests: the instructor's, never in the student hand-out. Random trajectories and
// decays (fixed seeds), quaternion signs, other steps, degenerate inputs, and other seeds, stairs and
// masses for the whole fall.
#include <gtest/gtest.h>

#include <cmath>
#include "physics/coursework/stairs_fall.h"
#include "support/expect_helpers.h"
#include "support/portable_random.h"

namespace pba::coursework {
namespace {

using pba::test::uniform;

Vec3 randomUnit(std::mt19937_64& rng) {
  return glm::normalize(Vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)) + 1e-3);
}

TEST(CW3_1_HandOverHeldOut, RandomParabolasAndAcceleratedSpinsAreExact) {
  std::mt19937_64 rng(2718);
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 c0(uniform(rng, -2, 2), uniform(rng, 0, 3), uniform(rng, -2, 2));
    const Vec3 v0(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -5, 5));
    const Vec3 a(uniform(rng, -20, 20), uniform(rng, -20, 20), uniform(rng, -20, 20));
    const Vec3 axis = randomUnit(rng);
    const Quat base = glm::angleAxis(uniform(rng, 0, 3), randomUnit(rng));
    const Real w0 = uniform(rng, -8, 8), alpha = uniform(rng, -30, 30);
    const Real h = uniform(rng, 1e-3, 0.02), t = uniform(rng, 0.1, 2.0);
    // Keep every frame-to-frame turn below π (a larger one is ambiguous from poses alone).
    const auto pose = [&](Real s) {
      return BonePose{c0 + v0 * s + 0.5 * a * s * s, glm::angleAxis(w0 * s + 0.5 * alpha * s * s, axis) * base};
    };
    const BoneMotion m = handOverMotion(pose(t - 2 * h), pose(t - h), pose(t), h);
    SCOPED_TRACE(::testing::Message() << "seed 2718, trial " << trial);
    EXPECT_VEC3_NEAR(m.velocity, v0 + a * t, 1e-7);
    EXPECT_VEC3_NEAR(m.angularVelocity, (w0 + alpha * t) * axis, 1e-6);
  }
}

TEST(CW3_1_HandOverHeldOut, QuaternionSignsBetweenFramesChangeNothing) {
  const Vec3 axis = glm::normalize(Vec3(0.0, 1.0, 1.0));
  const Real h = 0.02;
  BonePose f[3];
  for (int k = 0; k < 3; ++k) f[k] = {Vec3(0.1 * k, 0.0, 0.0), glm::angleAxis(3.0 + 0.2 * k, axis)};
  const BoneMotion plain = handOverMotion(f[0], f[1], f[2], h);
  EXPECT_VEC3_NEAR(plain.angularVelocity, 10.0 * axis, 1e-9);
  EXPECT_VEC3_NEAR(plain.velocity, Vec3(5.0, 0.0, 0.0), 1e-9);
  for (int flip = 0; flip < 3; ++flip) {
    BonePose g[3] = {f[0], f[1], f[2]};
    g[flip].orientation = -g[flip].orientation;
    const BoneMotion m = handOverMotion(g[0], g[1], g[2], h);
    SCOPED_TRACE(::testing::Message() << "frame " << flip << " negated");
    EXPECT_VEC3_NEAR(m.angularVelocity, plain.angularVelocity, 1e-9);
  }
}

TEST(CW3_1_HandOverHeldOut, ABadStepGivesZeroButAGoodOneDoesNot) {
  const BonePose a{Vec3(0.0), Quat(1, 0, 0, 0)}, b{Vec3(0.1, 0, 0), glm::angleAxis(0.1, Vec3(0, 0, 1))},
      c{Vec3(0.2, 0, 0), glm::angleAxis(0.2, Vec3(0, 0, 1))};
  for (const Real h : {0.0, -0.01}) {
    const BoneMotion m = handOverMotion(a, b, c, h);
    SCOPED_TRACE(::testing::Message() << "h = " << h);
    EXPECT_VEC3_NEAR(m.velocity, Vec3(0.0), 0.0);
    EXPECT_VEC3_NEAR(m.angularVelocity, Vec3(0.0), 0.0);
  }
  const BoneMotion good = handOverMotion(a, b, c, 0.1);
  EXPECT_VEC3_NEAR(good.velocity, Vec3(1.0, 0.0, 0.0), 1e-12);
  EXPECT_VEC3_NEAR(good.angularVelocity, Vec3(0.0, 0.0, 1.0), 1e-9);
}

TEST(CW3_1_HandOverHeldOut, OtherStairsStepsAndMassesKeepTheFigureContinuous) {
  StairsFallDesc desc;
  desc.rise = 0.22;
  desc.figureMass = 50.0;
  desc.seed = 11;
  desc.switchAt = 0.3;
  desc.tipAcceleration = 5.0;
  auto built = buildStairsFall(desc);
  ASSERT_TRUE(built) << built.error();
  StairsFall& scene = built.value();
  const Real h = 1.0 / 120.0;
  while (scene.controlled) stepStairsFall(scene, h);
  const std::vector<BoneMotion> exact = scriptedMotion(scene, scene.switchedAt);
  const std::vector<BoneMotion> started = figureMotion(scene);
  ASSERT_EQ(started.size(), exact.size());
  for (std::size_t b = 0; b < exact.size(); ++b) {
    SCOPED_TRACE(::testing::Message() << "bone " << b);
    EXPECT_VEC3_NEAR(started[b].angularVelocity, exact[b].angularVelocity, 1e-9);
    EXPECT_VEC3_NEAR(started[b].velocity, exact[b].velocity, 0.004);  // O(h²)
  }
}

TEST(CW3_2_RestDetectionHeldOut, RandomDecaysComeToRestWhereTheClosedFormSays) {
  std::mt19937_64 rng(1618);
  for (int trial = 0; trial < 40; ++trial) {
    RestDetector d;
    d.settings.quietTime = uniform(rng, 0.2, 1.0);
    const bool angular = trial % 2 == 1;
    const Real v0 = uniform(rng, 1.0, 10.0), tau = uniform(rng, 0.1, 1.0), h = uniform(rng, 0.002, 0.02);
    const Real tolerance = angular ? d.settings.angularSpeed : d.settings.linearSpeed;
    const Real tStar = tau * std::log(v0 / tolerance);
    Real declared = -1.0;
    for (int k = 1; k * h < tStar + d.settings.quietTime + 3 * h; ++k) {
      const Real t = k * h, v = v0 * std::exp(-t / tau);
      std::vector<BoneMotion> bones(5);
      bones[static_cast<std::size_t>(trial % 5)] =
          angular ? BoneMotion{Vec3(0.0), Vec3(0.0, v, 0.0)} : BoneMotion{Vec3(v, 0.0, 0.0), Vec3(0.0)};
      updateRest(d, bones, t, h);
      if (d.atRest && declared < 0.0) declared = t;
    }
    ASSERT_TRUE(d.atRest) << "seed 1618, trial " << trial;
    EXPECT_NEAR(d.restTime, tStar, h + 1e-9) << "seed 1618, trial " << trial;
    EXPECT_NEAR(declared - d.restTime, d.settings.quietTime, h + 1e-9) << "seed 1618, trial " << trial;
  }
}

TEST(CW3_2_RestDetectionHeldOut, DegenerateInputsAndAFigureThatMovesAgain) {
  RestDetector d;
  const std::vector<BoneMotion> still(4), none;
  // h ≤ 0 changes nothing; an empty figure is quiet.
  for (int k = 1; k <= 100; ++k) updateRest(d, still, 0.0, 0.0);
  EXPECT_EQ(d.quiet, 0.0);
  EXPECT_FALSE(d.atRest);
  for (int k = 1; k <= 60; ++k) updateRest(d, none, k * 0.01, 0.01);
  ASSERT_TRUE(d.atRest);
  EXPECT_NEAR(d.restTime, 0.0, 1e-9);
  // A figure at rest that moves again is not at rest any more.
  std::vector<BoneMotion> slides(4);
  slides[2].velocity = Vec3(0.0, -0.3, 0.0);
  updateRest(d, slides, 0.61, 0.01);
  EXPECT_FALSE(d.atRest);
  EXPECT_EQ(d.quiet, 0.0);
}

TEST(CW3_StairsFallHeldOut, OtherSeedsStairsAndMassesComeToRestAtTheBottom) {
  struct Case {
    unsigned seed;
    Real rise, mass;
  };
  for (const Case c : {Case{1, 0.18, 75.0}, Case{2, 0.25, 90.0}, Case{3, 0.20, 110.0}, Case{4, 0.22, 50.0},
                       Case{2, 0.16, 40.0}, Case{10, 0.22, 75.0}}) {
    StairsFallDesc desc;
    desc.seed = c.seed;
    desc.rise = c.rise;
    desc.figureMass = c.mass;
    auto built = buildStairsFall(desc);
    ASSERT_TRUE(built) << built.error();
    StairsFall& scene = built.value();
    for (int k = 0; k < 20 * 60 && !scene.rest.atRest; ++k) stepStairsFall(scene, 1.0 / 60.0);
    ASSERT_TRUE(scene.rest.atRest) << "seed " << c.seed << ": still moving after 20 s";
    const Vec3 com = figureCenterOfMass(scene);
    EXPECT_LT(com.y, c.rise + 0.25) << "seed " << c.seed;
    EXPECT_GT(com.x, -desc.run) << "seed " << c.seed;
    EXPECT_GT(scene.rest.restTime, scene.switchedAt) << "seed " << c.seed;
  }
}

}  // namespace
}  // namespace pba::coursework
