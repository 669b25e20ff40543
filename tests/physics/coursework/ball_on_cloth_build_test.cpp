// The coursework 2 scene's builder (reference library code, no task): bad descriptions name their field.
#include <gtest/gtest.h>

#include "physics/coursework/ball_on_cloth.h"

namespace pba::coursework {
namespace {

TEST(BallOnClothBuild, BadDescriptionsNameTheirField) {
  const auto fails = [](auto change, const char* field) {
    BallOnClothDesc desc;
    change(desc);
    auto built = buildBallOnCloth(desc);
    ASSERT_FALSE(built) << field;
    EXPECT_NE(built.error().find(field), std::string::npos) << built.error();
  };
  fails([](BallOnClothDesc& d) { d.resolution = 1; }, "resolution");
  fails([](BallOnClothDesc& d) { d.ballMass = 0.0; }, "ballMass");
  fails([](BallOnClothDesc& d) { d.ballRadius = -1.0; }, "ballRadius");
  fails([](BallOnClothDesc& d) { d.iterations = 0; }, "iterations");
  fails([](BallOnClothDesc& d) { d.damping = -0.5; }, "damping");
}

TEST(BallOnClothBuild, DefaultSceneHasFourPinnedCornersAndAFreeBall) {
  auto built = buildBallOnCloth({});
  ASSERT_TRUE(built) << built.error();
  EXPECT_EQ(built.value().cloth.pins.size(), 4u);
  EXPECT_EQ(built.value().cloth.size(), 24u * 24u);
  EXPECT_DOUBLE_EQ(built.value().ball.inverseMass, 1.0);
}

}  // namespace
}  // namespace pba::coursework
