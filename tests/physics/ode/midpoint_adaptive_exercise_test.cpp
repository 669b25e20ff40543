// Exercise tests of PART-7 (the midpoint step on the split s = (q, v)) and PART-8 (the adaptive method's
// step-size controller). PART-7's tests step only the midpoint method, PART-8's only the adaptive one (its
// DOPRI5 stages are not an exercise). Expected values come from closed forms: the exact flow of the
// oscillator and its step matrix, a projectile and a push that grows linearly in time, the decisions
// worked out by hand from the controller's rules, and the d⁴ scaling of the error per unit step.
#include <cmath>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "oscillator_support.h"
#include "projectile_support.h"

namespace pba::ode {
namespace {
using testing::convergesWithOrders;
using testing::followsTheProjectile;
using testing::multipliesEnergyEachStepBy;
using testing::Projectile;
using testing::takesOneStepAs;

TEST(PART_7_Midpoint, OneStepIsTheSecondDegreeTaylorPolynomialOfTheExactFlow) {
  // The exact flow of ẍ = −x over h is x₁ = c x₀ + s v₀, v₁ = −s x₀ + c v₀ with c = cos h, s = sin h. A
  // second-order method reproduces c and s to degree 2; midpoint is exactly c = 1 − h²/2, s = h.
  const Real h = 0.1, c = 1.0 - 0.5 * h * h, s = h;
  EXPECT_TRUE(takesOneStepAs(IntegratorKind::Midpoint, {.xx = c, .xv = s, .vx = -s, .vv = c}));
}

TEST(PART_7_Midpoint, ConvergesWithOrderTwoOnTheOscillator) {
  EXPECT_TRUE(convergesWithOrders(IntegratorKind::Midpoint, 200, {.x = 2.0, .v = 2.0, .phase = 2.0}));
}

TEST(PART_7_Midpoint, MultipliesTheOscillatorEnergyByOnePlusZToTheFourthOverFour) {
  // One midpoint step on ẍ = −ω²x is the matrix [[1 − z²/2, h], [−ω²h, 1 − z²/2]] (z = ωh); its
  // determinant, the energy factor, is (1 − z²/2)² + z² = 1 + z⁴/4.
  HarmonicOscillator osc;
  Integrator integrator(IntegratorKind::Midpoint);
  const Real h = 0.1, z = h * osc.omega();
  EXPECT_TRUE(multipliesEnergyEachStepBy(osc, integrator, h, 50, 1.0 + z * z * z * z / 4.0, 1e-13));
}

TEST(PART_7_Midpoint, FollowsAProjectileExactly) {
  // x(t) = x₀ + v₀ t + g t²/2: the midpoint slope's velocity v₀ + g h/2 is the mean velocity over the step.
  // Rounding only.
  Integrator integrator(IntegratorKind::Midpoint);
  EXPECT_TRUE(followsTheProjectile(integrator, 0.01, 200, 1e-11, 1e-11));
}

TEST(PART_7_Midpoint, TakesTheMiddleSlopeAtTheMiddleOfTheStep) {
  // a_x = ramp·t is linear in t, so the velocity gained over a step, ∫ a dt = ramp (t₁² − t₀²)/2, is
  // exactly h times the acceleration at t₀ + h/2 (the midpoint rule is exact for a linear integrand):
  // v_x(t) = v₀ + ramp t²/2 after any number of steps, but only if the middle slope is taken at t + h/2.
  Projectile p;
  p.ramp = 3.0;
  p.g = Vec3(0.0);
  const Real vx0 = p.v[0];
  Integrator integrator(IntegratorKind::Midpoint);
  const Real h = 0.05;
  for (int n = 1; n <= 40; ++n) {
    integrator.step(p, h);
    const Real t = n * h;
    ASSERT_NEAR(p.v[0], vx0 + 0.5 * p.ramp * t * t, 1e-12) << "step " << n;
    ASSERT_NEAR(p.v[1], 10.0, 1e-15);  // no force along y and z
  }
}

TEST(PART_8_StepControl, KeepsASubstepAtItsBoundAndProposesNinetyPercentOfIt) {
  // tolerance 10⁻⁶ /s, d = 0.01 s: the bound on a substep's error is 10⁻⁸. At the bound the ideal factor
  // is 1, times the safety 0.9.
  const AdaptiveSettings settings{.tolerance = 1e-6, .minStep = 1e-9};
  const StepDecision atBound = controlStep(1e-8, 0.01, settings);
  EXPECT_TRUE(atBound.accept);
  EXPECT_NEAR(atBound.next, 0.009, 1e-15);
  const StepDecision justAbove = controlStep(1.0001e-8, 0.01, settings);
  EXPECT_FALSE(justAbove.accept);
  EXPECT_LT(justAbove.next, 0.009);
  EXPECT_GT(justAbove.next, 0.0089);
}

TEST(PART_8_StepControl, GrowsBySixteenToTheQuarterWhenTheErrorIsSixteenTimesBelowTheBound) {
  // The error per unit step of a 5th-order method goes as d⁴: 16× below the bound allows a step 2× longer
  // (times the safety 0.9); 16× above it, a step half as long. A step 81× below allows 3×: 2.7 d.
  const AdaptiveSettings settings{.tolerance = 1e-6, .minStep = 1e-9};
  const StepDecision below = controlStep(1e-8 / 16.0, 0.01, settings);
  EXPECT_TRUE(below.accept);
  EXPECT_NEAR(below.next, 0.018, 1e-15);
  const StepDecision above = controlStep(16e-8, 0.01, settings);
  EXPECT_FALSE(above.accept);
  EXPECT_NEAR(above.next, 0.0045, 1e-15);
  EXPECT_NEAR(controlStep(1e-8 / 81.0, 0.01, settings).next, 0.027, 1e-15);
}

TEST(PART_8_StepControl, NeverChangesTheStepByMoreThanFiveTimesAndNeverGoesBelowTheMinimum) {
  const AdaptiveSettings settings{.tolerance = 1e-6, .minStep = 1e-4};
  const StepDecision exact = controlStep(0.0, 0.01, settings);  // no error at all: grow as much as allowed
  EXPECT_TRUE(exact.accept);
  EXPECT_NEAR(exact.next, 0.05, 1e-15);
  EXPECT_NEAR(controlStep(1e-30, 0.01, settings).next, 0.05, 1e-15);  // 0.9·10^5.5 > 5: clamped
  const StepDecision huge = controlStep(1.0, 0.01, settings);
  EXPECT_FALSE(huge.accept);
  EXPECT_NEAR(huge.next, 0.002, 1e-15);  // a fifth
  const StepDecision nearMinimum = controlStep(1.0, 3e-4, settings);
  EXPECT_FALSE(nearMinimum.accept);
  EXPECT_EQ(nearMinimum.next, 1e-4);  // a fifth would be 6·10⁻⁵: held at minStep
  const StepDecision atMinimum = controlStep(1.0, 1e-4, settings);
  EXPECT_TRUE(atMinimum.accept);  // nothing smaller will be tried: kept whatever its error
  EXPECT_EQ(atMinimum.next, 1e-4);
}

TEST(PART_8_AdaptiveStep, MeetsItsToleranceWithFewerStepsThanAFixedStepOfEqualAccuracy) {
  const Real T = 10.0;
  for (Real tolerance : {1e-6, 1e-9}) {
    SCOPED_TRACE(::testing::Message() << "tolerance " << tolerance);
    HarmonicOscillator osc;
    Integrator adaptive(IntegratorKind::Adaptive);
    ASSERT_TRUE(adaptive.setAdaptiveSettings({.tolerance = tolerance}).ok());
    adaptive.step(osc, T);  // one call: the controller chooses every substep
    const Real error =
        std::hypot(osc.positions()[0] - osc.exactPosition(T), osc.velocities()[0] - osc.exactVelocity(T));
    // Error per unit step ≤ tolerance ⇒ global error ≲ tolerance × T on this non-expanding system.
    EXPECT_LE(error, tolerance * T);
    const long steps = adaptive.adaptiveState().accepted + adaptive.adaptiveState().rejected;
    // Smallest fixed-step RK4 run (n = 2^k) that is at least as accurate. RK4 on ẍ = −x is the
    // rotation-like matrix [[c, s], [−s, c]] per step (c = 1 − h²/2 + h⁴/24, s = h − h³/6), applied
    // here directly so that this test does not depend on the PART-3 exercise.
    auto rk4Error = [&](int n) {
      const Real h = T / n, c = 1 - h * h / 2 + h * h * h * h / 24, s = h - h * h * h / 6;
      Real x = 1.0, v = 0.0;
      for (int i = 0; i < n; ++i) {
        const Real xn = c * x + s * v;
        v = -s * x + c * v;
        x = xn;
      }
      return std::hypot(x - std::cos(T), v + std::sin(T));
    };
    int fixedSteps = 1;
    while (rk4Error(fixedSteps) > error) {
      fixedSteps *= 2;
      ASSERT_LT(fixedSteps, 1 << 20);
    }
    EXPECT_LT(steps, fixedSteps) << "adaptive error " << error;
    // Fewer derivative evaluations as well (6 per DOPRI step, 4 per RK4 step).
    EXPECT_LT(adaptive.adaptiveState().evaluations, 4L * fixedSteps);
  }
}

TEST(PART_8_AdaptiveStep, ShrinksTheStepNearPericentreOfAnEccentricOrbit) {
  OrbitDesc desc;
  desc.velocity = Vec3(0.0, 0.0, -0.5);  // start at apocentre of an e ≈ 0.75 orbit
  KeplerOrbit orbit(desc);
  Integrator adaptive(IntegratorKind::Adaptive);
  ASSERT_TRUE(adaptive.setAdaptiveSettings({.tolerance = 1e-8}).ok());
  const Real e0 = orbit.energy();
  const Real T = orbit.period();
  const int frames = 200;
  for (int i = 0; i < frames; ++i) adaptive.step(orbit, T / frames);
  EXPECT_NEAR(orbit.energy(), e0, 1e-6 * std::abs(e0));
  EXPECT_NEAR(orbit.position().x, desc.position.x, 1e-5);  // back at apocentre after one period
  EXPECT_GT(adaptive.adaptiveState().accepted, frames);    // it subdivided somewhere
}

TEST(PART_8_AdaptiveStep, TenThousandTimesTighterToleranceTakesAboutTenTimesMoreSubsteps) {
  // Error per unit step ∝ d⁴ ⇒ the chosen d ∝ tolerance^(1/4): 10⁴× tighter, ~10× shorter substeps.
  auto substeps = [](Real tolerance) {
    HarmonicOscillator osc;
    Integrator adaptive(IntegratorKind::Adaptive);
    EXPECT_TRUE(adaptive.setAdaptiveSettings({.tolerance = tolerance}).ok());
    for (int i = 0; i < 10; ++i) adaptive.step(osc, 1.0);
    return static_cast<Real>(adaptive.adaptiveState().accepted);
  };
  const Real ratio = substeps(1e-11) / substeps(1e-7);
  EXPECT_GT(ratio, 7.0);
  EXPECT_LT(ratio, 14.0);
}

}  // namespace
}  // namespace pba::ode
