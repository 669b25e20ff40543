// Coursework 1, held-out tests: the instructor's, never in the student hand-out (tools/student_release.sh
// leaves tests/coursework/heldout/ out; `./pba mark` adds it). Same behaviour as the public tests, other
// angles: random gaits and proportions (fixed seeds), phases outside [0, 1), degenerate reach inputs, and a
// long walk.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include "physics/coursework/walker.h"
#include "support/expect_helpers.h"
#include "support/portable_random.h"

namespace pba::coursework {
namespace {

using Rng = std::mt19937_64;
using pba::test::uniform;

Vec3 randomVec3(Rng& rng, Real lo, Real hi) {
  return {uniform(rng, lo, hi), uniform(rng, lo, hi), uniform(rng, lo, hi)};
}

GaitDesc randomGait(Rng& rng) {
  GaitDesc g;
  g.stride = uniform(rng, 0.3, 1.0);
  g.stepHeight = uniform(rng, 0.02, 0.2);
  g.dutyFactor = uniform(rng, 0.5, 0.8);
  g.speed = uniform(rng, 0.5, 2.0);
  return g;
}

TEST(CW1_1_FootOffsetHeldOut, RandomGaitsPlantTheFootAndPeakMidSwing) {
  Rng rng(2026);
  for (int trial = 0; trial < 50; ++trial) {
    const GaitDesc g = randomGait(rng);
    SCOPED_TRACE("seed 2026, trial " + std::to_string(trial));
    const Vec3 first = footOffset(g, 0.0);
    for (Real u = 0.0; u < g.dutyFactor; u += 0.02)
      EXPECT_VEC3_NEAR(Vec3(g.stride * u, 0.0, 0.0) + footOffset(g, u), first, 1e-12);
    EXPECT_NEAR(footOffset(g, g.dutyFactor + 0.5 * (1.0 - g.dutyFactor)).y, g.stepHeight, 1e-12);
  }
}

TEST(CW1_1_FootOffsetHeldOut, NegativeAndLargePhasesWrap) {
  const GaitDesc g;
  for (Real u : {0.1, 0.45, 0.7, 0.95}) {
    EXPECT_VEC3_NEAR(footOffset(g, u - 3.0), footOffset(g, u), 1e-9);
    EXPECT_VEC3_NEAR(footOffset(g, u + 1000.0), footOffset(g, u), 1e-9);
  }
  EXPECT_GT(footOffset(g, -0.2).y, 0.0);  // phase 0.8: in the air
}

TEST(CW1_1_FootOffsetHeldOut, SwingNeverMovesBackwardOverTheGround) {
  Rng rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const GaitDesc g = randomGait(rng);
    Real lastWorld = -1e9;
    for (int k = 0; k <= 1000; ++k) {
      const Real u = g.dutyFactor + (1.0 - g.dutyFactor) * k / 1000.0 * 0.999999;
      const Real world = g.stride * u + footOffset(g, u).x;
      EXPECT_GE(world, lastWorld - 1e-12) << "seed 7, trial " << trial << ", phase " << u;
      lastWorld = world;
    }
    // Over one swing the foot covers a whole stride of ground (it was still for the rest of the cycle).
    const Real end = 1.0 - 1e-9;
    EXPECT_NEAR(g.stride * end + footOffset(g, end).x - (g.stride * g.dutyFactor + footOffset(g, g.dutyFactor).x),
                g.stride, 1e-6)
        << "seed 7, trial " << trial;
  }
}

TEST(CW1_2_ReachTargetHeldOut, WeightsOutsideTheUnitIntervalAreClamped) {
  const Vec3 s(0.0, 1.4, 0.2), hand = s + Vec3(0.0, -0.5, 0.0), goal = s + Vec3(0.2, 0.1, 0.1);
  EXPECT_VEC3_NEAR(reachTarget(s, 0.6, hand, goal, -2.0), hand, 1e-12);
  EXPECT_VEC3_NEAR(reachTarget(s, 0.6, hand, goal, 7.0), goal, 1e-12);
}

TEST(CW1_2_ReachTargetHeldOut, RandomTargetsStayWithinReach) {
  Rng rng(99);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 s = randomVec3(rng, -1.0, 1.0);
    const Real reach = uniform(rng, 0.2, 1.0);
    // Even trials: a goal within reach (|offset| ≤ 0.57·√3 reach < reach); odd ones: anywhere.
    const Vec3 hand = s + randomVec3(rng, -0.1, 0.1);
    const Vec3 goal = s + (trial % 2 == 0 ? randomVec3(rng, -0.57, 0.57) * reach : randomVec3(rng, -3.0, 3.0));
    const Real w = uniform(rng, 0.0, 1.0);
    const Vec3 t = reachTarget(s, reach, hand, goal, w);
    EXPECT_LE(glm::length(t - s), reach + 1e-12) << "seed 99, trial " << trial;
    // Inside the reach it is a point of the segment from the animated hand to the goal (the two distances
    // add up to the segment's length); otherwise it was pulled onto the reach sphere.
    if (glm::length(t - s) < reach - 1e-9) {
      EXPECT_NEAR(glm::length(t - hand) + glm::length(goal - t), glm::length(goal - hand), 1e-9)
          << "seed 99, trial " << trial;
    } else {
      EXPECT_NEAR(glm::length(t - s), reach, 1e-9) << "seed 99, trial " << trial;
    }
    // With the goal in reach and more than half the weight, the eased blend is past the middle.
    if (trial % 2 == 0 && w > 0.55) {
      EXPECT_LT(glm::length(t - goal), 0.5 * glm::length(hand - goal)) << "seed 99, trial " << trial;
    }
  }
}

