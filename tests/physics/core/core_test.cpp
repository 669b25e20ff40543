// Tests of the physics core: validation messages, rays, debug-draw helpers, exercise records and
// the floating-point traps of the test main.
#include <cmath>
#include <csignal>
#include <vector>

#include <gtest/gtest.h>

#include "physics/collision/ray.h"
#include "physics/core/debug_draw.h"
#include "physics/core/validate.h"
#include "physics/exercises/not_implemented.h"
#include "support/expect_helpers.h"
#include "support/fp_traps.h"

namespace pba {
namespace {

TEST(Validate, RangeMessageNamesFieldBoundsAndValue) {
  const Status s = checkRange("drop.restitution", 1.5, 0.0, 1.0);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "drop.restitution: must be in [0, 1], got 1.5");
  EXPECT_TRUE(checkRange("x", 1.0, 0.0, 1.0).ok());
  EXPECT_FALSE(checkPositive("dt", 0.0).ok());
  EXPECT_FALSE(checkPositive("dt", INFINITY).ok());
  EXPECT_FALSE(checkFinite("p", Vec3(0.0, NAN, 0.0)).ok());
}

TEST(Ray, SphereHitDistanceMatchesGeometry) {
  const Ray ray{{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}};
  const auto t = intersectRaySphere(ray, Vec3(0.0, 0.0, 0.0), 2.0);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 8.0, 1e-12);
  // Grazing at distance 1 from the centre of a unit-2 sphere: t = 10 − √(4 − 1).
  const Ray offset{{1.0, 0.0, 10.0}, {0.0, 0.0, -1.0}};
  EXPECT_NEAR(*intersectRaySphere(offset, Vec3(0.0), 2.0), 10.0 - std::sqrt(3.0), 1e-12);
  const Ray miss{{3.0, 0.0, 10.0}, {0.0, 0.0, -1.0}};
  EXPECT_FALSE(intersectRaySphere(miss, Vec3(0.0), 2.0).has_value());
  const Ray behind{{0.0, 0.0, 10.0}, {0.0, 0.0, 1.0}};
  EXPECT_FALSE(intersectRaySphere(behind, Vec3(0.0), 2.0).has_value());
  const Ray inside{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
  EXPECT_NEAR(*intersectRaySphere(inside, Vec3(0.0), 2.0), 2.0, 1e-12);
}

TEST(Ray, PlaneHitAndParallelMiss) {
  const Ray ray{{0.0, 5.0, 0.0}, glm::normalize(Vec3(1.0, -1.0, 0.0))};
  const auto t = intersectRayPlane(ray, Vec3(0.0), kUp);
  ASSERT_TRUE(t.has_value());
  EXPECT_VEC3_NEAR(pointAt(ray, *t), Vec3(5.0, 0.0, 0.0), 1e-12);
  EXPECT_FALSE(intersectRayPlane(Ray{{0, 1, 0}, {1, 0, 0}}, Vec3(0.0), kUp).has_value());
}

// Records segments so that the composed helpers can be checked geometrically.
class RecordingDraw final : public DebugDraw {
 public:
  std::vector<std::pair<Vec3, Vec3>> lines;
  void point(const Vec3&, float, const Color&) override {}
  void line(const Vec3& a, const Vec3& b, const Color&) override { lines.emplace_back(a, b); }
  void arrow(const Vec3&, const Vec3&, const Color&) override {}
  void sphere(const Vec3&, Real, const Color&) override {}
  void box(const Vec3&, const Vec3&, const Quat&, const Color&) override {}
  void capsule(const Vec3&, const Vec3&, Real, const Color&) override {}
  void text(const Vec3&, std::string_view, const Color&) override {}
};

TEST(DebugDraw, ArcStartsAtFromAndEndsAfterTheSweepOnItsRadius) {
  RecordingDraw d;
  const Vec3 center{1.0, 2.0, 3.0};
  d.arc(center, kUp, Vec3(1.0, 0.0, 0.0), kPi / 2, 0.5, colors::kRed);
  ASSERT_FALSE(d.lines.empty());
  EXPECT_VEC3_NEAR(d.lines.front().first, center + Vec3(0.5, 0.0, 0.0), 1e-12);
  // Counter-clockwise about +y takes +x to −z.
  EXPECT_VEC3_NEAR(d.lines.back().second, center + Vec3(0.0, 0.0, -0.5), 1e-12);
  for (const auto& [a, b] : d.lines) EXPECT_NEAR(glm::length(b - center), 0.5, 1e-12);
}

TEST(DebugDraw, DegenerateInputsDrawNothingAndNeverDivideByZero) {
  RecordingDraw d;
  d.arc(Vec3(0.0), Vec3(0.0), Vec3(1, 0, 0), 1.0, 1.0, colors::kRed);
  d.circle(Vec3(0.0), Vec3(0.0), 1.0, colors::kRed);
  d.cone(Vec3(0.0), Vec3(0.0), 0.5, 1.0, colors::kRed);
  EXPECT_TRUE(d.lines.empty());
}

TEST(Exercises, NotImplementedRecordsTheTagAndReturnsTheSafeDefault) {
  exercises::clearNotImplemented();
  EXPECT_EQ(exercises::notImplemented("TEST-2", 42), 42);
  EXPECT_EQ(exercises::notImplemented("TEST-1", 7), 7);
  EXPECT_EQ(exercises::notImplemented("TEST-2", 0), 0);
  EXPECT_EQ(exercises::notImplementedTags(), (std::vector<std::string>{"TEST-1", "TEST-2"}));
  exercises::clearNotImplemented();
  EXPECT_TRUE(exercises::notImplementedTags().empty());
}

// The quotient goes to a volatile so that the optimiser cannot drop the division.
void divideInto(volatile double* out, double a, double b) { *out = a / b; }

TEST(FloatingPointTraps, DivisionByZeroStopsTheTest) {
  // The test main enables traps; a death test proves it (the child dies of SIGFPE).
  if (!pba::testing::kFloatingPointTrapsAvailable)
    GTEST_SKIP() << "this C library cannot trap floating-point exceptions";
  volatile double zero = 0.0;
  volatile double result = 0.0;
#if defined(_WIN32)
  EXPECT_DEATH(divideInto(&result, 1.0, zero), "");  // a structured exception, not a signal
#elif GTEST_HAS_DEATH_TEST
  EXPECT_EXIT(divideInto(&result, 1.0, zero), ::testing::KilledBySignal(SIGFPE), "");
#else
  GTEST_SKIP() << "this GoogleTest has no death tests (Emscripten)";
#endif
}

}  // namespace
}  // namespace pba
