// A/B runs: the sides' settings parse, apply to the runner or the scene with errors naming the side, and
// the differences list names what B changed; a session steps and rewinds both sides together.
#include <gtest/gtest.h>

#include "app/runner/compare_run.h"
#include "app/runner/scene_runner.h"
#include "app/window/lab_session.h"
#include "test_scenes.h"

namespace pba::app {
namespace {

TEST(CompareRun, SidesParseIntoNameValuePairsAndRejectAWordWithoutAValue) {
  const auto ok = parseCompareSide("dt=0.01  speed=2", "--compare B");
  ASSERT_TRUE(ok);
  ASSERT_EQ(ok.value().size(), 2u);
  EXPECT_EQ(ok.value()[1].name, "speed");
  EXPECT_EQ(ok.value()[1].value, "2");
  EXPECT_TRUE(parseCompareSide("", "A").value().empty());
  const auto bad = parseCompareSide("dt=0.01 speed", "--compare B");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error(), "--compare B: expected NAME=VALUE pairs separated by spaces, got 'speed'");
}

TEST(CompareRun, ASideSetsTheClockAndSceneParametersAndNamesItselfInErrors) {
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());
  ASSERT_TRUE(applyCompareSide(r, {{"dt", "0.004"}, {"substeps", "3"}, {"speed", "2.5"}}, "B").ok());
  EXPECT_EQ(r.dt(), 0.004);
  EXPECT_EQ(r.substeps(), 3);
  EXPECT_EQ(static_cast<testing::ConstantVelocityScene&>(r.scene()).speed, 2.5);
  EXPECT_EQ(applyCompareSide(r, {{"speed", "99"}}, "B").error(), "B: speed: must be in [0, 10] m/s, got 99");
  EXPECT_EQ(applyCompareSide(r, {{"nope", "1"}}, "A").error(),
            "A: nope: not a parameter of scene 'constant' (nor dt, substeps, time_scale)");
  EXPECT_EQ(applyCompareSide(r, {{"dt", "1"}}, "A").error(), "A: dt: must be in [1e-06, 0.1] s, got 1");
}

TEST(CompareRun, DifferencesNameWhatBChanged) {
  SceneRunner a, b;
  ASSERT_TRUE(a.load("constant", 1).ok());
  ASSERT_TRUE(b.load("constant", 1).ok());
  EXPECT_TRUE(compareDifferences(a, b).empty());
  ASSERT_TRUE(applyCompareSide(b, {{"speed", "2"}, {"substeps", "2"}}, "B").ok());
  EXPECT_EQ(compareDifferences(a, b), (std::vector<std::string>{"substeps=2", "speed=2.0"}));
}

TEST(CompareRun, ASessionStepsPausesAndRewindsBothSidesTogether) {
  SceneRunner a;
  ASSERT_TRUE(a.load("constant", 1).ok());
  LabSession session("test", a, 1);
  auto b = std::make_unique<SceneRunner>();
  ASSERT_TRUE(b->load("constant", 1).ok());
  ASSERT_TRUE(applyCompareSide(*b, {{"speed", "2"}}, "B").ok());
  session.startCompare(std::move(b), "", "speed=2");
  for (int i = 0; i < 10; ++i) {
    a.advanceFrame(kDisplayFrame);
    session.partner()->advanceFrame(kDisplayFrame);
    session.afterFrame();
  }
  const auto x = [](SceneRunner& r) { return static_cast<testing::ConstantVelocityScene&>(r.scene()).x; };
  EXPECT_EQ(x(*session.partner()), 2.0 * x(a));
  session.togglePause();
  EXPECT_TRUE(session.partner()->paused());
  session.scrubTo(4);
  EXPECT_EQ(session.partner()->steps(), a.steps());
  EXPECT_EQ(x(*session.partner()), 2.0 * x(a));
  EXPECT_EQ(session.partnerPlots().series("x_m").size(), 5u);
  session.singleStep();
  EXPECT_EQ(session.partner()->steps(), a.steps());
  session.endCompare();
  EXPECT_FALSE(session.comparing());
}

TEST(CompareRun, DuplicateAsBCopiesAsParametersAndRestartsBoth) {
  SceneRunner a;
  ASSERT_TRUE(a.load("constant", 1).ok());
  ASSERT_TRUE(a.scene().params().setFromText("speed", "3").ok());
  a.advanceFrame(0.5);
  LabSession session("test", a, 1);
  session.duplicateAsB();
  ASSERT_TRUE(session.comparing());
  EXPECT_TRUE(session.editingB());
  EXPECT_EQ(a.steps(), 0);
  EXPECT_EQ(session.partner()->steps(), 0);
  EXPECT_EQ(static_cast<testing::ConstantVelocityScene&>(session.partner()->scene()).speed, 3.0);
  EXPECT_TRUE(compareDifferences(a, *session.partner()).empty());
}

}  // namespace
}  // namespace pba::app
