// Motion clips (clip.h): blending, cross-fades, looping and root motion, time warps and bad input.
// Clips here use linear translation and slerp rotation channels (no exercise code runs); expected
// values are the keys themselves and lerp/slerp written out in the test.
#include <gtest/gtest.h>

#include "physics/animation/builders.h"
#include "physics/animation/clip.h"
#include "support/expect_helpers.h"

namespace {

using pba::Quat;
using pba::Real;
using pba::Vec3;
namespace an = pba::animation;

an::Skeleton twoJoints() {
  an::Skeleton s;
  s.add("root", -1, Vec3(0.0, 1.0, 0.0));
  s.add("arm", 0, Vec3(0.5, 0.0, 0.0));
  return s;
}

/// Root walks 1 m along +x in 2 s; the arm turns 0.8 rad about z.
an::Clip stroll(const an::Skeleton& s) {
  an::Clip c;
  c.name = "stroll";
  c.duration = 2.0;
  c.tracks.resize(2);
  static_cast<void>(c.tracks[0].translation.insert(0.0, Vec3(0.0, 1.0, 0.0)));
  static_cast<void>(c.tracks[0].translation.insert(2.0, Vec3(1.0, 1.0, 0.0)));
  static_cast<void>(c.tracks[1].rotation.insert(0.0, Quat(1, 0, 0, 0)));
  static_cast<void>(c.tracks[1].rotation.insert(2.0, glm::angleAxis(0.8, Vec3(0, 0, 1))));
  static_cast<void>(s);
  return c;
}

TEST(ClipPlayback, LoopingWrapsTimeAndRootMotionModesPlaceTheRoot) {
  const an::Skeleton s = twoJoints();
  const an::Clip c = stroll(s);
  an::Pose pose;
  an::playPose(s, c, 2.5, {true, an::RootMotion::AsRecorded}, pose);
  EXPECT_VEC3_NEAR(pose.translations[0], Vec3(0.25, 1.0, 0.0), 1e-14);
  an::playPose(s, c, 2.5, {true, an::RootMotion::Accumulate}, pose);
  EXPECT_VEC3_NEAR(pose.translations[0], Vec3(1.25, 1.0, 0.0), 1e-14);
  an::playPose(s, c, 4.5, {true, an::RootMotion::Accumulate}, pose);
  EXPECT_VEC3_NEAR(pose.translations[0], Vec3(2.25, 1.0, 0.0), 1e-14);
  an::playPose(s, c, 2.5, {true, an::RootMotion::InPlace}, pose);
  EXPECT_VEC3_NEAR(pose.translations[0], Vec3(0.0, 1.0, 0.0), 1e-14);
  an::playPose(s, c, 2.5, {false, an::RootMotion::AsRecorded}, pose);
  EXPECT_VEC3_NEAR(pose.translations[0], Vec3(1.0, 1.0, 0.0), 1e-14);
  EXPECT_VEC3_NEAR(an::rootDisplacement(c, s), Vec3(1.0, 0.0, 0.0), 1e-14);
}

TEST(ClipBlend, WeightsSumToOneAndTheEndsAreTheClips) {
  for (Real t = -1.0; t <= 3.0; t += 0.1) {
    const an::BlendWeights w = an::crossFadeWeights(t, 0.5, 1.5);
    EXPECT_NEAR(w.first + w.second, 1.0, 1e-15);
    EXPECT_GE(w.second, 0.0);
    EXPECT_LE(w.second, 1.0);
  }
  EXPECT_EQ(an::crossFadeWeights(0.4, 0.5, 1.5).second, 0.0);
  EXPECT_EQ(an::crossFadeWeights(2.0, 0.5, 1.5).second, 1.0);
  const an::Skeleton s = twoJoints();
  const an::Clip c = stroll(s);
  an::Pose a, b, out;
  an::samplePose(s, c, 0.3, a);
  an::samplePose(s, c, 1.7, b);
  an::blendPoses(a, b, 0.0, out);
  EXPECT_EQ(out.translations, a.translations);
  EXPECT_EQ(out.rotations, a.rotations);
  an::blendPoses(a, b, 1.0, out);
  EXPECT_EQ(out.translations, b.translations);
  EXPECT_EQ(out.rotations, b.rotations);
  an::blendPoses(a, b, 0.25, out);
  EXPECT_VEC3_NEAR(out.translations[0], 0.75 * a.translations[0] + 0.25 * b.translations[0], 1e-15);
  // Both arm rotations are about z: the blend is the angle lerp (0.12 → 0.68 rad, a quarter of the way).
  EXPECT_NEAR(an::rotationAngle(out.rotations[1], glm::angleAxis(0.75 * 0.12 + 0.25 * 0.68, Vec3(0, 0, 1))), 0.0, 1e-7);
}

TEST(ClipValidation, ClipOfAnotherSkeletonIsRefusedNamingTheSource) {
  const an::Skeleton s = twoJoints();
  an::Clip c = stroll(s);
  const pba::Status ok = an::validate(c, s, "stroll.bvh");
  EXPECT_TRUE(ok.ok()) << ok.error();
  const an::Skeleton human = an::buildHumanoid();
  const pba::Status bad = an::validate(c, human, "stroll.bvh");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("stroll.bvh"), std::string::npos) << bad.error();
  EXPECT_NE(bad.error().find("2 tracks for a skeleton of 21 joints"), std::string::npos) << bad.error();
  c.duration = 0.0;
  EXPECT_NE(an::validate(c, s, "x.bvh").error().find("duration"), std::string::npos);
}

TEST(TimeWarp, MapsSceneTimeMonotonicallyAndRefusesGoingBack) {
  an::TimeWarp warp;
  EXPECT_DOUBLE_EQ(warp(1.7), 1.7);
  static_cast<void>(warp.map.insert(0.0, 0.0));
  static_cast<void>(warp.map.insert(1.0, 0.5));  // slow motion, then
  static_cast<void>(warp.map.insert(2.0, 2.5));  // fast forward
  EXPECT_TRUE(an::validate(warp).ok());
  EXPECT_DOUBLE_EQ(warp(0.5), 0.25);
  EXPECT_DOUBLE_EQ(warp(1.5), 1.5);
  EXPECT_DOUBLE_EQ(warp(3.0), 4.5);
  static_cast<void>(warp.map.insert(3.0, 1.0));
  const pba::Status bad = an::validate(warp);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("time warp: key 3"), std::string::npos) << bad.error();
}

TEST(Humanoid, MatchesTheBvhHierarchyAndItsGaitClipsAreValid) {
  const an::Skeleton s = an::buildHumanoid();
  ASSERT_TRUE(an::validate(s).ok());
  EXPECT_EQ(s.size(), 21);
  EXPECT_EQ(s.parents[static_cast<size_t>(s.find("LeftForeArm"))], s.find("LeftArm"));
  EXPECT_VEC3_NEAR(s.restTranslations[0], Vec3(0.0, 0.95, 0.0), 1e-15);
  for (const an::Clip& c :
       {an::buildGaitClip(s, {}), an::buildGaitClip(s, an::runGait(), "run"), an::buildWaveClip(s)}) {
    const pba::Status st = an::validate(c, s, c.name);
    EXPECT_TRUE(st.ok()) << st.error();
  }
}

}  // namespace
