// The window's UI state without a window: mode changes asked for during a frame wait for
// applyPending() between frames (issue 15: L inside a frame aborted every lab), and scene labels are
// placed beside their anchor and inside the free part of the window.
#include <gtest/gtest.h>

#include "app/window/lab_ui.h"

namespace pba::app {
namespace {

TEST(UiState, ALectureToggleWaitsForTheEndOfTheFrame) {
  UiState ui;
  ui.relayout = false;
  ui.request(UiChange::ToggleLecture);
  EXPECT_FALSE(ui.lecture) << "a frame in progress keeps the mode it started with";
  ui.applyPending();
  EXPECT_TRUE(ui.lecture);
  EXPECT_TRUE(ui.relayout) << "the panels take their lecture size once";
  EXPECT_TRUE(ui.frameRequested) << "the scene is framed in what the new panels leave";
  EXPECT_TRUE(ui.pending.empty());
}

TEST(UiState, TogglesAskedForInOneFrameApplyInOrder) {
  UiState ui;
  ui.request(UiChange::ToggleLecture);
  ui.request(UiChange::ToggleHideUi);
  ui.request(UiChange::ToggleLecture);
  ui.applyPending();
  EXPECT_FALSE(ui.lecture) << "two presses of L within one frame cancel";
  EXPECT_TRUE(ui.hideUi);
}

TEST(UiState, ANoticeLastsItsTimeThenIsGone) {
  UiState ui;
  ui.showNotice("Screenshot saved: a.png", 10.0);
  EXPECT_EQ(ui.notice, "Screenshot saved: a.png");
  EXPECT_DOUBLE_EQ(ui.noticeUntil, 10.0 + UiState::kNoticeSeconds);
  EXPECT_TRUE(ui.noticeVisible(11.0));
  ui.noticeFrames = 0;
  EXPECT_FALSE(ui.noticeVisible(12.5));
}

TEST(UiState, ANoticeShowsForSomeFramesEvenWhenAFrameTakesLongerThanItsTime) {
  UiState ui;
  ui.showNotice("Screenshot saved: a.png", 10.0);
  EXPECT_TRUE(ui.noticeVisible(15.0)) << "a 5 s frame: the notice is still seen";
  ui.noticeFrames = 0;  // its frames drawn
  EXPECT_FALSE(ui.noticeVisible(15.0));
}

TEST(PlaceLabel, ALabelSitsAboveAndRightOfItsAnchorSoItCoversNothingItLabels) {
  const LabelBox area{0, 0, 1280, 720};
  const LabelBox b = placeLabel(400, 300, 120, 20, 5, area);
  EXPECT_FLOAT_EQ(b.x0, 405);
  EXPECT_FLOAT_EQ(b.y1, 295);  // its bottom edge is above the anchor
  EXPECT_FLOAT_EQ(b.x1 - b.x0, 120);
}

TEST(PlaceLabel, ALabelThatWouldRunOffAnEdgeIsMovedInside) {
  const LabelBox area{400, 0, 1000, 720};  // the panel covers x < 400, an overlay x > 1000
  const LabelBox right = placeLabel(980, 300, 150, 20, 5, area);
  EXPECT_FLOAT_EQ(right.x1, 1000);
  const LabelBox left = placeLabel(100, 300, 150, 20, 5, area);
  EXPECT_FLOAT_EQ(left.x0, 400);
  const LabelBox top = placeLabel(500, 10, 150, 20, 5, area);
  EXPECT_FLOAT_EQ(top.y0, 0);
}

}  // namespace
}  // namespace pba::app
