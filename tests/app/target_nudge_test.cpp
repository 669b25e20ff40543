// The keyboard nudge of a scene's target (app/window/target_nudge.h): which keys nudge, in which direction
// relative to the camera, by how much, and that scenes without a target say so.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "app/window/target_nudge.h"
#include "test_scenes.h"

namespace pba::app {
namespace {

// A scene with one target that records what the runner asks of it.
class TargetScene final : public Scene {
 public:
  std::string description() const override { return "A target to nudge."; }
  void reset() override {}
  void step(Real) override {}
  void draw(DebugDraw&) const override {}
  nlohmann::json metrics() const override { return nlohmann::json::object(); }
  std::optional<std::string> nonFiniteState() const override { return std::nullopt; }
  bool nudge(const Vec3& delta) override {
    target += delta;
    return true;
  }
  Real nudgeStep() const override { return ownStep; }
  Vec3 target{0.0};
  Real ownStep = 0.0;
};

// A camera looking down −z: right +x, up +y, forward −z.
const Vec3 kRight(1, 0, 0), kUp(0, 1, 0), kForward(0, 0, -1);

void expectVecEq(const Vec3& a, const Vec3& b) {
  // Exact: the displacement is a unit vector times the step, no rounding beyond one product.
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
}

TEST(TargetNudge, ArrowsMoveInTheViewPlaneAndPageKeysAlongTheViewDirection) {
  EXPECT_EQ(nudgeDirectionForKey(GLFW_KEY_LEFT, 0), NudgeDirection::Left);
  EXPECT_EQ(nudgeDirectionForKey(GLFW_KEY_RIGHT, 0), NudgeDirection::Right);
  EXPECT_EQ(nudgeDirectionForKey(GLFW_KEY_UP, 0), NudgeDirection::Up);
  EXPECT_EQ(nudgeDirectionForKey(GLFW_KEY_DOWN, 0), NudgeDirection::Down);
  EXPECT_EQ(nudgeDirectionForKey(GLFW_KEY_PAGE_UP, 0), NudgeDirection::Away);
  EXPECT_EQ(nudgeDirectionForKey(GLFW_KEY_PAGE_DOWN, 0), NudgeDirection::Toward);
  EXPECT_EQ(nudgeDirectionForKey(GLFW_KEY_UP, GLFW_MOD_SHIFT), NudgeDirection::Away);
  EXPECT_EQ(nudgeDirectionForKey(GLFW_KEY_DOWN, GLFW_MOD_SHIFT), NudgeDirection::Toward);
  EXPECT_TRUE(nudgeIsFine(GLFW_MOD_CONTROL));
  EXPECT_FALSE(nudgeIsFine(GLFW_MOD_SHIFT));
}

TEST(TargetNudge, NoStandardKeyOfTheLabsNudges) {
  // docs/architecture.md §3: Space/P, O, R, [ ], 1–9, F1/H, F12, L, Tab, F.
  const int standard[] = {GLFW_KEY_SPACE,         GLFW_KEY_P,  GLFW_KEY_O, GLFW_KEY_R,   GLFW_KEY_LEFT_BRACKET,
                          GLFW_KEY_RIGHT_BRACKET, GLFW_KEY_F1, GLFW_KEY_H, GLFW_KEY_F12, GLFW_KEY_L,
                          GLFW_KEY_TAB,           GLFW_KEY_F};
  for (int key : standard) EXPECT_FALSE(nudgeDirectionForKey(key, 0).has_value()) << "GLFW key " << key;
  for (int key = GLFW_KEY_1; key <= GLFW_KEY_9; ++key) EXPECT_FALSE(nudgeDirectionForKey(key, 0).has_value());
}

TEST(TargetNudge, DisplacementFollowsTheCameraAxes) {
  expectVecEq(nudgeDisplacement(NudgeDirection::Right, kRight, kUp, kForward, 0.5), Vec3(0.5, 0, 0));
  expectVecEq(nudgeDisplacement(NudgeDirection::Left, kRight, kUp, kForward, 0.5), Vec3(-0.5, 0, 0));
  expectVecEq(nudgeDisplacement(NudgeDirection::Up, kRight, kUp, kForward, 0.5), Vec3(0, 0.5, 0));
  expectVecEq(nudgeDisplacement(NudgeDirection::Down, kRight, kUp, kForward, 0.5), Vec3(0, -0.5, 0));
  // Toward the camera is against the viewing direction: +z for a camera looking down −z.
  expectVecEq(nudgeDisplacement(NudgeDirection::Toward, kRight, kUp, kForward, 0.5), Vec3(0, 0, 0.5));
  expectVecEq(nudgeDisplacement(NudgeDirection::Away, kRight, kUp, kForward, 0.5), Vec3(0, 0, -0.5));
}

TEST(TargetNudge, StepIsTheScenesOwnElseTwoPercentOfItsSizeAndCtrlMakesItFiner) {
  TargetScene scene;
  ASSERT_TRUE(nudgeScene(scene, NudgeDirection::Right, kRight, kUp, kForward, 10.0, false));
  EXPECT_DOUBLE_EQ(scene.target.x, kNudgeFraction * 10.0);
  scene.target = Vec3(0.0);
  scene.ownStep = 0.05;
  ASSERT_TRUE(nudgeScene(scene, NudgeDirection::Up, kRight, kUp, kForward, 10.0, false));
  EXPECT_DOUBLE_EQ(scene.target.y, 0.05);
  scene.target = Vec3(0.0);
  ASSERT_TRUE(nudgeScene(scene, NudgeDirection::Up, kRight, kUp, kForward, 10.0, true));
  EXPECT_DOUBLE_EQ(scene.target.y, 0.05 * kNudgeFineFactor);
  EXPECT_DOUBLE_EQ(nudgeStepForSize(0.0), kNudgeMinStep) << "a point-sized scene still moves";
}

TEST(TargetNudge, ASceneWithoutATargetReportsNothingMoved) {
  testing::ConstantVelocityScene scene;
  EXPECT_FALSE(nudgeScene(scene, NudgeDirection::Left, kRight, kUp, kForward, 1.0, false));
}

}  // namespace
}  // namespace pba::app
