// Tests of the integrators that are not exercises: velocity Verlet, implicit Euler, adaptive's error
// handling (its controller is PART-8: midpoint_adaptive_exercise_test.cpp),
// the name table and the finite-difference Jacobian. Expected values come from closed forms.
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "oscillator_support.h"
#include "support/fp_traps.h"

namespace pba::ode {
namespace {
using testing::convergesWithOrders;
using testing::multipliesEnergyEachStepBy;

TEST(VelocityVerlet, ConvergesWithOrderTwoOnTheOscillator) {
  EXPECT_TRUE(convergesWithOrders(IntegratorKind::VelocityVerlet, 200, {.x = 2.0, .v = 2.0, .phase = 2.0}));
}

TEST(HarmonicOscillator, OnePassAccelerationIsTheForceScaledByTheInverseMass) {
  HarmonicOscillator osc({.mass = 3.0, .stiffness = 7.0, .x0 = 0.3, .v0 = 0.0, .copies = 5});
  const std::vector<Real> q{0.3, -1.7, 2.5, 1e-3, -0.0}, v(5, 0.0);
  std::vector<Real> a(5), f(5);
  osc.acceleration(0.0, q, v, a);
  osc.force(0.0, q, v, f);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(a[i], f[i] * (1.0 / 3.0)) << i;
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

TEST(IntegratorNames, RoundTripAndRejectUnknownNames) {
  for (IntegratorKind k : kAllIntegrators) EXPECT_EQ(parseIntegrator(integratorName(k)), k);
  EXPECT_FALSE(parseIntegrator("leapfrog").has_value());
  EXPECT_EQ(integratorNames().size(), kAllIntegrators.size());
}

/// ẏ = −y, but the derivative is NaN below y = 0.3: a model of a force that overflows outside its domain.
/// From y = 1 the solution e^(−t) stays above 0.3 up to t = 1.2, yet one DOPRI step of 1 s puts the
/// fourth stage at y ≈ 0.11 (the tableau's large coefficients) and the sixth stage's derivative is NaN.
class FragileDecay final : public OdeSystem {
 public:
  Real y = 1.0;
  std::size_t stateSize() const override { return 1; }
  void getState(std::span<Real> out) const override { out[0] = y; }
  void setState(std::span<const Real> s) override { y = s[0]; }
  void derivative(Real, std::span<const Real> s, std::span<Real> out) const override {
    out[0] = s[0] > 0.3 ? -s[0] : std::numeric_limits<Real>::quiet_NaN();
  }
};

TEST(Adaptive, RejectsASubstepWithANonFiniteErrorEstimateAndRetriesItSmaller) {
  pba::testing::FloatingPointTrapsOff trapsOff;  // the oversized substep produces NaN on purpose
  FragileDecay system;
  AdaptiveState state;
  Workspace w;
  adaptiveStep(system, 1.0, {.tolerance = 1e-8}, state, w);
  ASSERT_TRUE(std::isfinite(system.y)) << "a NaN substep was committed";
  EXPECT_GE(state.nonFiniteRejections, 1);
  EXPECT_EQ(state.shortfall, 0.0);
  EXPECT_EQ(system.time(), 1.0);
  EXPECT_NEAR(system.y, std::exp(-1.0), 1e-8);  // error per unit step ≤ tol over 1 s
}

TEST(Adaptive, AStateThatStaysNonFiniteIsNeverCommittedAndTheClockStaysWithIt) {
  pba::testing::FloatingPointTrapsOff trapsOff;
  FragileDecay system;
  system.y = 0.2;  // below the domain: every derivative is NaN
  AdaptiveState state;
  Workspace w;
  adaptiveStep(system, 0.5, {}, state, w);
  EXPECT_EQ(system.y, 0.2);
  EXPECT_EQ(system.time(), 0.0);
  EXPECT_EQ(state.shortfall, 0.5);
  EXPECT_EQ(state.accepted, 0);
  EXPECT_GE(state.nonFiniteRejections, 1);
}

TEST(Adaptive, WhenTheSubstepCapStopsItTheStateAndTheClockAgreeAndTheShortfallIsReported) {
  // Five substeps at tolerance 1e-12 cannot cover 10 s of the oscillator (the controller grows the step
  // by at most 5× per substep from its first guess). The state must be the solution at the time the
  // system reports, not at the end of the interval.
  HarmonicOscillator osc;
  Integrator integrator(IntegratorKind::Adaptive);
  ASSERT_TRUE(integrator.setAdaptiveSettings({.tolerance = 1e-12, .minStep = 1e-9, .maxSubsteps = 5}).ok());
  integrator.step(osc, 10.0);
  const Real shortfall = integrator.adaptiveState().shortfall;
  EXPECT_GT(shortfall, 0.0);
  EXPECT_EQ(integrator.lastShortfall(), shortfall);
  EXPECT_NEAR(osc.time(), 10.0 - shortfall, 1e-12);
  EXPECT_LT(osc.time(), 10.0);
  // Accepted substeps meet the tolerance per unit step: error ≤ 1e-12 × elapsed time (and a margin).
  EXPECT_NEAR(osc.positions()[0], osc.exactPosition(osc.time()), 1e-10);
  EXPECT_NEAR(osc.velocities()[0], osc.exactVelocity(osc.time()), 1e-10);
}

TEST(IntegratorSettings, InvalidValuesAreRefusedWithTheFieldNamedAndTheOldSettingsKept) {
  Integrator integrator(IntegratorKind::ImplicitEuler);
  const Real nan = std::numeric_limits<Real>::quiet_NaN(), inf = std::numeric_limits<Real>::infinity();
  struct ImplicitCase {
    ImplicitEulerSettings settings;
    const char* field;
  };
  for (const ImplicitCase& c : {ImplicitCase{{.maxIterations = 0}, "implicit.maxIterations"},
                                ImplicitCase{{.maxIterations = -3}, "implicit.maxIterations"},
                                ImplicitCase{{.relativeTolerance = 0.0}, "implicit.relativeTolerance"},
                                ImplicitCase{{.relativeTolerance = -1e-8}, "implicit.relativeTolerance"},
                                ImplicitCase{{.relativeTolerance = 1.0}, "implicit.relativeTolerance"},
                                ImplicitCase{{.relativeTolerance = nan}, "implicit.relativeTolerance"}}) {
    const Status s = integrator.setImplicitSettings(c.settings);
    ASSERT_FALSE(s.ok()) << c.field;
    EXPECT_EQ(s.error().rfind(c.field, 0), 0u) << s.error();
  }
  EXPECT_EQ(integrator.implicitSettings().maxIterations, ImplicitEulerSettings{}.maxIterations);
  struct AdaptiveCase {
    AdaptiveSettings settings;
    const char* field;
  };
  for (const AdaptiveCase& c :
       {AdaptiveCase{{.tolerance = 0.0}, "adaptive.tolerance"},
        AdaptiveCase{{.tolerance = -1e-6}, "adaptive.tolerance"},
        AdaptiveCase{{.tolerance = inf}, "adaptive.tolerance"}, AdaptiveCase{{.minStep = 0.0}, "adaptive.minStep"},
        AdaptiveCase{{.minStep = nan}, "adaptive.minStep"}, AdaptiveCase{{.maxSubsteps = 0}, "adaptive.maxSubsteps"}}) {
    const Status s = integrator.setAdaptiveSettings(c.settings);
    ASSERT_FALSE(s.ok()) << c.field;
    EXPECT_EQ(s.error().rfind(c.field, 0), 0u) << s.error();
  }
  EXPECT_EQ(integrator.adaptiveSettings().tolerance, AdaptiveSettings{}.tolerance);
  // The smallest valid values are accepted.
  EXPECT_TRUE(integrator.setImplicitSettings({.maxIterations = 1, .relativeTolerance = 1e-300}).ok());
  EXPECT_TRUE(integrator.setAdaptiveSettings({.tolerance = 1e-300, .minStep = 1e-300, .maxSubsteps = 1}).ok());
}

TEST(Integrator, EveryMethodAdvancesTheStateAndTheTimeTogetherOrNeither) {
  // A method either steps (the state moves and the clock advances by h) or, as an exercise stub, does
  // nothing at all: a stub that advanced the clock would make the state lie about its time.
  for (IntegratorKind k : kAllIntegrators) {
    HarmonicOscillator osc;
    Integrator integrator(k);
    integrator.step(osc, 0.05);
    const bool moved = osc.positions()[0] != 1.0 || osc.velocities()[0] != 0.0;
    EXPECT_EQ(osc.time(), moved ? 0.05 : 0.0) << integratorName(k);
  }
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
