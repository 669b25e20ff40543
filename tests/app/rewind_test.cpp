// Rewind: the runner's snapshots reproduce a run bit for bit, the history keeps its bounds and branches
// from a scrubbed frame, and scrubbing rebuilds the plots (docs/architecture.md §3, "Rewind").
#include <gtest/gtest.h>

#include <vector>

#include "app/runner/scene_registry.h"
#include "app/runner/scene_runner.h"
#include "app/window/lab_session.h"
#include "app/window/rewind_history.h"
#include "test_scenes.h"

namespace pba::app {
namespace {

/// A scene whose state is a large buffer: its saved state must count the buffer's bytes.
class BufferScene final : public Scene {
 public:
  std::string description() const override { return "A buffer of numbers."; }
  void reset() override { values.assign(100'000, 1.0); }
  void step(Real dt) override {
    for (double& v : values) v += dt;
  }
  void draw(DebugDraw&) const override {}
  nlohmann::json metrics() const override { return {{"first", values.front()}}; }
  std::optional<std::string> nonFiniteState() const override { return std::nullopt; }
  std::vector<double> values;
};
PBA_REGISTER_SCENE("Test", "buffer", BufferScene);

void frames(SceneRunner& r, int n) {
  for (int i = 0; i < n; ++i) r.advanceFrame(kDisplayFrame);
}

TEST(Rewind, RestoringASnapshotAndSteppingReproducesTheRunExactly) {
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());
  frames(r, 7);
  const RunnerSnapshot saved = r.snapshot();
  ASSERT_TRUE(saved.scene);
  frames(r, 11);
  const Real x = testing::constantVelocitySceneOf(r).x;
  const std::int64_t steps = r.steps();
  const Real t = r.simTime();
  ASSERT_TRUE(r.restore(saved));
  EXPECT_EQ(r.steps(), saved.steps);
  frames(r, 11);
  EXPECT_EQ(testing::constantVelocitySceneOf(r).x, x);  // bit for bit, not near
  EXPECT_EQ(r.steps(), steps);
  EXPECT_EQ(r.simTime(), t);
}

TEST(Rewind, ARestoredStateBringsBackParametersAndKeepsTheParameterTableOnTheLiveScene) {
  SceneRunner r;
  ASSERT_TRUE(r.load("constant", 1).ok());
  const RunnerSnapshot saved = r.snapshot();
  ASSERT_TRUE(r.scene().params().setFromText("speed", "4").ok());
  frames(r, 3);
  ASSERT_TRUE(r.restore(saved));
  EXPECT_EQ(testing::constantVelocitySceneOf(r).speed, 1.0);
  EXPECT_EQ(testing::constantVelocitySceneOf(r).x, 0.0);
  // The table still writes the live scene's field, not the saved copy's.
  ASSERT_TRUE(r.scene().params().setFromText("speed", "3").ok());
  EXPECT_EQ(testing::constantVelocitySceneOf(r).speed, 3.0);
}

TEST(Rewind, AStateOfAnotherSceneTypeIsRefusedAndChangesNothing) {
  SceneRunner a, b;
  ASSERT_TRUE(a.load("constant", 1).ok());
  ASSERT_TRUE(b.load("buffer", 1).ok());
  frames(a, 5);
  const RunnerSnapshot other = b.snapshot();
  const std::int64_t steps = a.steps();
  EXPECT_FALSE(a.restore(other));
  EXPECT_EQ(a.steps(), steps);
}

TEST(Rewind, ASavedStateCountsTheHeapItOwns) {
  SceneRunner r;
  ASSERT_TRUE(r.load("buffer", 1).ok());
  const RunnerSnapshot saved = r.snapshot();
  EXPECT_GE(saved.bytes(), 100'000 * sizeof(double));
  EXPECT_LT(saved.bytes(), 2 * 100'000 * sizeof(double));
}

RunnerSnapshot stateAt(double t) {
  RunnerSnapshot s;
  s.simTime = t;
  return s;
}

TEST(RewindHistory, CapacityIsTheTighterBoundTimesTheTimeOfAFrame) {
  RewindHistory none;
  EXPECT_EQ(none.capacitySeconds(), 0.0);
  RewindHistory byFrames(std::size_t(1) << 30, 5);  // 5 frames of 0.5 s
  for (int i = 0; i < 3; ++i) byFrames.push(stateAt(0.5 * i), {{"i", i}});
  EXPECT_NEAR(byFrames.capacitySeconds(), 5 * 0.5, 1e-12);
  // Frames of equal size (measured on an unbounded history): a byte bound of ten frames holds ten.
  RewindHistory unbounded(std::size_t(1) << 30, 1000);
  for (int i = 0; i < 3; ++i) unbounded.push(stateAt(0.25 * i), {{"i", i}});
  const std::size_t frameBytes = unbounded.bytes() / 3;
  RewindHistory byBytes(10 * frameBytes, 1000);
  for (int i = 0; i < 3; ++i) byBytes.push(stateAt(0.25 * i), {{"i", i}});
  EXPECT_NEAR(byBytes.capacitySeconds(), 10 * 0.25, 1e-9);
}

TEST(RewindHistory, KeepsAtMostItsFrameCountDroppingTheOldest) {
  RewindHistory h(std::size_t(1) << 30, 5);
  for (int i = 0; i < 8; ++i) h.push(stateAt(i), {{"i", i}});
  ASSERT_EQ(h.size(), 5u);
  EXPECT_EQ(h.at(0).state.simTime, 3.0);
  EXPECT_EQ(h.at(4).state.simTime, 7.0);
  EXPECT_EQ(h.cursor(), 4u);
  EXPECT_DOUBLE_EQ(h.seconds(), 4.0);
}

TEST(RewindHistory, KeepsWithinItsMemoryBoundAndAlwaysKeepsTheNewestFrame) {
  RewindHistory probe;
  probe.push(stateAt(0), {{"i", 0}});
  const std::size_t one = probe.bytes();
  RewindHistory h(3 * one + one / 2, 1000);
  for (int i = 0; i < 10; ++i) h.push(stateAt(i), {{"i", 0}});
  EXPECT_EQ(h.size(), 3u);
  EXPECT_LE(h.bytes(), h.maxBytes());
  RewindHistory tiny(1, 1000);  // smaller than one frame: the newest stays
  tiny.push(stateAt(0), {{"i", 0}});
  tiny.push(stateAt(1), {{"i", 0}});
  ASSERT_EQ(tiny.size(), 1u);
  EXPECT_EQ(tiny.at(0).state.simTime, 1.0);
}

TEST(RewindHistory, PushingBehindTheNewestFrameDiscardsTheFramesAfterTheCursor) {
  RewindHistory h;
  for (int i = 0; i < 6; ++i) h.push(stateAt(i), {{"i", i}});
  h.setCursor(2);
  EXPECT_FALSE(h.atNewest());
  const std::size_t before = h.bytes();
  h.push(stateAt(2.5), {{"i", 99}});
  ASSERT_EQ(h.size(), 4u);
  EXPECT_EQ(h.at(3).state.simTime, 2.5);
  EXPECT_TRUE(h.atNewest());
  EXPECT_LT(h.bytes(), before);
}

TEST(LabSessionRewind, ScrubbingRestoresTheStateAndRebuildsThePlotsUpToTheFrameShown) {
  SceneRunner runner;
  ASSERT_TRUE(runner.load("constant", 1).ok());
  LabSession session("test", runner, 1);
  for (int i = 0; i < 20; ++i) {
    runner.advanceFrame(kDisplayFrame);
    session.afterFrame();
  }
  ASSERT_EQ(session.history().size(), 21u);  // the reset state and 20 frames
  const Real x5 = session.history().at(5).metrics["x_m"].get<double>();
  session.scrubTo(5);
  EXPECT_TRUE(runner.paused());
  EXPECT_EQ(testing::constantVelocitySceneOf(runner).x, x5);
  const std::vector<double> plotted = session.plots().series("x_m");
  ASSERT_EQ(plotted.size(), 6u);  // frames 0..5
  EXPECT_EQ(plotted.back(), x5);
  session.stepBack();
  EXPECT_EQ(session.history().cursor(), 4u);
  session.stepForward();
  session.stepForward();
  EXPECT_EQ(session.history().cursor(), 6u);
  EXPECT_EQ(session.history().size(), 21u);  // moving through the history keeps it
  // Resuming from frame 6 branches: the next frame replaces frames 7..20.
  session.togglePause();
  runner.advanceFrame(kDisplayFrame);
  session.afterFrame();
  EXPECT_EQ(session.history().size(), 8u);
  EXPECT_EQ(testing::constantVelocitySceneOf(runner).x, session.history().at(7).metrics["x_m"].get<double>());
}

TEST(LabSessionRewind, StepForwardAtTheNewestFrameTakesANewStep) {
  SceneRunner runner;
  ASSERT_TRUE(runner.load("constant", 1).ok());
  LabSession session("test", runner, 1);
  session.stepForward();
  EXPECT_EQ(runner.steps(), 1);
  EXPECT_EQ(session.history().size(), 2u);
  session.reset();
  EXPECT_EQ(session.history().size(), 1u);
}

TEST(LabSessionRewind, CommaAndPeriodMoveBySimulationStepsAndKeepTheHistory) {
  SceneRunner runner;
  ASSERT_TRUE(runner.load("constant", 1).ok());
  LabSession session("test", runner, 1);
  const Real dt = runner.dt(), v = testing::constantVelocitySceneOf(runner).speed;
  for (int i = 0; i < 5; ++i) {
    runner.advanceFrame(kDisplayFrame);
    session.afterFrame();
  }
  const std::int64_t n = runner.steps();
  ASSERT_GT(n, 5) << "the test needs frames of more than one step";
  ASSERT_EQ(session.history().size(), 6u);
  auto x = [&] { return testing::constantVelocitySceneOf(runner).x; };
  session.stepBy(-1);  // between two kept frames
  EXPECT_EQ(runner.steps(), n - 1);
  EXPECT_NEAR(x(), static_cast<Real>(n - 1) * v * dt, 1e-12);  // x = steps · v · dt
  EXPECT_TRUE(runner.paused());
  EXPECT_EQ(session.history().size(), 6u);
  session.stepBy(-3);
  EXPECT_EQ(runner.steps(), n - 4);
  EXPECT_NEAR(x(), static_cast<Real>(n - 4) * v * dt, 1e-12);
  session.stepBy(+4);  // back at the newest frame
  EXPECT_EQ(runner.steps(), n);
  EXPECT_EQ(session.history().size(), 6u);
  session.stepBy(+1);  // a new step
  EXPECT_EQ(runner.steps(), n + 1);
  EXPECT_EQ(session.history().size(), 7u);
  // Shift: one second's worth of steps, clamped at the oldest frame.
  EXPECT_EQ(session.stepsPerSecond(), std::llround(1.0 / dt));
  session.stepBy(-session.stepsPerSecond());
  EXPECT_EQ(runner.steps(), 0);
  EXPECT_EQ(x(), 0.0);
  session.stepBy(session.stepsPerSecond());
  EXPECT_EQ(runner.steps(), session.stepsPerSecond());
  EXPECT_NEAR(x(), static_cast<Real>(session.stepsPerSecond()) * v * dt, 1e-12);
}

TEST(LabSessionReset, ResetAfterTheGuardPausedTheSceneRunsItAgainAndAUserPauseStays) {
  SceneRunner runner;
  ASSERT_TRUE(runner.load("constant", 1).ok());
  LabSession session("test", runner, 1);
  testing::constantVelocitySceneOf(runner).poison = true;
  runner.advanceFrame(kDisplayFrame);
  ASSERT_TRUE(runner.guardMessage().has_value());
  ASSERT_TRUE(runner.paused());
  testing::constantVelocitySceneOf(runner).poison = false;
  session.reset();
  EXPECT_FALSE(runner.guardMessage().has_value());
  EXPECT_FALSE(runner.paused()) << "R after the guard's pause must also run the scene";
  const std::int64_t steps = runner.steps();
  runner.advanceFrame(kDisplayFrame);
  EXPECT_GT(runner.steps(), steps);
  // Paused by the user, R resets and stays paused.
  session.togglePause();
  ASSERT_TRUE(runner.paused());
  session.reset();
  EXPECT_TRUE(runner.paused());
  EXPECT_EQ(runner.steps(), 0);
}

}  // namespace
}  // namespace pba::app
