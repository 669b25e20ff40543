// The scene runner: fixed steps from an accumulator, pause and single step, substeps, the
// instability guard, determinism; and the command line parser.
#include <gtest/gtest.h>

#include "app/lab.h"
#include "app/runner/command_line.h"
#include "app/runner/scene_registry.h"
#include "app/runner/scene_runner.h"
#include "support/fp_traps.h"
#include "test_scenes.h"

PBA_REGISTER_SCENE("Test", "constant", pba::app::testing::ConstantVelocityScene);

namespace pba::app {
namespace {
using testing::ConstantVelocityScene;

TEST(SceneRunner, TakesWholeFixedStepsAndCarriesTheRemainder) {
  SceneRunner r;
  ASSERT_TRUE(r.setDt(0.01).ok());
  ASSERT_TRUE(r.load("constant", 1).ok());
  // 0.025 s → 2 steps with 0.005 s left over; another 0.025 s → 0.03 s in all: 3 more steps.
  r.advanceFrame(0.025);
  EXPECT_EQ(r.steps(), 2);
  r.advanceFrame(0.025);
  EXPECT_EQ(r.steps(), 5);
  EXPECT_NEAR(testing::constantVelocitySceneOf(r).x, 5 * 0.01 * 1.0, 1e-15);
  EXPECT_NEAR(r.simTime(), 0.05, 1e-15);
}

TEST(SceneRunner, SixtyFramesOfOneSixtiethAtDefaultDtMakeOneSecond) {
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());
  for (int i = 0; i < 60; ++i) r.advanceFrame(kDisplayFrame);
  EXPECT_EQ(r.steps(), static_cast<long>(std::lround(1.0 / r.dt())));
  EXPECT_NEAR(r.simTime(), 1.0, 1e-12);
}

TEST(SceneRunner, PauseStopsTimeAndSingleStepAdvancesExactlyOneStep) {
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());
  r.setPaused(true);
  r.advanceFrame(1.0);
  EXPECT_EQ(r.steps(), 0);
  r.singleStep();
  EXPECT_EQ(r.steps(), 1);
  EXPECT_EQ(testing::constantVelocitySceneOf(r).stepsTaken, 1);
}

TEST(SceneRunner, SubstepsSplitEachStepAndTimeScaleSlowsTheClock) {
  SceneRunner r;
  ASSERT_TRUE(r.setDt(0.01).ok());
  ASSERT_TRUE(r.setSubsteps(4).ok());
  ASSERT_TRUE(r.setTimeScale(0.5).ok());
  ASSERT_TRUE(r.load("constant", 1).ok());
  r.advanceFrame(0.1);  // 0.05 s of simulated time
  EXPECT_EQ(r.steps(), 5);
  EXPECT_EQ(testing::constantVelocitySceneOf(r).stepsTaken, 20);
  EXPECT_NEAR(testing::constantVelocitySceneOf(r).x, 0.05, 1e-15);
  EXPECT_FALSE(r.setSubsteps(0).ok());
  EXPECT_FALSE(r.setTimeScale(5.0).ok());
  EXPECT_FALSE(r.setDt(-1.0).ok());
}

TEST(SceneRunner, MaxStepsBoundsOneFrameAndDropsTheBacklog) {
  SceneRunner r;
  ASSERT_TRUE(r.setDt(0.001).ok());
  ASSERT_TRUE(r.load("constant", 1).ok());
  r.advanceFrame(1.0, 10);
  EXPECT_EQ(r.steps(), 10);
  r.advanceFrame(0.0, 10);
  EXPECT_EQ(r.steps(), 10) << "the dropped backlog must not be stepped later";
}

TEST(SceneRunner, NonFiniteStatePausesWithAMessageNamingItAndWhatToTry) {
  pba::testing::FloatingPointTrapsOff traps;  // the scene makes a NaN on purpose
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());
  r.advanceFrame(0.1);
  testing::constantVelocitySceneOf(r).poison = true;
  const long before = r.steps();
  r.advanceFrame(0.1);
  EXPECT_EQ(r.steps(), before + 1) << "caught within one step";
  EXPECT_TRUE(r.paused());
  EXPECT_FALSE(r.finite());
  ASSERT_TRUE(r.guardMessage().has_value());
  EXPECT_NE(r.guardMessage()->find("point position is not finite"), std::string::npos);
  EXPECT_NE(r.guardMessage()->find("smaller time step"), std::string::npos);
  testing::constantVelocitySceneOf(r).poison = false;
  r.reset();
  EXPECT_FALSE(r.guardMessage().has_value());
  EXPECT_TRUE(r.finite());
}

