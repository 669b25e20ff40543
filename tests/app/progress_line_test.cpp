// The progress line of long jobs: a bar of 30 cells filled in proportion, the count, the elapsed time and
// the remaining time extrapolated from the rate so far.
#include <gtest/gtest.h>

#include "app/runner/progress_line.h"

namespace pba::app {
namespace {

TEST(ProgressLine, ShowsTheShareDoneTheCountAndTheTimeLeftAtTheRateSoFar) {
  // 40 of 120 frames in 10 s: a third of 30 cells, 80 frames left at 4 frames/s = 20 s.
  EXPECT_EQ(progressText("record", 40, 120, "frames", 10.0),
            "[record] [##########                    ] 40/120 frames, 10 s elapsed, ~20 s left");
}

TEST(ProgressLine, AFinishedJobHasAFullBarAndNoTimeLeft) {
  EXPECT_EQ(progressText("bench", 52, 52, "scenes", 130.4),
            "[bench] [##############################] 52/52 scenes, 130 s elapsed");
  EXPECT_EQ(progressText("bench", 0, 52, "scenes", 0.0),
            "[bench] [                              ] 0/52 scenes, 0 s elapsed");
}

}  // namespace
}  // namespace pba::app
