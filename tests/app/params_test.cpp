// Parameters: text and JSON setters validate and name the field; toJson round-trips.
#include <gtest/gtest.h>

#include "test_scenes.h"

namespace pba::app {
namespace {
using testing::ConstantVelocityScene;

TEST(Params, SetFromTextParsesEveryKindAndValidatesTheRange) {
  ConstantVelocityScene s;
  EXPECT_TRUE(s.params().setFromText("speed", "2.5").ok());
  EXPECT_EQ(s.speed, 2.5);
  EXPECT_TRUE(s.params().setFromText("count", "7").ok());
  EXPECT_EQ(s.count, 7);
  EXPECT_TRUE(s.params().setFromText("visible", "false").ok());
  EXPECT_FALSE(s.visible);
  EXPECT_TRUE(s.params().setFromText("mode", "third").ok());
  EXPECT_EQ(s.mode, 2);
  EXPECT_TRUE(s.params().setFromText("heading", "90").ok());
  EXPECT_NEAR(s.heading, kPi / 2, 1e-15);
  EXPECT_TRUE(s.params().setFromText("label", "hand_L,hand_R").ok());
  EXPECT_EQ(s.label, "hand_L,hand_R");

  const Status range = s.params().setFromText("speed", "11");
  ASSERT_FALSE(range.ok());
  EXPECT_EQ(range.error(), "speed: must be in [0, 10] m/s, got 11");
  EXPECT_EQ(s.speed, 2.5) << "a rejected value must leave the parameter unchanged";
  EXPECT_NE(s.params().setFromText("speed", "fast").error().find("expected a number"), std::string::npos);
  EXPECT_NE(s.params().setFromText("count", "2.5").error().find("whole number"), std::string::npos);
  EXPECT_NE(s.params().setFromText("mode", "fourth").error().find("one of: first, second, third"), std::string::npos);
  EXPECT_NE(s.params().setFromText("nope", "1").error().find("no such parameter"), std::string::npos);
  EXPECT_FALSE(s.params().setFromText("speed", "nan").ok());
}

TEST(Params, SetFromJsonChecksTypesAndPrefixesTheField) {
  ConstantVelocityScene s;
  EXPECT_EQ(s.params().setFromJson("speed", "fast", "params.").error(),
            "params.speed: expected a number, got \"fast\"");
  EXPECT_EQ(s.params().setFromJson("visible", 1, "params.").error(), "params.visible: expected true or false, got 1");
  EXPECT_NE(s.params().setFromJson("mode", "x", "params.").error().find("params.mode"), std::string::npos);
  EXPECT_EQ(s.params().setFromJson("label", 3, "params.").error(), "params.label: expected a string, got 3");
  EXPECT_TRUE(s.params().setFromJson("speed", 3.0, "params.").ok());
  EXPECT_EQ(s.speed, 3.0);
}

TEST(Params, ToJsonThenSetFromJsonRestoresEveryValueExactly) {
  ConstantVelocityScene a;
  a.speed = 0.1 + 0.2;  // not representable exactly: checks shortest round-trip printing
  a.count = 42;
  a.visible = false;
  a.mode = 1;
  a.heading = 0.3;
  a.label = "a \"quoted\" name";
  const nlohmann::json saved = nlohmann::json::parse(a.params().toJson().dump());
  ConstantVelocityScene b;
  for (const auto& [key, value] : saved.items()) ASSERT_TRUE(b.params().setFromJson(key, value, "").ok()) << key;
  EXPECT_EQ(b.speed, a.speed);
  EXPECT_EQ(b.count, a.count);
  EXPECT_EQ(b.visible, a.visible);
  EXPECT_EQ(b.mode, a.mode);
  EXPECT_EQ(b.label, a.label);
  // Angles travel in degrees: one conversion each way, so equal to within a few ulps.
  EXPECT_NEAR(b.heading, a.heading, 4e-16);
  EXPECT_EQ(b.params().toJson(), saved) << "a second save must be identical to the first";
}

// A parameter shown only in some mode keeps working in scene files and on the command line.
TEST(Params, ShownWhenHidesOnlyTheWidgetNotTheValue) {
  Params params;
  bool advanced = false;
  Real step = 0.2;
  params.flag("advanced", &advanced, "Show the step.");
  params.real("step", &step, 0.01, 1.0, "s", "A step.").shownWhen([&advanced] { return advanced; });
  const Param* p = params.find("step");
  ASSERT_NE(p, nullptr);
  ASSERT_TRUE(static_cast<bool>(p->shown));
  EXPECT_FALSE(p->shown());
  advanced = true;
  EXPECT_TRUE(p->shown());
  EXPECT_FALSE(static_cast<bool>(params.find("advanced")->shown)) << "parameters without a predicate are always shown";
  EXPECT_TRUE(params.setFromText("step", "0.5").ok());
  EXPECT_EQ(step, 0.5);
  EXPECT_EQ(params.toJson().at("step"), 0.5);
}

}  // namespace
}  // namespace pba::app
