// Coursework 1, public tests (docs/course/coursework-1-reach-and-walk.md). The instructor's held-out tests
// check the same behaviour with other gaits, proportions and goals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include "physics/coursework/walker.h"
#include "support/expect_helpers.h"

namespace pba::coursework {
namespace {

const GaitDesc kGait{};  // stride 0.7 m, step height 0.08 m, duty factor 0.6, 1.2 m/s

// A stance foot in world coordinates: the hip has moved stride·u along x at phase u (one cycle covers
// one stride), so hip + offset must stay put. Finite differences of it over the stance phase are zero.
TEST(CW1_1_FootOffset, PlantedFootDoesNotSlideDuringStance) {
  const Vec3 first = Vec3(0.0) + footOffset(kGait, 0.0);
  for (Real u = 0.05; u < kGait.dutyFactor; u += 0.05) {
    const Vec3 world = Vec3(kGait.stride * u, 0.0, 0.0) + footOffset(kGait, u);
    SCOPED_TRACE("phase " + std::to_string(u));
    EXPECT_VEC3_NEAR(world, first, 1e-12);
  }
}

TEST(CW1_1_FootOffset, StanceIsCentredOnTheHip) {
  // Stance covers stride·dutyFactor of ground; centred: it starts that much / 2 ahead.
  const Real half = 0.5 * kGait.stride * kGait.dutyFactor;
  EXPECT_NEAR(footOffset(kGait, 0.0).x, half, 1e-12);
  EXPECT_NEAR(footOffset(kGait, kGait.dutyFactor - 1e-9).x, -half, 1e-8);
}

TEST(CW1_1_FootOffset, SwingPeaksAtStepHeightInItsMiddle) {
  const Real middle = kGait.dutyFactor + 0.5 * (1.0 - kGait.dutyFactor);
  EXPECT_NEAR(footOffset(kGait, middle).y, kGait.stepHeight, 1e-12);
  for (Real u = 0.0; u < 1.0; u += 0.01) {
    const Vec3 o = footOffset(kGait, u);
    EXPECT_GE(o.y, -1e-12) << "phase " << u;
    EXPECT_LE(o.y, kGait.stepHeight + 1e-12) << "phase " << u;
  }
}

TEST(CW1_1_FootOffset, CycleIsContinuousAndPeriodic) {
  // Steps of 1e-4 cycle: the foot moves at most stride·(a few) per cycle, so a jump above 1e-3 m is a gap.
  Vec3 last = footOffset(kGait, 0.0);
  for (int k = 1; k <= 10000; ++k) {
    const Vec3 o = footOffset(kGait, k * 1e-4);
    EXPECT_LT(glm::length(o - last), 1e-3) << "phase " << k * 1e-4;
    last = o;
  }
  EXPECT_VEC3_NEAR(footOffset(kGait, 1.3), footOffset(kGait, 0.3), 1e-12);
  // Over the cycle the foot ranges over the ground the body covers while it is planted, stride·dutyFactor.
  Real lo = 1e9, hi = -1e9;
  for (int k = 0; k < 1000; ++k)
    lo = std::min(lo, footOffset(kGait, k * 1e-3).x), hi = std::max(hi, footOffset(kGait, k * 1e-3).x);
  EXPECT_NEAR(hi - lo, kGait.stride * kGait.dutyFactor, 1e-3);
}

const Vec3 kShoulder{0.0, 1.45, -0.19};
const Real kReach = 0.58;
const Vec3 kHanging = kShoulder + Vec3(0.0, -0.56, 0.0);

TEST(CW1_2_ReachTarget, EndsOfTheBlendAreTheAnimatedHandAndTheGoal) {
  const Vec3 goal = kShoulder + Vec3(0.3, -0.1, -0.2);  // 0.37 m away: in reach
  EXPECT_VEC3_NEAR(reachTarget(kShoulder, kReach, kHanging, goal, 0.0), kHanging, 1e-12);
  EXPECT_VEC3_NEAR(reachTarget(kShoulder, kReach, kHanging, goal, 1.0), goal, 1e-12);
  // Any ease symmetric about w = 1/2 passes through the midpoint there.
  EXPECT_VEC3_NEAR(reachTarget(kShoulder, kReach, kHanging, goal, 0.5), 0.5 * (kHanging + goal), 1e-12);
}

TEST(CW1_2_ReachTarget, EaseStartsAndEndsAtRest) {
  // One-sided differences at w = 0 and 1: a cubic with zero slope moves O(ε²), a linear blend O(ε).
  const Vec3 goal = kShoulder + Vec3(0.3, -0.1, -0.2);
  const Real eps = 1e-4;
  const Real span = glm::length(goal - kHanging);
  EXPECT_LT(glm::length(reachTarget(kShoulder, kReach, kHanging, goal, eps) - kHanging), 10.0 * eps * eps * span);
  EXPECT_LT(glm::length(reachTarget(kShoulder, kReach, kHanging, goal, 1.0 - eps) - goal), 10.0 * eps * eps * span);
}

TEST(CW1_2_ReachTarget, OutOfReachGoalIsPulledOntoTheReachSphere) {
  const Vec3 goal = kShoulder + Vec3(2.0, 0.0, 0.0);
  const Vec3 t = reachTarget(kShoulder, kReach, kHanging, goal, 1.0);
  EXPECT_NEAR(glm::length(t - kShoulder), kReach, 1e-12);
  EXPECT_VEC3_NEAR(t, kShoulder + Vec3(kReach, 0.0, 0.0), 1e-12);
}

// The whole walker: the two tasks and the library's two-bone IK together.
TEST(CW1_Walker, BonesKeepTheirLengthsAndStanceFeetStayPut) {
  const WalkerDesc desc;
  WalkerState state;
  const Real h = 1.0 / 120.0;
  Vec3 previousLeft(0.0);
  bool previousStance = false;
  for (int frame = 0; frame < 480; ++frame) {
    stepWalker(desc, state, h);
    const WalkerPose& p = state.pose;
    for (int s = 0; s < 2; ++s) {
      EXPECT_NEAR(glm::length(p.knees[s] - p.hips[s]), desc.thigh, 1e-9);
      EXPECT_NEAR(glm::length(p.feet[s] - p.knees[s]), desc.shin, 1e-9);
      EXPECT_NEAR(glm::length(p.elbows[s] - p.shoulders[s]), desc.upperArm, 1e-9);
      EXPECT_GE(p.feet[s].y, -1e-9);
    }
    const Real phase = state.time * desc.gait.speed / desc.gait.stride;
    const bool stance = phase - std::floor(phase) < desc.gait.dutyFactor - 1e-9 && phase - std::floor(phase) > 1e-9;
    if (stance && previousStance) {
      SCOPED_TRACE("frame " + std::to_string(frame));
      EXPECT_VEC3_NEAR(p.feet[0], previousLeft, 1e-9);
    }
    previousStance = stance;
    previousLeft = p.feet[0];
    if (frame == 155) {  // t = 1.3 s: the reach is complete, and the goal is in reach of the walking body
      SCOPED_TRACE("the reach at 1.3 s");
      EXPECT_VEC3_NEAR(p.hands[1], desc.reachGoal, 1e-3);
    }
  }
}

TEST(CW1_Walker, RightHandArrivesAtAGoalInReach) {
  WalkerDesc desc;
  desc.gait.speed = 0.0001;  // nearly standing, so the goal beside the shoulder stays in reach
  desc.reachGoal = Vec3(0.35, 1.3, -0.3);
  WalkerState state;
  for (int frame = 0; frame < 240; ++frame) stepWalker(desc, state, 1.0 / 120.0);  // 2 s > start + duration
  EXPECT_VEC3_NEAR(state.pose.hands[1], desc.reachGoal, 1e-3);
  // Standing at the start of the cycle: the left foot planted ahead of its hip, the right one behind.
  EXPECT_GT(state.pose.feet[0].x - state.pose.pelvis.x, 0.1);
  EXPECT_LT(state.pose.feet[1].x - state.pose.pelvis.x, -0.05);
}

}  // namespace
}  // namespace pba::coursework
