// Exercise tests of the ODE integrators: PART-1 explicit Euler, PART-2 symplectic Euler, PART-3 RK4,
// PART-6 position Verlet. Each tag's tests step only that tag's method; the expected values come from the
// exact flow of the oscillator (its Taylor polynomials, step matrices, energy factors) or a projectile.
#include <cmath>
#include <cstddef>
#include <span>

#include <gtest/gtest.h>

#include "oscillator_support.h"
#include "physics/ode/ode_system.h"
#include "projectile_support.h"

namespace pba::ode {
namespace {
using testing::convergesWithOrders;
using testing::followsTheProjectile;
using testing::multipliesEnergyEachStepBy;
using testing::Projectile;
using testing::takesOneStepAs;

TEST(PART_1_ExplicitEuler, OneStepIsTheFirstDegreeTaylorPolynomialOfTheExactFlow) {
  // The exact flow of ẍ = −x over h is the rotation x₁ = c x₀ + s v₀, v₁ = −s x₀ + c v₀ with c = cos h,
  // s = sin h; a method of order p reproduces the Taylor polynomials of c and s to degree p, and explicit
  // Euler is exactly degree 1 (c = 1, s = h).
  const Real h = 0.1, c = 1.0, s = h;
  EXPECT_TRUE(takesOneStepAs(IntegratorKind::Euler, {.xx = c, .xv = s, .vx = -s, .vv = c}));
}

TEST(PART_1_ExplicitEuler, ConvergesWithOrderOneOnTheOscillator) {
  EXPECT_TRUE(convergesWithOrders(IntegratorKind::Euler, 2000, {.x = 1.0, .v = 1.0, .phase = 1.0}));
}

TEST(PART_1_ExplicitEuler, MultipliesTheOscillatorEnergyByExactlyOnePlusZSquaredPerStep) {
  // Euler's step matrix [[1, h], [−ω²h, 1]] has determinant 1 + (ωh)²: each step scales
  // m v² + k x² by exactly that (Lobb notes: Euler spirals outward).
  HarmonicOscillator osc;
  Integrator integrator(IntegratorKind::Euler);
  const Real h = 0.1, z = osc.omega() * h;
  ASSERT_TRUE(multipliesEnergyEachStepBy(osc, integrator, h, 200, 1.0 + z * z, 1e-13));
  // Lobb's observation: within three oscillations the energy is several times the initial one.
  EXPECT_GT(osc.energy() / 0.5, 6.0);
}

/// A three-coordinate system whose force the test knows in closed form, f_i = c_i + d_i q_i + e_i v_i + t,
/// with inverse masses (0.5, 0, 2): the middle coordinate is pinned. It counts stateChanged() calls.
class KnownForceSystem final : public OwnedStateSystem {
 public:
  static constexpr Real c[3] = {1.0, -4.0, 0.5}, d[3] = {-3.0, 2.0, -1.5}, e[3] = {-0.2, 0.7, -0.4};
  KnownForceSystem() : OwnedStateSystem({0.3, -1.2, 2.0}, {1.5, 0.0, -0.6}, {0.5, 0.0, 2.0}) {}
  void force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const override {
    for (std::size_t i = 0; i < 3; ++i) out[i] = c[i] + d[i] * q[i] + e[i] * v[i] + t;
  }
  void stateChanged() override { ++changes; }
  int changes = 0;
};

TEST(PART_1_ExplicitEuler, AssemblesTheSlopeFromTheForceAndInverseMassesAtTheStartOfTheStep) {
  // The ODE view: ṡ = (v, M⁻¹ f(t, q, v)), every part taken at the start (t₀ = 2 s). By hand, with
  // h = 0.1: f = (1 − 0.9 − 0.3 + 2, −4 − 2.4 + 0 + 2, 0.5 − 3 + 0.24 + 2) = (1.8, −4.4, −0.26);
  // q₁ = q₀ + h v₀ = (0.45, −1.2, 1.94); v₁ = v₀ + h M⁻¹ f = (1.5 + 0.09, 0, −0.6 − 0.052).
  // The pinned middle coordinate (M⁻¹ = 0) feels −4.4 N and must not move.
  KnownForceSystem system;
  system.setTime(2.0);
  Workspace w;
  explicitEulerStep(system, 0.1, w);
  const Real q1[3] = {0.45, -1.2, 1.94}, v1[3] = {1.59, 0.0, -0.652};
  for (std::size_t i = 0; i < 3; ++i) {
    // Values of order 1 after a handful of operations: a few ulps.
    EXPECT_NEAR(system.positions()[i], q1[i], 1e-15) << "q" << i;
    EXPECT_NEAR(system.velocities()[i], v1[i], 1e-15) << "v" << i;
  }
  EXPECT_EQ(system.positions()[1], -1.2);  // pinned: exactly where it was
  EXPECT_EQ(system.velocities()[1], 0.0);
  EXPECT_NEAR(system.time(), 2.1, 1e-15);  // the clock advanced by h
  EXPECT_EQ(system.changes, 1);            // and the system was told once
}

TEST(PART_1_ExplicitEuler, TheSecondStepStartsFromTheFirstStepsStateAndTime) {
  // Two steps of h = 0.1 from t₀ = 2 s: the second slope is the closed-form force at (q₁, v₁, 2.1 s),
  // q₁ and v₁ from the previous test's hand computation.
  KnownForceSystem system;
  system.setTime(2.0);
  Workspace w;
  explicitEulerStep(system, 0.1, w);
  explicitEulerStep(system, 0.1, w);
  const Real q1[3] = {0.45, -1.2, 1.94}, v1[3] = {1.59, 0.0, -0.652}, inverseMass[3] = {0.5, 0.0, 2.0};
  for (std::size_t i = 0; i < 3; ++i) {
    const Real f1 = KnownForceSystem::c[i] + KnownForceSystem::d[i] * q1[i] + KnownForceSystem::e[i] * v1[i] + 2.1;
    EXPECT_NEAR(system.positions()[i], q1[i] + 0.1 * v1[i], 1e-14) << "q" << i;
    EXPECT_NEAR(system.velocities()[i], v1[i] + 0.1 * inverseMass[i] * f1, 1e-14) << "v" << i;
  }
  EXPECT_NEAR(system.time(), 2.2, 1e-14);
  EXPECT_EQ(system.changes, 2);
}

TEST(PART_2_SymplecticEuler, OneStepIsTheProductOfAKickAndADrift) {
  // On ẍ = −x the method is a kick (a shear of v by −h x) followed by a drift (a shear of x by h v):
  // [[1, h], [0, 1]]·[[1, 0], [−h, 1]] = [[1 − h², h], [−h, 1]], a matrix of determinant 1 (area
  // preserving: symplectic). Explicit Euler's matrix [[1, h], [−h, 1]] differs in the (1, 1) entry.
  const Real h = 0.1;
  EXPECT_TRUE(takesOneStepAs(IntegratorKind::SymplecticEuler, {.xx = 1.0 - h * h, .xv = h, .vx = -h, .vv = 1.0}));
}

TEST(PART_2_SymplecticEuler, ConvergesWithOrderOneOnTheOscillator) {
  // The velocity alone converges with order 2: kick-then-drift is leapfrog with the positions shifted
  // by half a step, x_n ≈ x(t_n + h/2), so the O(h) error lies entirely in x (h v/2).
  EXPECT_TRUE(convergesWithOrders(IntegratorKind::SymplecticEuler, 2000, {.x = 1.0, .v = 2.0, .phase = 1.0}));
}

TEST(PART_2_SymplecticEuler, EnergyErrorStaysWithinHalfOmegaHWithoutDriftOverAThousandPeriods) {
  // Symplectic Euler conserves the modified energy Ẽ = ½(m v² + k x² − h k x v) exactly (ω = 1 here;
  // check: substitute one step). With v₀ = 0, Ẽ = E₀, so E − E₀ = h k x v / 2, whose largest value on
  // the level set Ẽ = E₀ is at x = v: (E − E₀)/E₀ ≤ ωh/(2 − ωh) = ωh/2 + O(h²). The energy therefore
  // oscillates in that band and never drifts.
  HarmonicOscillator osc;
  Integrator integrator(IntegratorKind::SymplecticEuler);
  const Real h = 0.05, e0 = osc.energy();
  const int perPeriod = static_cast<int>(std::lround(2.0 * kPi / h));
  const int periods = 1000;
  Real worst = 0.0, firstPeriodMean = 0.0, lastPeriodMean = 0.0;
  for (int p = 0; p < periods; ++p) {
    Real mean = 0.0;
    for (int i = 0; i < perPeriod; ++i) {
      integrator.step(osc, h);
      worst = std::max(worst, std::abs(osc.energy() - e0) / e0);
      mean += osc.energy() / perPeriod;
    }
    if (p == 0) firstPeriodMean = mean;
    if (p == periods - 1) lastPeriodMean = mean;
  }
  EXPECT_GT(worst, 0.0);
  const Real z = osc.omega() * h;
  EXPECT_LE(worst, z / (2.0 - z));
  EXPECT_GT(worst, 0.9 * z / 2.0);  // and the band is really that wide (the bound is sharp)
  // No drift: the mean over a period is the same after 1000 periods (to rounding and sampling).
  EXPECT_NEAR(lastPeriodMean, firstPeriodMean, 1e-3 * e0);
}

TEST(PART_3_RungeKutta4, OneStepMatchesTheTaylorPolynomialOfDegreeFour) {
  // For ẍ = −x, RK4's step is the degree-4 Taylor polynomial of exp(hA): x₁ = c x₀ + s v₀,
  // v₁ = −s x₀ + c v₀ with c = 1 − h²/2 + h⁴/24, s = h − h³/6.
  const Real h = 0.1, c = 1 - h * h / 2 + h * h * h * h / 24, s = h - h * h * h / 6;
  EXPECT_TRUE(takesOneStepAs(IntegratorKind::Rk4, {.xx = c, .xv = s, .vx = -s, .vv = c}));
}

TEST(PART_3_RungeKutta4, ConvergesWithOrderFourOnTheOscillator) {
  EXPECT_TRUE(convergesWithOrders(IntegratorKind::Rk4, 100, {.x = 4.0, .v = 4.0, .phase = 4.0}));
}

TEST(PART_3_RungeKutta4, LosesEnergyByItsAmplificationFactorPerStep) {
  // |c|² + |s|² with c, s above (ω = 1): 1 − z⁶/72 + z⁸/576.
  HarmonicOscillator osc;
  Integrator integrator(IntegratorKind::Rk4);
  for (Real h : {0.1, 0.3, 0.6}) {
    const Real z = osc.omega() * h;
    const Real factor = 1.0 - std::pow(z, 6) / 72.0 + std::pow(z, 8) / 576.0;
    ASSERT_TRUE(multipliesEnergyEachStepBy(osc, integrator, h, 50, factor, 1e-13));
  }
}

TEST(PART_6_Verlet, ConvergesWithOrderTwoOnTheOscillator) {
  EXPECT_TRUE(convergesWithOrders(IntegratorKind::Verlet, 200, {.x = 2.0, .v = 2.0, .phase = 2.0}));
}

TEST(PART_6_Verlet, FollowsAProjectileExactly) {
  // x(t) = x₀ + v₀ t + g t²/2 is quadratic in t: Verlet's central second difference is exact for it.
  // Rounding only: |x| ≲ 10 m, 200 steps ⇒ 1e-11.
  Integrator integrator(IntegratorKind::Verlet);
  EXPECT_TRUE(followsTheProjectile(integrator, 0.01, 200, 1e-11, 1e-9));
}

TEST(PART_6_Verlet, RestartsWhenTheStateIsChangedFromOutside) {
  // A collision or a mouse drag changes q and v between steps: Verlet must start again from the new
  // state instead of using its stale q(t − h).
  Projectile p;
  Integrator integrator(IntegratorKind::Verlet);
  integrator.step(p, 0.01);
  p.q = {5.0, 5.0, 5.0};
  p.v = {0.0, 0.0, 0.0};
  integrator.step(p, 0.01);
  EXPECT_NEAR(p.q[1], 5.0 + 0.5 * p.g.y * 1e-4, 1e-12);
  EXPECT_NEAR(p.v[1], p.g.y * 0.01, 1e-12);
}

}  // namespace
}  // namespace pba::ode
