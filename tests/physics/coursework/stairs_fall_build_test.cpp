// The coursework 3 scene (reference library code, no task): bad descriptions name their field, the figure
// stands on the top step behind its nosing, and the script's velocities are its poses' derivatives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include "physics/coursework/stairs_fall.h"
#include "support/expect_helpers.h"

namespace pba::coursework {
namespace {

TEST(StairsFallBuild, BadDescriptionsNameTheirField) {
  const auto fails = [](auto change, const char* field) {
    StairsFallDesc desc;
    change(desc);
    auto built = buildStairsFall(desc);
    ASSERT_FALSE(built) << field;
    EXPECT_NE(built.error().find(field), std::string::npos) << built.error();
  };
  fails([](StairsFallDesc& d) { d.steps = 0; }, "steps");
  fails([](StairsFallDesc& d) { d.rise = 0.0; }, "rise");
  fails([](StairsFallDesc& d) { d.run = -0.3; }, "run");
  fails([](StairsFallDesc& d) { d.figureMass = 0.0; }, "figureMass");
  fails([](StairsFallDesc& d) { d.figureScale = std::nan(""); }, "figureScale");
  fails([](StairsFallDesc& d) { d.switchAt = -1.0; }, "switchAt");
  fails([](StairsFallDesc& d) { d.jointFriction = -1.0; }, "jointFriction");
  fails([](StairsFallDesc& d) { d.rest.quietTime = std::nan(""); }, "rest.quietTime");
}

TEST(StairsFallBuild, TheFigureStandsOnTheTopStepBehindItsNosing) {
  for (const unsigned seed : {0u, 3u, 9u}) {
    StairsFallDesc desc;
    desc.seed = seed;
    auto built = buildStairsFall(desc);
    ASSERT_TRUE(built) << built.error();
    Real lowest = 1e30, front = -1e30;
    for (const ragdoll::BoneDesc& b : built.value().figure.bones)
      for (int k = 0; k < 8; ++k) {
        const Vec3 s((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0);
        const Vec3 corner = b.center + b.orientation * (s * b.halfExtents);
        lowest = std::min(lowest, corner.y);
        front = std::max(front, corner.x);
      }
    const Real nosing = -(desc.steps - 1) * desc.run;
    EXPECT_GT(lowest, desc.steps * desc.rise - 0.02) << "seed " << seed;  // the human's feet rest on y = 0
    EXPECT_LT(lowest, desc.steps * desc.rise + 0.02) << "seed " << seed;
    EXPECT_LT(front, nosing) << "seed " << seed;
    EXPECT_GT(front, nosing - 0.05) << "seed " << seed;
    EXPECT_TRUE(built.value().controlled);
  }
}

TEST(StairsFallBuild, ScriptedVelocitiesAreTheDerivativesOfTheScriptedPoses) {
  auto built = buildStairsFall(StairsFallDesc{});
  ASSERT_TRUE(built) << built.error();
  const StairsFall& scene = built.value();
  const Real t = 0.3, e = 1e-5;
  const std::vector<BonePose> ahead = scriptedPose(scene, t + e), behind = scriptedPose(scene, t - e);
  const std::vector<BoneMotion> motion = scriptedMotion(scene, t);
  for (std::size_t b = 0; b < motion.size(); ++b) {
    // Central differences: error O(e²) ≈ 1e-10 m/s, against rounding of 1e-16 / e ≈ 1e-11 m/s.
    SCOPED_TRACE(::testing::Message() << "bone " << b);
    EXPECT_VEC3_NEAR(motion[b].velocity, (ahead[b].center - behind[b].center) / (2 * e), 1e-8);
  }
}

TEST(StairsFallBuild, SwitchingAtTheStartHandsOverAFigureAtRest) {
  StairsFallDesc desc;
  desc.switchAt = 0.0;
  auto built = buildStairsFall(desc);
  ASSERT_TRUE(built) << built.error();
  EXPECT_FALSE(built.value().controlled);
  EXPECT_EQ(built.value().switchedAt, 0.0);
}

}  // namespace
}  // namespace pba::coursework
