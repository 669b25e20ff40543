// Plot history ring buffers and persisted lab settings.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "app/lab_settings.h"
#include "app/plot_history.h"

namespace pba::app {
namespace {

TEST(PlotHistory, KeepsTheNewestSamplesOldestFirst) {
  PlotHistory h(4);
  for (int i = 0; i < 6; ++i) h.record(i, {{"x", i}, {"flag", i % 2 == 0}, {"name", "ignored"}});
  EXPECT_EQ(h.series("x"), (std::vector<float>{2, 3, 4, 5}));
  EXPECT_EQ(h.series("flag"), (std::vector<float>{1, 0, 1, 0}));
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
