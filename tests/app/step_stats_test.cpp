// StepStats: nearest-rank percentiles of the frames' physics time over a bounded window, and clear()
// returning the memory (the soak measures the heap right after a scene loads).
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "app/runner/step_stats.h"

namespace {

using pba::app::StepStats;

// Nearest rank over a plain copy of the samples: the smallest value with at least p of them at or below.
double nearestRank(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size()))) - 1];
}

TEST(StepStats, PercentilesAreTheNearestRankOfTheLastWindowFrames) {
  StepStats stats(100);
  std::vector<double> all;
  for (int i = 0; i < 250; ++i) {
    const double ms = 0.5 * i + std::fmod(37.0 * i, 11.0);  // rising, in a scrambled order
    stats.add(ms);
    all.push_back(ms);
  }
  const std::vector<double> window(all.end() - 100, all.end());
  EXPECT_EQ(stats.count(), 100u);
  EXPECT_EQ(stats.last(), all.back());
  EXPECT_EQ(stats.summary().median, nearestRank(window, 0.5));
  EXPECT_EQ(stats.summary().p95, nearestRank(window, 0.95));
  EXPECT_EQ(stats.summary().max, *std::max_element(window.begin(), window.end()));
  EXPECT_NE(nearestRank(window, 0.5), nearestRank(all, 0.5));  // the window, not every sample, is summarised
}

TEST(StepStats, BelowTheWindowEverySampleCounts) {
  StepStats stats;
  std::vector<double> all;
  for (int i = 0; i < 601; ++i) stats.add(all.emplace_back(std::fmod(13.0 * i, 29.0)));
  EXPECT_EQ(stats.count(), 601u);
  EXPECT_EQ(stats.summary().median, nearestRank(all, 0.5));
  EXPECT_EQ(stats.summary().p95, nearestRank(all, 0.95));
}

TEST(StepStats, ClearEmptiesAndKeepsTheWindow) {
  StepStats stats(4);
  for (int i = 0; i < 10; ++i) stats.add(i);
  stats.clear();
  EXPECT_EQ(stats.count(), 0u);
  EXPECT_EQ(stats.last(), 0.0);
  EXPECT_EQ(stats.summary().max, 0.0);
  for (int i = 0; i < 6; ++i) stats.add(10.0 + i);
  EXPECT_EQ(stats.count(), 4u);
  EXPECT_EQ(stats.summary().max, 15.0);
  EXPECT_EQ(stats.last(), 15.0);
}

}  // namespace
