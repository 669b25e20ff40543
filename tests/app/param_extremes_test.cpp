// The extremes check (app/checks/param_extremes.h) passes a sound scene and finds each defect it looks for:
// a metric that turns NaN without the guard, a value of the declared range that validate() refuses.
#include <cmath>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include "app/checks/param_extremes.h"
#include "app/runner/scene_registry.h"

namespace pba::app {
namespace {

/// A point moving at speed gain, gain in [0, 2], a workload count in [1, 3]; `Defect` decides what
/// goes wrong at gain 2.
enum class Defect { None, NanMetricWithoutGuard, RefusesItsMaximum };

template <Defect D>
class GainScene : public Scene {
 public:
  GainScene() {
    params_.real("gain", &gain, 0.0, 2.0, "", "A gain.");
    params_.integer("count", &count, 1, 3, "", "A count of work.").workload();
    params_.text("label", &label, "A text (not checked).");
  }
  std::string description() const override { return "A point whose speed has a gain."; }
  Status validate() override {
    if (D == Defect::RefusesItsMaximum && gain == 2.0) return Error{"gain: 2 is not allowed"};
    return Status::success();
  }
  void reset() override { x = 0.0; }
  void step(Real dt) override { x += gain * dt; }
  void draw(DebugDraw&) const override {}
  nlohmann::json metrics() const override {
    const bool nan = D == Defect::NanMetricWithoutGuard && gain == 2.0;
    return {{"x_m", x}, {"gain_effect", nan ? std::numeric_limits<double>::quiet_NaN() : gain}};
  }
  std::optional<std::string> nonFiniteState() const override { return std::nullopt; }

  Real gain = 1.0, x = 0.0;
  int count = 1;
  std::string label;
};

PBA_REGISTER_SCENE("Extremes", "extremes-sound", GainScene<Defect::None>);
PBA_REGISTER_SCENE("Extremes", "extremes-nan-metric", GainScene<Defect::NanMetricWithoutGuard>);
PBA_REGISTER_SCENE("Extremes", "extremes-refuses-maximum", GainScene<Defect::RefusesItsMaximum>);

int check(const std::string& scene, std::string* report) {
  std::ostringstream out;
  const int failures = checkParamExtremes("test", ExtremesOptions{3, scene}, out);
  *report = out.str();
  return failures;
}

TEST(ParamExtremes, ASoundSceneRunsAtEveryExtremeAndRefusesValuesJustOutside) {
  std::string report;
  EXPECT_EQ(check("extremes-sound", &report), 0) << report;
  // gain at both ends, count at its minimum (its maximum is a workload); label is text; the four values
  // just outside.
  EXPECT_NE(report.find("3 runs at the extremes (0 paused by the guard), 4 refusals checked, 0 failures"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("skip extremes-sound count=3 (a workload)"), std::string::npos) << report;
  EXPECT_NE(report.find("run extremes-sound gain=2 -> finite"), std::string::npos) << report;
}

TEST(ParamExtremes, AMetricThatTurnsNanWithoutTheGuardIsAFailure) {
  std::string report;
  EXPECT_EQ(check("extremes-nan-metric", &report), 1) << report;
  EXPECT_NE(report.find("FAIL extremes-nan-metric gain=2: metric test.gain_effect is not finite"), std::string::npos)
      << report;
}

TEST(ParamExtremes, AValueOfTheDeclaredRangeThatTheSceneRefusesIsAFailure) {
  std::string report;
  EXPECT_EQ(check("extremes-refuses-maximum", &report), 1) << report;
  EXPECT_NE(report.find("FAIL extremes-refuses-maximum gain=2: refused a value in its declared range: gain: 2 is "
                        "not allowed"),
            std::string::npos)
      << report;
}

TEST(ParamExtremes, AnUnknownSceneIsAFailure) {
  std::string report;
  EXPECT_EQ(check("no-such-scene", &report), 1);
}

}  // namespace
}  // namespace pba::app