TEST(CW1_2_ReachTargetHeldOut, GoalAtTheShoulderIsFinite) {
  const Vec3 s(0.0, 1.4, 0.0);
  const Vec3 t = reachTarget(s, 0.5, s + Vec3(0.0, -0.45, 0.0), s, 1.0);
  EXPECT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z));
  EXPECT_VEC3_NEAR(t, s, 1e-12);
}

TEST(CW1_WalkerHeldOut, ShortLegsAndLongWalkStayFiniteOnTheGround) {
  WalkerDesc desc;
  desc.thigh = 0.38;
  desc.shin = 0.36;
  desc.hipHeight = 0.7;
  desc.gait.stride = 0.5;
  desc.gait.speed = 0.9;
  WalkerState state;
  Real highestFoot = 0.0;
  for (int frame = 0; frame < 20000; ++frame) {
    stepWalker(desc, state, 1.0 / 60.0);
    highestFoot = std::max(highestFoot, state.pose.feet[0].y);
    if (frame == 77) {  // t = 1.3 s: the reach is complete and the default goal in reach of the body
      EXPECT_LT(glm::length(state.pose.hands[1] - desc.reachGoal), 0.02);
    }
    for (int s = 0; s < 2; ++s) {
      ASSERT_TRUE(std::isfinite(state.pose.feet[s].x) && std::isfinite(state.pose.hands[s].y)) << frame;
      ASSERT_GE(state.pose.feet[s].y, -1e-9) << frame;
      ASSERT_NEAR(glm::length(state.pose.feet[s] - state.pose.knees[s]), desc.shin, 1e-9) << frame;
    }
  }
  EXPECT_GT(highestFoot, 0.5 * desc.gait.stepHeight);  // the feet were lifted
}

TEST(CW1_WalkerHeldOut, OutOfReachGoalStretchesTheArmTowardIt) {
  WalkerDesc desc;
  desc.gait.speed = 0.0001;
  desc.reachGoal = Vec3(0.0, 3.0, -0.19);  // straight above the right shoulder, far out of reach
  WalkerState state;
  for (int frame = 0; frame < 240; ++frame) stepWalker(desc, state, 1.0 / 120.0);
  const Vec3 arm = state.pose.hands[1] - state.pose.shoulders[1];
  EXPECT_NEAR(glm::length(arm), desc.upperArm + desc.forearm, 1e-6);
  EXPECT_GT(arm.y, 0.99 * glm::length(arm));
}

}  // namespace
}  // namespace pba::coursework