TEST(SceneRunner, RunawayEnergyPausesTheScene) {
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());            // energy 0.5 J at reset
  testing::constantVelocitySceneOf(r).driven = true;  // no gain bound: only the factor of |E| at reset
  testing::constantVelocitySceneOf(r).energyBoost =
      0.5 * kRunawayEnergyFactor - 1.0;  // |E| = 49.5 J < 100 × 0.5 J: fine
  r.advanceFrame(0.1);
  EXPECT_FALSE(r.paused());
  testing::constantVelocitySceneOf(r).energyBoost = 0.5 * kRunawayEnergyFactor * 2;
  r.advanceFrame(0.1);
  EXPECT_TRUE(r.paused());
  ASSERT_TRUE(r.guardMessage().has_value());
  EXPECT_NE(r.guardMessage()->find("runaway"), std::string::npos);
}

// Issue 35: a passive scene may not gain energy; the bound counts from reset or the user's last input.
TEST(SceneRunner, APassiveSceneThatGainsMoreThanTheSlackIsPausedAsARunaway) {
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());  // energy 0.5 J at reset, 1 m/s
  const Real e0 = 0.5;
  testing::constantVelocitySceneOf(r).energyBoost = 0.9 * kPassiveEnergySlack * e0;  // within the slack
  r.advanceFrame(0.1);
  EXPECT_FALSE(r.paused());
  testing::constantVelocitySceneOf(r).energyBoost = 1.1 * kPassiveEnergySlack * e0;  // 0.5 % of E0 past it
  r.advanceFrame(0.1);
  EXPECT_TRUE(r.paused());
  ASSERT_TRUE(r.guardMessage().has_value());
  EXPECT_NE(r.guardMessage()->find("runaway"), std::string::npos);
  EXPECT_NE(r.guardMessage()->find("press R to reset"), std::string::npos);
  EXPECT_TRUE(r.finite());
  r.reset();  // the boost stays: the reference is now the boosted energy, so no pause
  r.setPaused(false);
  r.advanceFrame(0.1);
  EXPECT_FALSE(r.paused());
}

TEST(SceneRunner, TheEnergyBoundCountsFromTheUsersLastInput) {
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());
  testing::constantVelocitySceneOf(r).energyBoost = 10.0;  // a drag threw the point
  r.noteInput();
  r.advanceFrame(0.1);
  EXPECT_FALSE(r.paused()) << "energy the user put in is not a runaway";
  testing::constantVelocitySceneOf(r).energyBoost = 11.0;  // then it gains on its own: 1 J of 10.5 J
  r.advanceFrame(0.1);
  EXPECT_TRUE(r.paused());
}

TEST(SceneRunner, AParameterEditMovesTheEnergyBoundWithoutAPause) {
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());
  r.advanceFrame(0.1);
  testing::constantVelocitySceneOf(r).speed = 3.0;  // parameter 'speed' edited: 4.5 J, not a runaway
  r.advanceFrame(0.1);
  EXPECT_FALSE(r.paused());
  testing::constantVelocitySceneOf(r).energyBoost = 0.5;  // 5 J: 11 % more than at the edit
  r.advanceFrame(0.1);
  EXPECT_TRUE(r.paused());
}

TEST(SceneRunner, ASolverThatSaysItDivergedPausesTheSceneWhileItsStateIsFinite) {
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());
  r.advanceFrame(0.1);
  EXPECT_FALSE(r.paused());
  testing::constantVelocitySceneOf(r).diverged = true;
  const long before = r.steps();
  r.advanceFrame(0.1);
  EXPECT_EQ(r.steps(), before + 1) << "caught within one step";
  EXPECT_TRUE(r.paused());
  EXPECT_TRUE(r.finite()) << "a runaway, not a non-finite state (the soak tells them apart)";
  ASSERT_TRUE(r.guardMessage().has_value());
  EXPECT_NE(r.guardMessage()->find("the test solver diverged"), std::string::npos);
  EXPECT_NE(r.guardMessage()->find("runaway"), std::string::npos);
}

TEST(SceneRunner, PanelDtLastsOneSceneAndCommandLineDtLastsForAll) {
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());
  const Real sceneDefault = r.dt();
  ASSERT_TRUE(r.setDt(0.002, /*keepAcrossScenes=*/false).ok());
  ASSERT_TRUE(r.load("constant", 1).ok());
  EXPECT_EQ(r.dt(), sceneDefault);
  ASSERT_TRUE(r.setDt(0.003).ok());
  ASSERT_TRUE(r.load("constant", 1).ok());
  EXPECT_EQ(r.dt(), 0.003);
}

TEST(SceneRunner, UnknownSceneIsAnError) {
  SceneRunner r;
  const Status s = r.load("no-such", 1);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("unknown scene 'no-such'"), std::string::npos);
}

