// Command-line errors name what the user typed: a lab flag's bad value names the flag (not
// "--set"), a flag meant for another scene says so, and --frames/--seconds are bounded.
#include <gtest/gtest.h>

#include "app/lab.h"
#include "app/runner/command_line.h"
#include "app/runner/scene_registry.h"

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

TEST(CommandLineFlags, SizeIsWidthByHeightWithinTheWindowBounds) {
  const Result<LabOptions> full = parseArgs({"--size", "1920x1080", "--screenshot", "a.png"});
  ASSERT_TRUE(full.ok()) << full.error();
  EXPECT_EQ(full.value().size, std::make_pair(1920, 1080));
  EXPECT_EQ(parseArgs({"--size=320x240"}).value().size, std::make_pair(320, 240));
  EXPECT_FALSE(parseArgs({}).value().size.has_value());
  for (const char* bad : {"1920", "1920x", "x1080", "1920x1080x1", "-1920x1080", "319x240", "320x239", "8193x1080",
                          "1920 x 1080", "1e3x1080", "99999999999x1080"}) {
    const Result<LabOptions> r = parseArgs({"--size", bad});
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_EQ(r.error().rfind("--size: expected WIDTHxHEIGHT in pixels", 0), 0u) << r.error();
    EXPECT_NE(r.error().find(std::string("'") + bad + "'"), std::string::npos) << r.error();
  }
  EXPECT_EQ(parseArgs({"--size", "1920x1080", "--headless"}).error(), "--size sets the window's size: drop --headless");
}

}  // namespace
}  // namespace pba::app
