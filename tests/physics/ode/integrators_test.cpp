// Tests of the integrators that are not exercises: midpoint, velocity Verlet, implicit Euler, adaptive,
// the name table and the finite-difference Jacobian. Expected values come from closed forms.
#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "oscillator_support.h"

namespace pba::ode {
namespace {
using testing::convergesWithOrders;
using testing::multipliesEnergyEachStepBy;

TEST(Midpoint, ConvergesWithOrderTwoOnTheOscillator) {
  EXPECT_TRUE(convergesWithOrders(IntegratorKind::Midpoint, 200, {.x = 2.0, .v = 2.0, .phase = 2.0}));
}

TEST(VelocityVerlet, ConvergesWithOrderTwoOnTheOscillator) {
  EXPECT_TRUE(convergesWithOrders(IntegratorKind::VelocityVerlet, 200, {.x = 2.0, .v = 2.0, .phase = 2.0}));
}

TEST(Midpoint, MultipliesTheOscillatorEnergyByOnePlusZToTheFourthOverFour) {
  // One midpoint step on ẍ = −ω²x is the matrix [[1 − z²/2, h], [−ω²h, 1 − z²/2]] (z = ωh); its
  // determinant, the energy factor, is (1 − z²/2)² + z² = 1 + z⁴/4.
  HarmonicOscillator osc;
  Integrator integrator(IntegratorKind::Midpoint);
  const Real h = 0.1, z = h * osc.omega();
  EXPECT_TRUE(multipliesEnergyEachStepBy(osc, integrator, h, 50, 1.0 + z * z * z * z / 4.0, 1e-13));
}

TEST(ImplicitEuler, IsExactBackwardEulerOnTheOscillatorAndDissipatesAsOneOverOnePlusZSquared) {
  // Backward Euler: v₁ = v₀ − hω²x₁, x₁ = x₀ + h v₁  ⇒ energy × 1/(1 + z²) per step. The oscillator is
  // linear, so the linearised step is exact. Tested at 10× the symplectic Euler / Verlet limit z = 2.
  OscillatorDesc desc;
  desc.stiffness = 1e4;  // ω = 100 rad/s
  HarmonicOscillator osc(desc);
  Integrator integrator(IntegratorKind::ImplicitEuler);
  const Real h = 10.0 * 2.0 / osc.omega();
  const Real z = osc.omega() * h;
  for (int i = 0; i < 20; ++i) {
    const Real x0 = osc.positions()[0], v0 = osc.velocities()[0], e0 = osc.energy();
    integrator.step(osc, h);
    const Real w2 = osc.omega() * osc.omega();
    const Real x1 = (x0 + h * v0) / (1.0 + h * h * w2);
    EXPECT_NEAR(osc.positions()[0], x1, 1e-12 * std::abs(x0) + 1e-300);
    EXPECT_NEAR(osc.velocities()[0], v0 - h * w2 * x1, 1e-9 * (std::abs(v0) + 1e-300) + 1e-12);
    EXPECT_LE(osc.energy(), e0);
    EXPECT_NEAR(osc.energy() / e0, 1.0 / (1.0 + z * z), 1e-9);
  }
}

TEST(ImplicitEuler, FiniteDifferenceJacobianAgreesWithTheAnalyticOne) {
  // KeplerOrbit has no analytic forceDifferential: the default central difference must match the
  // Hessian of −GMm/|r| applied to a direction: K dq = GMm (3 r (r·dq)/|r|⁵ − dq/|r|³).
  KeplerOrbit orbit;
  const std::vector<Real> q{0.7, -0.2, 0.4}, v{0.1, 0.0, 0.3}, dq{0.3, 0.5, -0.1}, dv{0.0, 0.0, 0.0};
  std::vector<Real> out(3);
  orbit.forceDifferential(0.0, q, v, dq, dv, out);
  const Vec3 r{q[0], q[1], q[2]}, d{dq[0], dq[1], dq[2]};
  const Real len = glm::length(r);
  const Vec3 expected = (3.0 * r * glm::dot(r, d) / std::pow(len, 5) - d / std::pow(len, 3)) * orbit.desc().gm;
  // Central differences with ε ≈ 1e-6: truncation O(ε²) and rounding O(1e-16/ε) ≈ 1e-10.
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(out[static_cast<std::size_t>(i)], expected[i], 1e-8);
}

TEST(Adaptive, MeetsItsToleranceWithFewerStepsThanAFixedStepOfEqualAccuracy) {
  const Real T = 10.0;
  for (Real tolerance : {1e-6, 1e-9}) {
    SCOPED_TRACE(::testing::Message() << "tolerance " << tolerance);
    HarmonicOscillator osc;
    Integrator adaptive(IntegratorKind::Adaptive);
    adaptive.adaptiveSettings.tolerance = tolerance;
    adaptive.step(osc, T);  // one call: the controller chooses every substep
    const Real error = std::hypot(osc.positions()[0] - osc.exactPosition(T), osc.velocities()[0] - osc.exactVelocity(T));
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

TEST(Adaptive, ShrinksTheStepNearPericentreOfAnEccentricOrbit) {
  OrbitDesc desc;
  desc.velocity = Vec3(0.0, 0.0, -0.5);  // start at apocentre of an e ≈ 0.75 orbit
  KeplerOrbit orbit(desc);
  Integrator adaptive(IntegratorKind::Adaptive);
  adaptive.adaptiveSettings.tolerance = 1e-8;
  const Real e0 = orbit.energy();
  const Real T = orbit.period();
  const int frames = 200;
  for (int i = 0; i < frames; ++i) adaptive.step(orbit, T / frames);
  EXPECT_NEAR(orbit.energy(), e0, 1e-6 * std::abs(e0));
  EXPECT_NEAR(orbit.position().x, desc.position.x, 1e-5);  // back at apocentre after one period
  EXPECT_GT(adaptive.adaptiveState().accepted, frames);    // it subdivided somewhere
}

TEST(IntegratorNames, RoundTripAndRejectUnknownNames) {
  for (IntegratorKind k : kAllIntegrators) EXPECT_EQ(parseIntegrator(integratorName(k)), k);
  EXPECT_FALSE(parseIntegrator("leapfrog").has_value());
  EXPECT_EQ(integratorNames().size(), kAllIntegrators.size());
}

TEST(Integrator, AdvancesTheSystemTimeByTheStep) {
  for (IntegratorKind k : {IntegratorKind::Midpoint, IntegratorKind::VelocityVerlet, IntegratorKind::ImplicitEuler,
                           IntegratorKind::Adaptive}) {
    HarmonicOscillator osc;
    Integrator integrator(k);
    for (int i = 0; i < 10; ++i) integrator.step(osc, 0.05);
    EXPECT_NEAR(osc.time(), 0.5, 1e-12) << integratorName(k);
  }
}

TEST(DueSteps, ScheduleStepsOfHOnTheRunnersClockAndShortenTheLastToEndExactlyAtTheStopTime) {
  // The oscillator scene's schedule: clock dt = 1/60 s, step h = 0.1 s, stop at 3 periods (6π s).
  // Reference: 188 midpoint steps of h then one of 6π − 18.8 s, each the matrix
  // [[1 − z²/2, h], [−h, 1 − z²/2]] (ω = 1), against the closed form cos t, −sin t at 6π.
  const Real h = 0.1, dt = 1.0 / 60.0, stopAt = 6.0 * kPi;
  HarmonicOscillator osc;
  Integrator integrator(IntegratorKind::Midpoint);
  Real t = 0.0, clock = 0.0;
  std::vector<Real> sizes;
  for (int frame = 0; frame < 30 * 60; ++frame) {
    clock += dt;
    while (const std::optional<DueStep> due = nextDueStep(t, h, clock, stopAt)) {
      EXPECT_LE(due->end, clock + 1e-9 * h) << "a step ran ahead of the clock";
      integrator.step(osc, due->h);
      t = due->end;
      sizes.push_back(due->h);
    }
  }
  ASSERT_EQ(sizes.size(), 189u);
  EXPECT_EQ(t, stopAt);
  const Real last = stopAt - 188 * h;
  EXPECT_NEAR(sizes.back(), last, 1e-12);
  Real x = 1.0, v = 0.0;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const Real k = i + 1 < sizes.size() ? h : last, c = 1.0 - 0.5 * k * k;
    const Real xn = c * x + k * v, vn = -k * x + c * v;
    x = xn;
    v = vn;
  }
  EXPECT_NEAR(osc.positions()[0], x, 1e-12);
  EXPECT_NEAR(osc.velocities()[0], v, 1e-12);
  const Real error = std::hypot(osc.positions()[0] - std::cos(stopAt), osc.velocities()[0] + std::sin(stopAt));
  EXPECT_NEAR(error, std::hypot(x - 1.0, v), 1e-12);
  // Nothing more falls due once the stop time is reached, however far the clock runs.
  EXPECT_FALSE(nextDueStep(t, h, 1e6, stopAt).has_value());
}

}  // namespace
}  // namespace pba::ode
