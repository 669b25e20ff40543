// The CMU asst4 pendulum joint (ode/pendulum.h), both steppers: asst4's symplectic Euler with the exact
// damping factor (stepPendulum) and PendulumSystem under the non-exercise integrators. Expected values
// are closed forms computed here: the exact large-amplitude period, exponential decay, equilibria.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "physics/ode/integrators.h"
#include "physics/ode/pendulum.h"
#include "support/expect_helpers.h"

namespace pba::ode {
namespace {

// The library's integrators of higher order (midpoint and adaptive's controller are PART-7 and PART-8: in
// the hand-out these Pendulum tests report "needs PART-7/PART-8", skipped, until both are done).
constexpr IntegratorKind kLibraryMethods[] = {IntegratorKind::Midpoint, IntegratorKind::VelocityVerlet,
                                              IntegratorKind::ImplicitEuler, IntegratorKind::Adaptive};

/// Arithmetic–geometric mean (Gauss): the complete elliptic integral is K(k) = π / (2 AGM(1, √(1 − k²))).
Real agm(Real a, Real b) {
  for (int i = 0; i < 40 && std::abs(a - b) > 1e-16 * a; ++i) {
    const Real m = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = m;
  }
  return a;
}

PendulumDesc undamped() {
  PendulumDesc d;
  d.mass = 1.3;
  d.comOffset = Vec3(0.0, -0.8, 0.0);
  d.inertiaCm = 0.05;
  d.damping = 0.0;
  return d;
}

/// Period of the undamped compound pendulum swinging with amplitude A [rad] about its rest angle:
/// θ̈ = −(m g L / I) sin θ gives T = 4 K(sin(A/2)) √(I / (m g L)) = 2π / AGM(1, cos(A/2)) · √(I / (m g L)).
Real exactPeriod(const PendulumDesc& d, Real amplitude) {
  const Real omega0 = std::sqrt(d.mass * d.gravity * comDistance(d) / pivotInertia(d));  // small-angle [rad/s]
  return 2.0 * kPi / (agm(1.0, std::cos(0.5 * amplitude)) * omega0);
}

/// The pendulum from `start` after `duration` [s], by the adaptive integrator (tolerance 1e-11, 50
/// calls): the reference of the large-amplitude tests (global error ≲ tolerance × duration).
PendulumState adaptiveRun(const PendulumDesc& d, const PendulumState& start, Real duration) {
  PendulumSystem system(d);
  system.setPendulumState(start);
  Integrator integrator(IntegratorKind::Adaptive);
  EXPECT_TRUE(integrator.setAdaptiveSettings({.tolerance = 1e-11}).ok());
  for (int i = 0; i < 50; ++i) integrator.step(system, duration / 50);
  return system.pendulumState();
}

TEST(Pendulum, AdaptiveSystemReturnsAfterTheExactLargeAmplitudePeriod) {
  // Released at rest from θ₀ = 1 rad; the small-angle period 2π √(I/mgL) would be 6.6 % short.
  const PendulumDesc d = undamped();
  const Real theta0 = 1.0, period = exactPeriod(d, theta0);
  const PendulumState full = adaptiveRun(d, {theta0, 0.0}, period);
  EXPECT_NEAR(full.angle, theta0, 1e-8);
  EXPECT_NEAR(full.angularVelocity, 0.0, 1e-8);
  EXPECT_NEAR(adaptiveRun(d, {theta0, 0.0}, 0.5 * period).angle, -theta0, 1e-8);  // halfway: the other extreme
}

TEST(Pendulum, DampingDecaysTheSpinAsExpOfMinusAT) {
  // No gravity, still pivot: θ̈ = −a ω ⇒ ω(t) = ω₀ e^(−a t), θ(t) = θ₀ + ω₀ (1 − e^(−a t)) / a.
  PendulumDesc d = undamped();
  d.gravity = 0.0;
  d.damping = 0.7;
  const Real h = 1.0 / 240.0, w0 = 3.0;
  const int n = 480;
  const Real t = n * h;
  // asst4's step multiplies ω by exactly e^(−a h) per step: the decay is exact to rounding.
  PendulumState s{0.2, w0};
  for (int i = 0; i < n; ++i) s = stepPendulum(d, s, Vec3(0.0), h);
  EXPECT_NEAR(s.angularVelocity, w0 * std::exp(-d.damping * t), 1e-13);
  // Its drift uses the damped velocity of each step: θ = θ₀ + h Σ ω₀ e^(−a h k), k = 1…n (geometric sum).
  const Real q = std::exp(-d.damping * h);
  EXPECT_NEAR(s.angle, 0.2 + h * w0 * q * (1.0 - std::pow(q, n)) / (1.0 - q), 1e-12);
  // The integrators see the damping as the torque −a I ω; on ω̇ = −a ω each method multiplies ω by its
  // own amplification factor R(z), z = a h, per step (the Taylor or Padé approximant of e^(−z)).
  const Real z = d.damping * h;
  for (IntegratorKind k : kLibraryMethods) {
    SCOPED_TRACE(std::string(integratorName(k)));
    PendulumSystem system(d);
    system.setPendulumState({0.2, w0});
    Integrator integrator(k);
    ASSERT_TRUE(integrator.setAdaptiveSettings({.tolerance = 1e-10}).ok());
    for (int i = 0; i < n; ++i) integrator.step(system, h);
    Real factor = std::exp(-z), tolerance = 1e-9;  // adaptive: the exact decay, to its tolerance
    if (k == IntegratorKind::Midpoint) factor = 1.0 - z + 0.5 * z * z, tolerance = 1e-13;
    if (k == IntegratorKind::VelocityVerlet) factor = (1.0 - 0.5 * z) * (1.0 - 0.5 * z), tolerance = 1e-13;
    // Implicit Euler's Jacobian is a central difference here (exact for a linear force up to rounding
    // of ≈ 1e-16/ε with ε ≈ 1e-6): 1e-9.
    if (k == IntegratorKind::ImplicitEuler) factor = 1.0 / (1.0 + z), tolerance = 1e-9;
    EXPECT_NEAR(system.pendulumState().angularVelocity, w0 * std::pow(factor, n), tolerance * w0);
  }
}

TEST(Pendulum, PsiIsTheAtan2AngleOfTheCentreOfMassOffsetFromTheDownwardVertical) {
  PendulumDesc d = undamped();
  const Real l = 0.8;
  for (const Real psi : {-2.5, -0.4, 0.0, 0.3, 1.2, 3.0}) {
    d.comOffset = l * Vec3(std::sin(psi), -std::cos(psi), 0.0);
    EXPECT_NEAR(comOffsetAngle(d), psi, 1e-14);
    EXPECT_NEAR(comDistance(d), l, 1e-15);
    EXPECT_VEC3_NEAR(centerOfMassOffset(d, 0.0), d.comOffset, 1e-15);  // θ = 0: the body as given
  }
  d.comOffset = Vec3(0.3, 0.4, 0.0);  // above and to the right of the pivot: ψ = π − atan(3/4)
  EXPECT_NEAR(comOffsetAngle(d), kPi - std::atan(0.75), 1e-15);
  EXPECT_NEAR(comDistance(d), 0.5, 1e-15);
}

TEST(Pendulum, HangsStillAtMinusPsiWithACentreOfMassOffset) {
  // ψ tilts the body: the centre of mass is straight below the pivot at θ = −ψ, where the gravity
  // torque vanishes and the energy is zero.
  PendulumDesc d = undamped();
  d.comOffset = 0.8 * Vec3(std::sin(0.4), -std::cos(0.4), 0.0);
  const PendulumState rest{-0.4, 0.0};
  EXPECT_NEAR(pendulumEnergy(d, rest), 0.0, 1e-15);
  EXPECT_NEAR(centerOfMassOffset(d, -0.4).x, 0.0, 1e-15);
  PendulumState s = rest;
  for (int i = 0; i < 240; ++i) s = stepPendulum(d, s, Vec3(0.0), 1.0 / 240.0);
  EXPECT_NEAR(s.angle, -0.4, 1e-14);
  for (IntegratorKind k : kLibraryMethods) {
    PendulumSystem system(d);
    system.setPendulumState(rest);
    Integrator integrator(k);
    for (int i = 0; i < 240; ++i) integrator.step(system, 1.0 / 240.0);
    EXPECT_NEAR(system.pendulumState().angle, -0.4, 1e-12) << integratorName(k);
  }
  // Released from the vertical instead, it swings symmetrically about −ψ with amplitude ψ: half a
  // period later it is at −2ψ.
  EXPECT_NEAR(adaptiveRun(d, {0.0, 0.0}, 0.5 * exactPeriod(d, 0.4)).angle, -0.8, 1e-8);
}

TEST(Pendulum, AnAcceleratingPivotTiltsTheEquilibriumToTanThetaEqualsMinusAOverG) {
  // In the pivot's frame the body feels g and −a_p: with a_p = (a, 0, 0) it hangs at tan θ = −a/g.
  // Started there at rest it stays; started at θ = 0 with damping it settles there.
  PendulumDesc d = undamped();
  const Real a = 3.0;
  const Vec3 ap(a, 0.0, 0.0);
  const Real thetaEq = std::atan2(-a, d.gravity);
  EXPECT_NEAR(angularAcceleration(d, {thetaEq, 0.0}, ap), 0.0, 1e-14);
  PendulumState s{thetaEq, 0.0};
  for (int i = 0; i < 240; ++i) s = stepPendulum(d, s, ap, 1.0 / 240.0);
  EXPECT_NEAR(s.angle, thetaEq, 1e-12);
  // Damped at a = 2/s the offset decays as e^(−t) (ω₀ ≈ 3.4 rad/s > a/2): 20 s leave 0.3 e^(−20) ≈ 1e-9.
  d.damping = 2.0;
  s = {0.0, 0.0};
  for (int i = 0; i < 240 * 20; ++i) s = stepPendulum(d, s, ap, 1.0 / 240.0);
  EXPECT_NEAR(s.angle, thetaEq, 1e-6);
  for (IntegratorKind k : kLibraryMethods) {
    PendulumSystem system(d, [&](Real) { return ap; });
    Integrator integrator(k);
    for (int i = 0; i < 240 * 20; ++i) integrator.step(system, 1.0 / 240.0);
    EXPECT_NEAR(system.pendulumState().angle, thetaEq, 1e-6) << integratorName(k);
  }
}

TEST(Pendulum, TheSystemsForceIsInertiaTimesAsst4sAccelerationMinusTheDampingTorque) {
  PendulumDesc d = undamped();
  d.comOffset = 0.8 * Vec3(std::sin(-0.3), -std::cos(-0.3), 0.0);
  d.damping = 0.4;
  const Vec3 ap(1.5, -0.5, 0.0);
  PendulumSystem system(d, [&](Real t) { return t * ap; });  // the pivot's acceleration at time t
  const std::vector<Real> q{0.9}, v{-1.7};
  std::vector<Real> f(1);
  system.force(2.0, q, v, f);
  const Real inertia = d.inertiaCm + d.mass * 0.8 * 0.8;
  EXPECT_NEAR(f[0], inertia * (angularAcceleration(d, {0.9, -1.7}, 2.0 * ap) + 0.4 * 1.7), 1e-13);
  EXPECT_NEAR(system.inverseMasses()[0], 1.0 / inertia, 1e-15);
}

TEST(Pendulum, APivotMovedByHandGivesTheSecondDifferenceOfItsPositionsAsItsAcceleration) {
  // A pivot swinging x = A sin ωt sampled every h: the central second difference is −A ω² sin ωt up to
  // A ω⁴ h²/12, and a pendulum driven by it follows the one driven by the analytic acceleration.
  const Real amplitude = 0.5, w = 2.0 * kPi * 0.3, h = 1.0 / 240.0;
  auto pivot = [&](Real t) { return Vec3(amplitude * std::sin(w * t), 3.0, 0.0); };
  auto exact = [&](Real t) { return Vec3(-amplitude * w * w * std::sin(w * t), 0.0, 0.0); };
  const Real bound = amplitude * std::pow(w, 4) * h * h / 12.0 * 1.01;
  PendulumDesc d = undamped();
  d.damping = 0.1;
  PendulumState byHand{0.5, 0.0}, scripted = byHand;
  for (int i = 0; i < 240 * 10; ++i) {
    const Real t = i * h;
    const Vec3 a = pivotAccelerationFromPositions(pivot(t - h), pivot(t), pivot(t + h), h);
    ASSERT_LE(glm::length(a - exact(t)), bound) << "t = " << t;
    byHand = stepPendulum(d, byHand, a, h);
    scripted = stepPendulum(d, scripted, exact(t), h);
  }
  EXPECT_NEAR(byHand.angle, scripted.angle, 1e-6);
  // Exact for a pivot with constant acceleration (x = c t²/2).
  const Vec3 c(1.0, -2.0, 0.0);
  auto parabola = [&](Real t) { return 0.5 * t * t * c; };
  EXPECT_VEC3_NEAR(pivotAccelerationFromPositions(parabola(0.9), parabola(1.0), parabola(1.1), 0.1), c, 1e-12);
}

TEST(Pendulum, Asst4StepSwingsWithTheSmallAnglePeriodTwoPiRootIOverMgL) {
  // Amplitude 0.01 rad: the large-amplitude correction 1 + A²/16 is 6·10⁻⁶; symplectic Euler's own
  // frequency error (ωh)²/24 is 5·10⁻⁹ at h = 10⁻⁴ s. Period from upward zero crossings (interpolated).
  const PendulumDesc d = undamped();
  const Real h = 1e-4, period = 2.0 * kPi * std::sqrt(pivotInertia(d) / (d.mass * d.gravity * comDistance(d)));
  PendulumState s{0.0, 0.01 * 2.0 * kPi / period};  // through the bottom at amplitude 0.01 rad
  std::vector<Real> crossings;
  for (int i = 0; i < static_cast<int>(5.5 * period / h); ++i) {
    const PendulumState next = stepPendulum(d, s, Vec3(0.0), h);
    if (s.angle < 0.0 && next.angle >= 0.0) crossings.push_back((i + s.angle / (s.angle - next.angle)) * h);
    s = next;
  }
  ASSERT_GE(crossings.size(), 5u);
  EXPECT_NEAR((crossings.back() - crossings.front()) / static_cast<Real>(crossings.size() - 1), period, 2e-5 * period);
}

TEST(Pendulum, Asst4StepKeepsTheUndampedEnergyInABandWithoutDrift) {
  // Symplectic Euler: the energy error oscillates within O(ω₀h) and does not grow — the same band in
  // the first and the hundredth period (explicit Euler's would grow every step).
  const PendulumDesc d = undamped();
  const Real h = 1.0 / 240.0, omega0 = std::sqrt(d.mass * d.gravity * comDistance(d) / pivotInertia(d));
  const Real period = exactPeriod(d, 1.0);
  const PendulumState start{1.0, 0.0};
  const Real e0 = pendulumEnergy(d, start);
  PendulumState s = start;
  const int perPeriod = static_cast<int>(period / h);
  Real firstBand = 0.0, lastBand = 0.0;
  for (int i = 0; i < 100 * perPeriod; ++i) {
    s = stepPendulum(d, s, Vec3(0.0), h);
    const Real error = std::abs(pendulumEnergy(d, s) - e0) / e0;
    if (i < perPeriod) firstBand = std::max(firstBand, error);
    if (i >= 99 * perPeriod) lastBand = std::max(lastBand, error);
  }
  EXPECT_LE(firstBand, omega0 * h);
  EXPECT_NEAR(lastBand, firstBand, 0.1 * firstBand);
}

}  // namespace
}  // namespace pba::ode
