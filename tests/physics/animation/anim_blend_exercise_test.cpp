// Exercise tests of ANIM-6 (blendAtPhase, clip.cpp): two looping clips blended at one phase. The clips are
// built here so that every expected value is a closed form: a root that rises linearly (a at 1 m per cycle,
// b at 2 m per cycle; vertical, so holding the root in place leaves it) and one joint that turns about z
// linearly by +1 rad (a) or −1 rad (b) per cycle. Two keys per channel, linear translations and slerp
// rotations about one axis, so that at phase p clip a has height p and angle p, clip b height 2p and angle
// −p, and their blend by w has height (1 − w) p + 2 w p and angle (1 − 2w) p. No squad channel (ANIM-5)
// is involved.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/animation/clip.h"
#include "support/expect_helpers.h"

namespace pba::animation {
namespace {

const Vec3 kZ{0.0, 0.0, 1.0};

Skeleton twoJoints() {
  Skeleton s;
  s.add("root", -1, Vec3(0.0));
  s.add("arm", 0, Vec3(0.0, 0.5, 0.0));
  return s;
}

Clip linearCycle(const Skeleton& s, Real duration, Real rise, Real turn) {
  Clip c;
  c.name = "cycle";
  c.duration = duration;
  c.tracks.resize(static_cast<size_t>(s.size()));
  for (JointTrack& t : c.tracks) {
    t.translation = Channel<Vec3>(Interpolation::Linear);
    t.rotation = RotationChannel(RotationInterpolation::Slerp);
  }
  static_cast<void>(c.tracks[0].translation.insert(0.0, Vec3(0.0)));
  static_cast<void>(c.tracks[0].translation.insert(duration, Vec3(0.0, rise, 0.0)));
  static_cast<void>(c.tracks[1].rotation.insert(0.0, Quat(1.0, 0.0, 0.0, 0.0)));
  static_cast<void>(c.tracks[1].rotation.insert(duration, glm::angleAxis(turn, kZ)));
  return c;
}

struct Cycles {
  Skeleton skeleton = twoJoints();
  Clip a = linearCycle(skeleton, 1.0, 1.0, 1.0);
  Clip b = linearCycle(skeleton, 2.0, 2.0, -1.0);
};

void expectBlendAt(const Pose& pose, Real p, Real w) {
  EXPECT_VEC3_NEAR(pose.translations[0], Vec3(0.0, (1.0 - w) * p + 2.0 * w * p, 0.0), 1e-12);
  const Quat expected = glm::angleAxis((1.0 - 2.0 * w) * p, kZ);
  EXPECT_NEAR(std::abs(glm::dot(pose.rotations[1], expected)), 1.0, 1e-12);
}

TEST(ANIM_6_BlendAtPhase, EachWeightSamplesBothClipsAtTheSamePhaseAndMixesThem) {
  const Cycles c;
  for (Real w : {0.0, 0.25, 0.5, 1.0})
    for (Real p : {0.1, 0.4, 0.7}) {
      SCOPED_TRACE(testing::Message() << "w " << w << " phase " << p);
      Pose out = restPose(c.skeleton);
      EXPECT_NEAR(blendAtPhase(c.skeleton, c.a, c.b, w, p, 0.0, out), p, 1e-15);
      ASSERT_EQ(out.rotations.size(), 2u);
      expectBlendAt(out, p, w);
    }
}

TEST(ANIM_6_BlendAtPhase, OneCycleTakesTheBlendedDuration) {
  // Cycle lengths: 1 s (a alone), 2 s (b alone), 1.5 s halfway, 1.25 s at w = 1/4.
  const Cycles c;
  const struct { Real w, period; } cases[] = {{0.0, 1.0}, {1.0, 2.0}, {0.5, 1.5}, {0.25, 1.25}};
  for (const auto& k : cases) {
    SCOPED_TRACE(k.w);
    Pose out = restPose(c.skeleton);
    const Real dt = 0.1 * k.period;  // a tenth of a cycle
    const Real phase = blendAtPhase(c.skeleton, c.a, c.b, k.w, 0.2, dt, out);
    EXPECT_NEAR(phase, 0.3, 1e-12);
    expectBlendAt(out, 0.3, k.w);
  }
}

TEST(ANIM_6_BlendAtPhase, ThePhaseWrapsIntoOneCycle) {
  const Cycles c;
  Pose out = restPose(c.skeleton);
  // 0.9 of a cycle plus 0.3 of one at w = 0.5 (period 1.5 s): 1.2 → 0.2.
  const Real phase = blendAtPhase(c.skeleton, c.a, c.b, 0.5, 0.9, 0.3 * 1.5, out);
  EXPECT_NEAR(phase, 0.2, 1e-12);
  expectBlendAt(out, 0.2, 0.5);
  // Ten steps of a tenth of a cycle come back to the start.
  Real p = 0.0;
  for (int k = 0; k < 10; ++k) p = blendAtPhase(c.skeleton, c.a, c.b, 0.25, p, 0.125, out);
  EXPECT_NEAR(std::min(p, 1.0 - p), 0.0, 1e-12);
}

}  // namespace
}  // namespace pba::animation
