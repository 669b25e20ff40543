// The IK comparison scene's legend (issue 15: the pinv yellow and pink entries were faint on the
// white panels): every method has an entry, and every colour has a contrast of at least 3:1 against
// white by the WCAG 2 formula (relative luminance of linearised sRGB), an independent measure.
#include <cmath>

#include <gtest/gtest.h>

#include "app/runner/scene_registry.h"

namespace pba::lab {
namespace {

double linear(float c) { return c <= 0.04045f ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double contrastOnWhite(const Color& c) {
  const double luminance = 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
  return 1.05 / (luminance + 0.05);
}

TEST(IkComparisonLegend, EveryMethodHasAnEntryThatReadsOnWhite) {
  const app::SceneEntry* entry = app::findScene("comparison");
  ASSERT_NE(entry, nullptr);
  std::unique_ptr<app::Scene> scene = entry->create();
  scene->reset();
  const std::vector<app::LegendEntry> legend = scene->legend();
  ASSERT_GE(legend.size(), 8u) << "one entry per method";
  for (const app::LegendEntry& e : legend)
    EXPECT_GE(contrastOnWhite(e.color), 3.0)
        << e.text << ": rgb " << e.color.r << ", " << e.color.g << ", " << e.color.b;
}

}  // namespace
}  // namespace pba::lab
