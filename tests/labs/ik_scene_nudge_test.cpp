// The IK lab's scenes under the keyboard nudge (Scene::nudge, app/window/target_nudge.h): the goal last
// picked moves by exactly the displacement, the scripted path stops, and the two-bone scene's pole
// target can be picked and moved like a goal. Positions are read back through pick(), the same
// interface the mouse uses.
#include <gtest/gtest.h>

#include <functional>

#include "app/runner/scene_registry.h"
#include "app/window/lab_session.h"

namespace pba::lab {
namespace {

std::unique_ptr<app::Scene> makeScene(const std::string& name) {
  const app::SceneEntry* entry = app::findScene(name);
  if (!entry) return nullptr;
  std::unique_ptr<app::Scene> scene = entry->create();
  scene->reset();
  return scene;
}

/// The handle picked by a ray shot straight down −z at `p` from 10 m away, if any.
std::optional<int> handleAt(const app::Scene& scene, const Vec3& p) {
  const std::optional<app::PickHit> hit = scene.pick(app::Ray{p + Vec3(0, 0, 10), Vec3(0, 0, -1)});
  return hit ? std::optional<int>(hit->handle) : std::nullopt;
}

TEST(IkSceneNudge, TheGoalMovesByTheDisplacementAndThePathStops) {
  std::unique_ptr<app::Scene> scene = makeScene("limits");
  ASSERT_TRUE(scene);
  const Vec3 p(0.5, 1.5, 0.0), delta(0.4, -0.3, 0.0);  // delta: several goal radii
  scene->drag(0, p);
  scene->release(0);
  ASSERT_EQ(handleAt(*scene, p), 0);
  ASSERT_TRUE(scene->nudge(delta));
  EXPECT_EQ(handleAt(*scene, p + delta), 0);
  EXPECT_FALSE(handleAt(*scene, p).has_value());
  EXPECT_EQ(scene->params().toJson()["path"], "mouse");
  scene->step(1.0);  // the path no longer moves the goal
  EXPECT_EQ(handleAt(*scene, p + delta), 0);
  EXPECT_GT(scene->nudgeStep(), 0.0);
}

TEST(IkSceneNudge, WithSeveralGoalsTheLastPickedOneMoves) {
  std::unique_ptr<app::Scene> scene = makeScene("tree");  // the double Y: two goals
  ASSERT_TRUE(scene);
  const Vec3 a(-3.0, 2.0, 0.0), b(3.0, 2.0, 0.0), delta(0.0, 0.5, 0.0);
  scene->drag(0, a);
  scene->release(0);
  scene->drag(1, b);
  scene->release(1);
  ASSERT_TRUE(scene->nudge(delta));
  EXPECT_EQ(handleAt(*scene, b + delta), 1);
  EXPECT_EQ(handleAt(*scene, a), 0) << "the other goal stays";
}

TEST(IkSceneNudge, TheTwoBonePoleTargetIsPickedDraggedAndNudged) {
  std::unique_ptr<app::Scene> scene = makeScene("two-bone");
  ASSERT_TRUE(scene);
  const double shoulderY = 1.0;  // TwoBoneDesc::shoulder
  // Dragging the pole (handle 1000) straight up from the shoulder sets pole_angle to 0°.
  scene->drag(1000, Vec3(0.75, shoulderY + 1.5, 0.0));
  scene->release(1000);
  EXPECT_NEAR(scene->params().toJson()["pole_angle"].get<double>(), 0.0, 1e-9);
  // A nudge toward +z turns it to atan2(1.5, 1.5) = 45°.
  ASSERT_TRUE(scene->nudge(Vec3(0.0, 0.0, 1.5)));
  EXPECT_NEAR(scene->params().toJson()["pole_angle"].get<double>(), 45.0, 1e-9);
}

}  // namespace
}  // namespace pba::lab

// Issue 15: dragging the goal while paused moved the goal but did not re-solve, while the arrow keys
// did. Both now go through LabSession, which refreshes a paused scene after any goal change. The goal
// is put far out of reach, so only a new solve can make the residual metric large (with a stubbed
// solver too: its pose stays, its residual is then the distance to the far goal).
namespace pba::lab {
namespace {

double residualAfter(const std::function<void(app::LabSession&)>& moveGoal) {
  app::SceneRunner runner;
  EXPECT_TRUE(runner.load("limits", 1).ok());
  app::LabSession session("ik", runner, 1);
  runner.setPaused(true);
  moveGoal(session);
  EXPECT_EQ(runner.steps(), 0) << "nothing stepped: the solve came from the refresh";
  return runner.scene().metrics()["residual"].get<double>();
}

TEST(IkScenePaused, ADragOfTheGoalReSolvesLikeANudge) {
  const Vec3 far(30.0, 1.5, 0.0);  // [m] the limits arm reaches about 2 m
  const double dragged = residualAfter([&](app::LabSession& s) {
    s.drag(0, far);
    s.release(0);
  });
  // The arrow key Right with the camera's right along +x, pressed until the goal is as far.
  const double nudged = residualAfter([&](app::LabSession& s) {
    for (int press = 0; press < 100000 && s.runner().scene().dragHandles().at(0).position.x < far.x; ++press)
      ASSERT_TRUE(s.nudge(app::NudgeDirection::Right, Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, -1), 1.0, false));
  });
  EXPECT_GT(dragged, 20.0) << "the paused drag re-solved toward the far goal";
  EXPECT_GT(nudged, 20.0) << "the paused nudges re-solved toward the far goal";
}

}  // namespace
}  // namespace pba::lab
