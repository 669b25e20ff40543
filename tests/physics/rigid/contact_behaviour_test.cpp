// Contacts against closed forms and stated bounds: the incline (slide distance ½ g (sin θ − μ cos θ) t²
// when tan θ > μ, none otherwise), restitution (bounce apex ratio e²), stacking (a 10-box column and a
// 210-box pyramid standing 10 s), warm starting carried by feature id.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/rigid/builders.h"
#include "support/expect_helpers.h"

namespace pba::rigid {
namespace {

Real slideAfter(Real angleDeg, Real mu, Real seconds) {
  World w;
  const Incline in = buildIncline(w, degToRad(angleDeg), mu);
  const int steps = static_cast<int>(std::lround(seconds * 60.0));
  for (int i = 0; i < steps; ++i) w.step(1.0 / 60.0);
  return glm::dot(w.body(in.box).position - in.start, in.downhill);
}

TEST(Incline, SlideDistanceIsWithinOnePercentOfTheClosedForm) {
  for (const auto& [angle, mu] : {std::pair{30.0, 0.3}, std::pair{40.0, 0.5}, std::pair{20.0, 0.1}}) {
    const Real t = 2.0;
    const Real th = degToRad(angle);
    const Real expected = 0.5 * kStandardGravity * (std::sin(th) - mu * std::cos(th)) * t * t;
    EXPECT_NEAR(slideAfter(angle, mu, t), expected, 0.01 * expected) << angle << "°, μ " << mu;
  }
}

TEST(Incline, ABoxSticksWhenTheSlopeIsBelowTheFrictionAngle) {
  EXPECT_LT(std::abs(slideAfter(20.0, 0.5, 3.0)), 1e-3);  // tan 20° = 0.36 < 0.5
  EXPECT_LT(std::abs(slideAfter(26.0, 0.5, 3.0)), 1e-3);  // tan 26° = 0.49, just below
}

// A ball dropped from h bounces to e² h: the speed after impact is e times the speed before, and the
// apex height goes with the square of the speed.
TEST(Restitution, TheBounceApexRatioIsESquared) {
  for (Real e : {0.5, 0.8}) {
    WorldSettings s;
    s.restitutionThreshold = 0.1;
    World w(s);
    addGround(w);
    BodyDesc ball;
    ball.shape = collision::makeSphere(0.1).value();
    ball.position = Vec3(0.0, 2.1, 0.0);  // bottom 2 m above the ground
    ball.restitution = e;
    const int b = w.addBody(ball).value();
    Real apex = 0.0;
    bool bounced = false;
    for (int i = 0; i < 240; ++i) {
      w.step(1.0 / 60.0);
      const Body& body = w.body(b);
      if (body.linearVelocity.y > 0.0) bounced = true;
      if (bounced) apex = std::max(apex, body.position.y - 0.1);
      if (bounced && body.linearVelocity.y < 0.0 && apex > 0.1) break;
    }
    // 3 % covers the discrete apex (60 Hz samples) and the impact inside a step.
    EXPECT_NEAR(apex / 2.0, e * e, 0.03 * e * e) << "e = " << e;
  }
}

struct StackRun {
  Real columnDrift = 0.0, pyramidDrift = 0.0;  // horizontal [m]
  Real restingKinetic = 0.0;                   // [J] largest in the last second
  Real deepest = 0.0;                          // [m]
  Real restingSpeed = 0.0;                     // [m/s] largest body speed in the last second
};

StackRun runStack(bool sleeping) {
  WorldSettings s;
  s.sleeping = sleeping;
  s.iterations = 2;  // the lab's stack scene setting
  World w(s);
  addGround(w);
  const StackBodies sb = buildStack(w, StackDesc{});
  const Vec3 c0 = w.body(sb.columnTop).position, p0 = w.body(sb.pyramidTop).position;
  StackRun r;
  for (int i = 0; i < 600; ++i) {
    w.step(1.0 / 60.0);
    const WorldStats st = w.stats();
    r.deepest = std::max(r.deepest, st.maxPenetration);
    if (i >= 540) {
      r.restingKinetic = std::max(r.restingKinetic, st.kineticEnergy);
      for (int b : sb.boxes) r.restingSpeed = std::max(r.restingSpeed, glm::length(w.body(b).linearVelocity));
    }
  }
  const Vec3 horizontal(1.0, 0.0, 1.0);
  r.columnDrift = glm::length(horizontal * (w.body(sb.columnTop).position - c0));
  r.pyramidDrift = glm::length(horizontal * (w.body(sb.pyramidTop).position - p0));
  return r;
}

// Bounds: the tops move less than 1 cm sideways in 10 s; at rest (the last second) no box moves faster
// than 1 mm/s, so the 220 boxes of 1000 kg hold less than 0.1 J in all; no contact sinks deeper than 1 cm
// (twice the linear slop: a soft contact carries the 10-box column at about 5 mm).
TEST(Stacking, TheColumnAndThePyramidStandTenSecondsWithoutDriftOrJitter) {
  const StackRun r = runStack(false);
  EXPECT_LT(r.columnDrift, 0.01);
  EXPECT_LT(r.pyramidDrift, 0.01);
  EXPECT_LT(r.restingSpeed, 1e-3);
  EXPECT_LT(r.restingKinetic, 0.1);
  EXPECT_LT(r.deepest, 0.01);
}

TEST(Stacking, WithSleepingEveryBoxFallsAsleepAndStaysPut) {
  const StackRun r = runStack(true);
  EXPECT_LT(r.columnDrift, 0.01);
  EXPECT_LT(r.pyramidDrift, 0.01);
  EXPECT_EQ(r.restingKinetic, 0.0);
}

TEST(WarmStarting, CarriesImpulsesOverByFeatureId) {
  World w;
  addGround(w);
  addBox(w, Vec3(0.5), Vec3(0.0, 0.5, 0.0), Quat(1, 0, 0, 0), 1000.0, 0.6, colors::kRed);
  for (int i = 0; i < 30; ++i) w.step(1.0 / 60.0);
  ASSERT_EQ(w.contacts().size(), 1u);
  const ContactConstraint& c = w.contacts()[0];
  ASSERT_EQ(c.count, 4);
  // At rest the four impulses carry the weight: Σ λ = m g dt.
  Real sum = 0.0;
  for (int i = 0; i < 4; ++i) sum += c.points[i].normalImpulse;
  EXPECT_NEAR(sum, 1000.0 * kStandardGravity * (1.0 / 60.0) / w.settings().substeps, 0.02 * sum);
}

}  // namespace
}  // namespace pba::rigid
