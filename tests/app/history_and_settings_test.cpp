// Plot history ring buffers and persisted lab settings.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "app/window/lab_settings.h"
#include "app/window/plot_history.h"

namespace pba::app {
namespace {

TEST(PlotHistory, KeepsTheNewestSamplesOldestFirst) {
  PlotHistory h(4);
  for (int i = 0; i < 6; ++i) h.record(i, {{"x", i}, {"flag", i % 2 == 0}, {"name", "ignored"}});
  EXPECT_EQ(h.series("x"), (std::vector<double>{2, 3, 4, 5}));
  EXPECT_EQ(h.series("flag"), (std::vector<double>{1, 0, 1, 0}));
  EXPECT_EQ(h.names(), (std::vector<std::string>{"flag", "x"}));
  EXPECT_TRUE(h.series("name").empty());
  h.clear();
  EXPECT_TRUE(h.names().empty());
}

TEST(LabSettings, SaveThenLoadRoundTripsAndDamagedFilesGiveDefaults) {
  const auto dir = std::filesystem::temp_directory_path() / "pba_settings_test";
  std::filesystem::remove_all(dir);
  LabSettings s;
  s.lastScene = "spring";
  s.windowWidth = 1600;
  s.windowHeight = 900;
  s.lecture = true;
  s.plotted = {"energy_J"};
  ASSERT_TRUE(saveLabSettings(dir.string(), s));
  const LabSettings back = loadLabSettings(dir.string());
  EXPECT_EQ(back.lastScene, "spring");
  EXPECT_EQ(back.windowWidth, 1600);
  EXPECT_EQ(back.windowHeight, 900);
  EXPECT_TRUE(back.lecture);
  EXPECT_EQ(back.plotted, s.plotted);
  std::ofstream(dir / "settings.json") << "{ damaged";
  EXPECT_EQ(loadLabSettings(dir.string()).lastScene, "");
  EXPECT_EQ(loadLabSettings((dir / "missing").string()).windowWidth, 1280);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pba::app

// Issue 15: a conserved energy's plot read "[0.5, 0.5]" over a staircase of float rounding. A series
// whose spread is tiny against its size is plotted as its deviation from the mean, with a range that
// reads as two different numbers.
TEST(PlotScale, ANearlyConstantSeriesIsPlottedAsItsDeviationFromTheMean) {
  std::vector<double> energy;
  for (int i = 0; i < 100; ++i) energy.push_back(0.5 + 1e-7 * std::sin(0.3 * i));
  const pba::app::PlotScale scale = pba::app::plotScale(energy);
  EXPECT_TRUE(scale.deviation);
  double mean = 0.0;
  for (double e : energy) mean += e / 100.0;
  EXPECT_NEAR(scale.offset, mean, 1e-15);
  EXPECT_NEAR(scale.hi - scale.lo,
              *std::max_element(energy.begin(), energy.end()) - *std::min_element(energy.begin(), energy.end()), 1e-15);
  const std::string caption = pba::app::plotCaption("energy_J", energy, scale);
  EXPECT_NE(caption.find("mean 0.5"), std::string::npos) << caption;
  EXPECT_EQ(caption.find("[0.5, 0.5]"), std::string::npos) << caption;
}

TEST(PlotScale, ANarrowRangeIsPrintedWithEnoughDigitsToTellItsEndsApart) {
  const std::vector<double> series = {1.001, 1.004, 1.002};  // spread 3e-3: above the deviation share
  const pba::app::PlotScale scale = pba::app::plotScale(series);
  EXPECT_FALSE(scale.deviation);
  EXPECT_EQ(scale.offset, 0.0);
  EXPECT_NE(pba::app::plotCaption("x", series, scale).find("[1.001, 1.004]"), std::string::npos)
      << pba::app::plotCaption("x", series, scale);
}

TEST(PlotScale, AConstantSeriesGetsABandAroundItsValue) {
  const pba::app::PlotScale scale = pba::app::plotScale({2.0, 2.0, 2.0});
  EXPECT_LT(scale.lo, 2.0);
  EXPECT_GT(scale.hi, 2.0);
  EXPECT_FALSE(scale.deviation);
}
