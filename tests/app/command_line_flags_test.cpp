// Command-line errors name what the user typed: a lab flag's bad value names the flag (not
// "--set"), a flag meant for another scene says so, and --frames/--seconds are bounded.
#include <gtest/gtest.h>

#include "app/command_line.h"
#include "app/lab.h"
#include "app/scene_registry.h"

namespace pba::app {
namespace {

// Lab flags of this test binary: one for a parameter of scene "constant" (tests/app/runner_test.cpp
// registers it), one for a parameter no test scene has.
PBA_REGISTER_LAB_FLAG("test-speed", "speed", "sets the constant scene's speed");
PBA_REGISTER_LAB_FLAG("test-missing", "no_such_parameter", "a parameter of no scene");

Result<LabOptions> parseArgs(std::vector<const char*> args) {
  args.insert(args.begin(), "pba-test");
  return parseCommandLine(static_cast<int>(args.size()), args.data());
}

TEST(CommandLineFlags, ALabFlagRemembersTheOptionThatSetIt) {
  const Result<LabOptions> r = parseArgs({"--test-speed", "3", "--set", "count=2"});
  ASSERT_TRUE(r.ok()) << r.error();
  ASSERT_EQ(r.value().overrides.size(), 2u);
  EXPECT_EQ(r.value().overrides[0], (ParamOverride{"speed", "3", "--test-speed"}));
  EXPECT_EQ(r.value().overrides[1], (ParamOverride{"count", "2", "--set"}));
}

TEST(CommandLineFlags, OverrideErrorsNameTheFlagTyped) {
  EXPECT_EQ(overrideError({"links", "0", "--links"}, "links: must be in [1, 1000], got 0"),
            "--links: must be in [1, 1000], got 0");
  EXPECT_EQ(overrideError({"integrator", "leapfrog", "--integrator"},
                          "integrator: unknown value 'leapfrog' (one of: euler, rk4)"),
            "--integrator: unknown value 'leapfrog' (one of: euler, rk4)");
  EXPECT_EQ(overrideError({"links", "0", "--set"}, "links: must be in [1, 1000], got 0"),
            "--set links: must be in [1, 1000], got 0");
}

TEST(CommandLineFlags, PrepareRunnerNamesTheLabFlagOfABadValue) {
  SceneRunner r;
  const Status s = prepareRunner("test", parseArgs({"--scene", "constant", "--test-speed", "40"}).value(), r);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().rfind("--test-speed: must be in [0, 10]", 0), 0u) << s.error();
}

TEST(CommandLineFlags, AFlagForAnotherSceneSaysSoInsteadOfNoSuchParameter) {
  SceneRunner r;
  const Status s = prepareRunner("test", parseArgs({"--scene", "constant", "--test-missing", "1"}).value(), r);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(),
            "--test-missing: not a parameter of scene 'constant' (see --help for the scene each lab option selects)");
}

TEST(CommandLineFlags, FramesAndSecondsAreBounded) {
  EXPECT_TRUE(parseArgs({"--seconds", "100000"}).ok());
  EXPECT_TRUE(parseArgs({"--frames", "6000000"}).ok());
  const Result<LabOptions> seconds = parseArgs({"--seconds", "1e12"});
  ASSERT_FALSE(seconds.ok());
  EXPECT_EQ(seconds.error(), "--seconds: expected a number in (0, 100000] s, got '1e12'");
  const Result<LabOptions> frames = parseArgs({"--frames", "6000001"});
  ASSERT_FALSE(frames.ok());
  EXPECT_EQ(frames.error(), "--frames: expected a whole number in [1, 6000000], got '6000001'");
  EXPECT_FALSE(parseArgs({"--seconds", "0"}).ok());
}

}  // namespace
}  // namespace pba::app
