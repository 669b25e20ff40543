// ANIM-2: Catmull-Rom tangents on non-uniform knots and asst4's boundary rules. The expected tangents
// are the formula (p2 − p0)/(t2 − t0) evaluated here on the knot values; continuity is checked on the
// segment data (a Hermite segment starts at p1 with slope m1/h and ends at p2 with slope m2/h), so
// these tests need no Hermite evaluation (ANIM-1).
#include <gtest/gtest.h>

#include <vector>

#include "physics/animation/catmull_rom.h"

namespace {

using pba::Real;
namespace an = pba::animation;

const std::vector<Real> kTimes{0.0, 0.4, 1.5, 1.7, 3.0};
const std::vector<Real> kValues{1.0, -2.0, 0.5, 3.0, 2.0};

Real tangentPerSecond(const an::CatmullRomSegment& s, const std::array<Real, 4>& w) {
  return an::weightedKnots(kValues, s.key, w) / s.length;
}

TEST(ANIM_2_CatmullRom, InteriorTangentsAreTheNeighbourSlopesOnNonUniformKnots) {
  const an::CatmullRomSegment s = an::catmullRomSegment(kTimes, 1.6);  // interval [1.5, 1.7)
  ASSERT_EQ(s.region, an::SegmentRegion::Interior);
  EXPECT_EQ(s.key, 2);
  EXPECT_NEAR(s.length, 0.2, 1e-15);
  EXPECT_NEAR(s.u, 0.5, 1e-12);
  EXPECT_NEAR(tangentPerSecond(s, s.startTangent), (kValues[3] - kValues[1]) / (kTimes[3] - kTimes[1]), 1e-12);
  EXPECT_NEAR(tangentPerSecond(s, s.endTangent), (kValues[4] - kValues[2]) / (kTimes[4] - kTimes[2]), 1e-12);
}

TEST(ANIM_2_CatmullRom, MissingOuterKnotsAreMirrored) {
  // First interval: k0 = k1 − (k2 − k1) in time and value, so the slope is (p2 − p0)/(t2 − t0).
  const an::CatmullRomSegment first = an::catmullRomSegment(kTimes, 0.1);
  ASSERT_EQ(first.region, an::SegmentRegion::Interior);
  EXPECT_EQ(first.key, 0);
  const Real p0 = 2 * kValues[0] - kValues[1], t0 = 2 * kTimes[0] - kTimes[1];
  EXPECT_NEAR(tangentPerSecond(first, first.startTangent), (kValues[1] - p0) / (kTimes[1] - t0), 1e-12);
  const an::CatmullRomSegment last = an::catmullRomSegment(kTimes, 2.9);
  ASSERT_EQ(last.region, an::SegmentRegion::Interior);
  EXPECT_EQ(last.key, 3);
  const Real p5 = 2 * kValues[4] - kValues[3], t5 = 2 * kTimes[4] - kTimes[3];
  EXPECT_NEAR(tangentPerSecond(last, last.endTangent), (p5 - kValues[3]) / (t5 - kTimes[3]), 1e-12);
}

TEST(ANIM_2_CatmullRom, IsC1AcrossEveryInteriorKnot) {
  for (size_t k = 1; k + 1 < kTimes.size(); ++k) {
    const an::CatmullRomSegment before = an::catmullRomSegment(kTimes, kTimes[k] - 1e-9);
    const an::CatmullRomSegment after = an::catmullRomSegment(kTimes, kTimes[k]);
    ASSERT_EQ(before.key + 1, static_cast<int>(k));
    ASSERT_EQ(after.key, static_cast<int>(k));
    EXPECT_NEAR(after.u, 0.0, 1e-15) << "a knot is the start of its interval, so the curve passes through it";
    EXPECT_NEAR(tangentPerSecond(before, before.endTangent), tangentPerSecond(after, after.startTangent), 1e-12)
        << "knot " << k;
  }
}

TEST(ANIM_2_CatmullRom, BoundaryRulesOfTheAssignment) {
  EXPECT_EQ(an::catmullRomSegment({}, 0.3).region, an::SegmentRegion::Empty);
  const std::vector<Real> one{0.7};
  const an::CatmullRomSegment single = an::catmullRomSegment(one, 5.0);
  EXPECT_EQ(single.region, an::SegmentRegion::Constant);
  EXPECT_EQ(single.key, 0);
  const an::CatmullRomSegment before = an::catmullRomSegment(kTimes, -1.0);
  EXPECT_EQ(before.region, an::SegmentRegion::Constant);
  EXPECT_EQ(before.key, 0);
  const an::CatmullRomSegment atFirst = an::catmullRomSegment(kTimes, 0.0);
  EXPECT_EQ(atFirst.region, an::SegmentRegion::Constant);
  EXPECT_EQ(atFirst.key, 0);
  const an::CatmullRomSegment after = an::catmullRomSegment(kTimes, 3.0);
  EXPECT_EQ(after.region, an::SegmentRegion::Constant);
  EXPECT_EQ(after.key, 4);
}

TEST(ANIM_2_CatmullRom, TwoKnotsGiveTheChordSlopeAtBothEnds) {
  const std::vector<Real> times{1.0, 3.0};
  const std::vector<Real> values{2.0, 6.0};
  const an::CatmullRomSegment s = an::catmullRomSegment(times, 2.0);
  ASSERT_EQ(s.region, an::SegmentRegion::Interior);
  EXPECT_NEAR(an::weightedKnots(values, s.key, s.startTangent) / s.length, 2.0, 1e-14);
  EXPECT_NEAR(an::weightedKnots(values, s.key, s.endTangent) / s.length, 2.0, 1e-14);
}

}  // namespace
