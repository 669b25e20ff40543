// Coursework 3, public tests (docs/course/coursework-3-ragdoll-down-stairs.md). The instructor's held-out
// tests check the same behaviour with other seeds, stairs, masses, steps and degenerate inputs.
#include <gtest/gtest.h>

#include <cmath>
#include "physics/coursework/stairs_fall.h"
#include "support/expect_helpers.h"

namespace pba::coursework {
namespace {

/// One bone on a parabola c(t) = c₀ + v₀ t + ½ a t², spinning about a fixed axis by θ(t) = ω₀ t + ½ α t².
struct Trajectory {
  Vec3 c0{0.0}, v0{0.0}, a{0.0};
  Vec3 axis{0.0, 1.0, 0.0};
  Real omega0 = 0.0, alpha = 0.0;
  Quat base{1, 0, 0, 0};
  BonePose at(Real t) const {
    return {c0 + v0 * t + 0.5 * a * t * t, glm::angleAxis(omega0 * t + 0.5 * alpha * t * t, axis) * base};
  }
  BoneMotion motion(Real t) const { return {v0 + a * t, (omega0 + alpha * t) * axis}; }
};

TEST(CW3_1_HandOver, ParabolaAndAcceleratedSpinGiveTheirExactDerivatives) {
  Trajectory path;
  path.c0 = Vec3(0.2, 1.5, -0.3);
  path.v0 = Vec3(1.0, 2.0, 0.5);
  path.a = Vec3(0.0, -9.81, 0.3);
  path.axis = glm::normalize(Vec3(1.0, 2.0, -0.5));
  path.omega0 = 0.7;
  path.alpha = 4.0;
  path.base = glm::angleAxis(0.4, Vec3(0.0, 0.0, 1.0));
  const Real t = 0.5, h = 1.0 / 60.0;
  const BoneMotion m = handOverMotion(path.at(t - 2 * h), path.at(t - h), path.at(t), h);
  // A quadratic in t: the second-order difference is exact up to rounding.
  EXPECT_VEC3_NEAR(m.velocity, path.motion(t).velocity, 1e-9);
  EXPECT_VEC3_NEAR(m.angularVelocity, path.motion(t).angularVelocity, 1e-9);
}

TEST(CW3_1_HandOver, SteadySpinIsExactAndABoneAtRestGetsZero) {
  Trajectory spin;
  spin.axis = glm::normalize(Vec3(-0.3, 0.2, 1.0));
  spin.omega0 = 6.0;  // 0.1 rad a frame
  const Real h = 1.0 / 60.0;
  const BoneMotion m = handOverMotion(spin.at(0.0), spin.at(h), spin.at(2 * h), h);
  EXPECT_VEC3_NEAR(m.angularVelocity, 6.0 * spin.axis, 1e-9);
  EXPECT_VEC3_NEAR(m.velocity, Vec3(0.0), 1e-12);
  const BonePose still{Vec3(1.0, 2.0, 3.0), glm::angleAxis(1.0, Vec3(1.0, 0.0, 0.0))};
  const BoneMotion rest = handOverMotion(still, still, still, h);
  EXPECT_VEC3_NEAR(rest.velocity, Vec3(0.0), 1e-12);
  EXPECT_VEC3_NEAR(rest.angularVelocity, Vec3(0.0), 1e-12);
}

TEST(CW3_1_HandOver, RagdollStartsWithTheScriptedVelocities) {
  auto built = buildStairsFall(StairsFallDesc{});
  ASSERT_TRUE(built) << built.error();
  StairsFall& scene = built.value();
  const Real h = 1.0 / 60.0;
  while (scene.controlled) stepStairsFall(scene, h);
  const std::vector<BonePose> pose = scriptedPose(scene, scene.switchedAt);
  const std::vector<BoneMotion> exact = scriptedMotion(scene, scene.switchedAt);
  const std::vector<BoneMotion> started = figureMotion(scene);  // the ragdoll's bodies, before any step
  ASSERT_EQ(started.size(), exact.size());
  for (std::size_t b = 0; b < exact.size(); ++b) {
    const rigid::Body& body =
        scene.ragdoll.world().body(scene.ragdoll.bodyOf(static_cast<int>(scene.stairs.bones.size() + b)));
    SCOPED_TRACE(::testing::Message() << "bone " << b);
    EXPECT_VEC3_NEAR(body.position, pose[b].center, 1e-12);
    // The script turns about a fixed axis with constant angular acceleration: ω is exact; the centres move
    // on circles, where the second-order difference errs by O(h²) (a first-order one by ½ h |a| ≈ 5 cm/s).
    EXPECT_VEC3_NEAR(started[b].angularVelocity, exact[b].angularVelocity, 1e-9);
    EXPECT_VEC3_NEAR(started[b].velocity, exact[b].velocity, 0.01);
  }
}

/// Feeds the detector a figure of `bones` bones whose first bone moves at speed(t) [m/s] and spins at
/// spin(t) [rad/s], the others still, for `seconds` at step h; returns the detector.
template <typename Speed, typename Spin>
RestDetector feed(RestDetector d, int bones, Real seconds, Real h, Speed speed, Spin spin) {
  const int n = static_cast<int>(std::lround(seconds / h));
  for (int k = 1; k <= n; ++k) {
    const Real t = k * h;
    std::vector<BoneMotion> motion(static_cast<std::size_t>(bones));
    motion[0] = {Vec3(0.0, 0.0, speed(t)), Vec3(spin(t), 0.0, 0.0)};
    updateRest(d, motion, t, h);
  }
  return d;
}

TEST(CW3_2_RestDetection, DecayingSpeedComesToRestWhereTheClosedFormSays) {
  RestDetector d;  // 0.05 m/s, 0.25 rad/s, 0.5 s
  const Real v0 = 2.0, tau = 0.4, h = 0.01;
  const auto none = [](Real) { return 0.0; };
  // v0 e^(−t/τ) < 0.05 from t* = τ ln(v0 / 0.05); the quiet stretch starts at the step that ends first after t*.
  const Real tStar = tau * std::log(v0 / d.settings.linearSpeed);
  const auto decay = [&](Real t) { return v0 * std::exp(-t / tau); };
  const RestDetector early = feed(d, 16, tStar + d.settings.quietTime - 2 * h, h, decay, none);
  EXPECT_FALSE(early.atRest) << "declared before quietTime had passed";
  const RestDetector late = feed(d, 16, tStar + d.settings.quietTime + 2 * h, h, decay, none);
  ASSERT_TRUE(late.atRest);
  EXPECT_NEAR(late.restTime, tStar, h + 1e-9);
}

TEST(CW3_2_RestDetection, ABounceRestartsTheQuietStretch) {
  RestDetector d;
  const Real h = 0.01;
  const auto none = [](Real) { return 0.0; };
  // Still until 0.3 s, a bounce of 1 m/s in the step ending at 0.31 s, still after.
  const auto bounce = [](Real t) { return std::abs(t - 0.31) < 1e-6 ? 1.0 : 0.0; };
  const RestDetector before = feed(d, 3, 0.7, h, bounce, none);
  EXPECT_FALSE(before.atRest) << "the bounce at 0.31 s must restart the stretch";
  const RestDetector after = feed(d, 3, 0.9, h, bounce, none);
  ASSERT_TRUE(after.atRest);
  EXPECT_NEAR(after.restTime, 0.31, 1e-9);
}

TEST(CW3_2_RestDetection, ASlowSpinKeepsAStillFigureMoving) {
  RestDetector d;
  const Real h = 1.0 / 60.0;
  const auto none = [](Real) { return 0.0; };
  // Turning at 0.5 rad/s (above 0.25) for 2 s, then still.
  const auto spin = [](Real t) { return t <= 2.0 + 1e-9 ? 0.5 : 0.0; };
  EXPECT_FALSE(feed(d, 2, 2.0, h, none, spin).atRest);
  const RestDetector later = feed(d, 2, 3.0, h, none, spin);
  ASSERT_TRUE(later.atRest);
  EXPECT_NEAR(later.restTime, 2.0, h + 1e-9);
}

TEST(CW3_StairsFall, TheFigureTumblesDownAndComesToRestAtTheBottom) {
  const StairsFallDesc desc;
  auto built = buildStairsFall(desc);
  ASSERT_TRUE(built) << built.error();
  StairsFall& scene = built.value();
  const Real top = desc.steps * desc.rise;
  for (int k = 0; k < 20 * 60 && !scene.rest.atRest; ++k) stepStairsFall(scene, 1.0 / 60.0);
  ASSERT_TRUE(scene.rest.atRest) << "still moving after 20 s";
  EXPECT_GT(scene.rest.restTime, scene.switchedAt + 0.5);
  const Vec3 com = figureCenterOfMass(scene);
  ASSERT_TRUE(std::isfinite(com.x) && std::isfinite(com.y) && std::isfinite(com.z));
  // Lying at the foot of the stairs: lower than one step and the figure's half depth, past the first step.
  EXPECT_LT(com.y, desc.rise + 0.25) << "top of the stairs at " << top << " m";
  EXPECT_GT(com.x, -desc.run);
}

}  // namespace
}  // namespace pba::coursework
