// imageStats (CPU only): blank, two-colour and gradient images written with stb_image_write.
#include "graphics/screenshot.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <filesystem>
#include <vector>

namespace gfx = pba::graphics;

namespace {

std::string writeImage(const std::string& name, int w, int h, const std::vector<unsigned char>& rgb) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  EXPECT_NE(stbi_write_png(path.c_str(), w, h, 3, rgb.data(), w * 3), 0);
  return path;
}

}  // namespace

TEST(ImageStats, UniformImageHasOneColourAndZeroDeviation) {
  const std::string path = writeImage("pba_stats_blank.png", 16, 8, std::vector<unsigned char>(16 * 8 * 3, 200));
  gfx::ImageStats s;
  std::string error;
  ASSERT_TRUE(gfx::imageStats(path, &s, &error)) << error;
  EXPECT_EQ(s.width, 16);
  EXPECT_EQ(s.height, 8);
  EXPECT_EQ(s.distinctColors, 1);
  EXPECT_NEAR(s.luminanceStdDev, 0.0, 1e-9);
  EXPECT_NEAR(s.meanLuminance, 200.0, 1e-6);
  std::filesystem::remove(path);
}

TEST(ImageStats, HalfBlackHalfWhiteHasDeviationOfHalfTheRange) {
  const int w = 10, h = 4;
  std::vector<unsigned char> rgb(static_cast<std::size_t>(w * h * 3), 0);
  for (int y = 0; y < h / 2; ++y) {
    for (int x = 0; x < w * 3; ++x) rgb[static_cast<std::size_t>(y * w * 3 + x)] = 255;
  }
  const std::string path = writeImage("pba_stats_two.png", w, h, rgb);
  gfx::ImageStats s;
  ASSERT_TRUE(gfx::imageStats(path, &s, nullptr));
  EXPECT_EQ(s.distinctColors, 2);
  // Luma of white is 255 (weights sum to 1): two equal populations at 0 and 255 -> sd = 127.5.
  EXPECT_NEAR(s.luminanceStdDev, 127.5, 1e-3);
  std::filesystem::remove(path);
}

TEST(ImageStats, GradientCountsEveryDistinctColour) {
  const int w = 64, h = 2;
  std::vector<unsigned char> rgb;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) rgb.insert(rgb.end(), {static_cast<unsigned char>(4 * x), 10, 20});
  }
  const std::string path = writeImage("pba_stats_gradient.png", w, h, rgb);
  gfx::ImageStats s;
  ASSERT_TRUE(gfx::imageStats(path, &s, nullptr));
  EXPECT_EQ(s.distinctColors, 64);
  EXPECT_GT(s.luminanceStdDev, 10.0);
  std::filesystem::remove(path);
}

TEST(ImageStats, MissingFileGivesAnErrorNamingThePath) {
  std::string error;
  gfx::ImageStats s;
  EXPECT_FALSE(gfx::imageStats("/nonexistent/shot.png", &s, &error));
  EXPECT_NE(error.find("/nonexistent/shot.png"), std::string::npos);
}