Result<LabOptions> parse(std::vector<const char*> args) {
  args.insert(args.begin(), "pba-test");
  return parseCommandLine(static_cast<int>(args.size()), args.data());
}

TEST(CommandLine, ParsesTheContractOfDesignSection4) {
  auto r = parse({"--scene", "constant", "--headless", "--frames", "12", "--dt", "0.005", "--metrics", "-", "--seed",
                  "9", "--lecture", "--set", "speed=2", "--substeps=3"});
  ASSERT_TRUE(r.ok()) << r.error();
  const LabOptions& o = r.value();
  EXPECT_EQ(o.scene, "constant");
  EXPECT_TRUE(o.headless);
  EXPECT_EQ(o.frameCount(), 12);
  EXPECT_EQ(*o.dt, 0.005);
  EXPECT_EQ(o.metrics, "-");
  EXPECT_EQ(o.seed, 9u);
  EXPECT_TRUE(o.lecture);
  EXPECT_EQ(*o.substeps, 3);
  ASSERT_EQ(o.overrides.size(), 1u);
  EXPECT_EQ(o.overrides[0], (ParamOverride{"speed", "2", "--set"}));
  EXPECT_EQ(parse({"--seconds", "1"}).value().frameCount(), 60);
  EXPECT_EQ(parse({"--seconds", "0.02"}).value().frameCount(), 2);    // 1.2 frames: rounded up
  EXPECT_EQ(parse({"--seconds", "10e-60"}).value().frameCount(), 1);  // shorter than a frame: one frame
  const auto inlineSet = parse({"--set=speed=2.5"});
  ASSERT_TRUE(inlineSet.ok()) << inlineSet.error();
  EXPECT_EQ(inlineSet.value().overrides.at(0), (ParamOverride{"speed", "2.5", "--set"}));
  EXPECT_EQ(parse({}).value().frameCount(), kDefaultHeadlessFrames);
}

// Scene-selecting lab flags of this test binary only (the scenes need not exist for parsing).
PBA_REGISTER_LAB_FLAG("test-low", "speed", "selects scene 'low'", "low");
PBA_REGISTER_LAB_FLAG("test-high", "speed", "selects scene 'high' over 'low'", "high", 1);

TEST(CommandLine, TheHighestPriorityLabFlagPicksTheSceneInAnyOrder) {
  EXPECT_EQ(parse({"--test-low", "1"}).value().impliedScene, "low");
  EXPECT_EQ(parse({"--test-low", "1", "--test-high", "2"}).value().impliedScene, "high");
  EXPECT_EQ(parse({"--test-high", "2", "--test-low", "1"}).value().impliedScene, "high");
  // Both values still reach the parameter, in command-line order.
  EXPECT_EQ(parse({"--test-high", "2", "--test-low", "1"}).value().overrides.size(), 2u);
}

TEST(CommandLine, BadArgumentsNameTheOption) {
  EXPECT_EQ(parse({"--bogus"}).error(), "unknown option '--bogus' (see --help)");
  EXPECT_NE(parse({"--frames", "0"}).error().find("--frames"), std::string::npos);
  EXPECT_NE(parse({"--frames"}).error().find("missing value"), std::string::npos);
  EXPECT_NE(parse({"--dt", "1"}).error().find("--dt"), std::string::npos);
  EXPECT_NE(parse({"--set", "speed"}).error().find("NAME=VALUE"), std::string::npos);
  EXPECT_NE(parse({"--frames", "3", "--seconds", "1"}).error().find("one or the other"), std::string::npos);
  EXPECT_NE(parse({"--headless", "--screenshot", "x.png"}).error().find("--screenshot"), std::string::npos);
  EXPECT_NE(parse({"--headless=yes"}).error().find("takes no value"), std::string::npos);
}

TEST(CommandLine, PrepareRunnerAppliesOverridesAndReportsBadOnes) {
  SceneRunner r;
  ASSERT_TRUE(prepareRunner("test", parse({"--scene", "constant", "--set", "speed=4"}).value(), r).ok());
  EXPECT_EQ(testing::constantVelocitySceneOf(r).speed, 4.0);
  SceneRunner invalid;
  const Status v = prepareRunner("test", parse({"--scene", "constant", "--set", "label=invalid"}).value(), invalid);
  EXPECT_EQ(v.error(), "label: 'invalid' is not a valid label") << "Scene::validate() runs before the scene is used";
  SceneRunner bad;
  const Status s = prepareRunner("test", parse({"--scene", "constant", "--set", "speed=40"}).value(), bad);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("speed: must be in [0, 10]"), std::string::npos);
}

}  // namespace
}  // namespace pba::app
