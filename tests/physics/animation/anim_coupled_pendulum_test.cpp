// The coupled n-link pendulum (physics/animation/coupled_pendulum.h, RATTLE on constrained particles).
// References written here: the planar double pendulum's closed-form equations of motion (Lagrange, in
// the two angles from the vertical) integrated by a hand-written RK4 at a small step; the small-angle
// normal modes of two equal links, ω² = (g/L)(2 ∓ √2); conservation of the mechanical energy.
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "physics/animation/coupled_pendulum.h"

namespace pba::animation {
namespace {

const Vec3 kGravity(0.0, -9.81, 0.0);  // [m/s²]

CoupledPendulum chain(const std::vector<Real>& m, const std::vector<Real>& L) {
  CoupledPendulum c;
  c.masses = m;
  c.lengths = L;
  c.rest(Vec3(0.0), Vec3(0, -1, 0));
  return c;
}

/// Puts a planar chain (x-y plane, pivot at the origin) at angles θ_k from the downward vertical, at rest.
void setAngles(CoupledPendulum& c, const std::vector<Real>& theta) {
  Vec3 p(0.0);
  for (size_t k = 0; k < theta.size(); ++k) {
    p += c.lengths[k] * Vec3(std::sin(theta[k]), -std::cos(theta[k]), 0.0);
    c.positions[k] = p;
    c.velocities[k] = Vec3(0.0);
  }
}

Real angleOf(const CoupledPendulum& c, size_t k) {
  const Vec3 r = c.positions[k] - (k == 0 ? c.pivot : c.positions[k - 1]);
  return std::atan2(r.x, -r.y);
}

/// The closed-form double pendulum: state (θ1, θ2, ω1, ω2), masses m1, m2 at the ends of rods L1, L2.
struct DoublePendulum {
  Real m1, m2, L1, L2, g;
  std::array<Real, 4> derivative(const std::array<Real, 4>& s) const {
    const Real t1 = s[0], t2 = s[1], w1 = s[2], w2 = s[3], d = t1 - t2;
    const Real den = 2.0 * m1 + m2 - m2 * std::cos(2.0 * d);
    const Real a1 = (-g * (2.0 * m1 + m2) * std::sin(t1) - m2 * g * std::sin(t1 - 2.0 * t2) -
                     2.0 * std::sin(d) * m2 * (w2 * w2 * L2 + w1 * w1 * L1 * std::cos(d))) /
                    (L1 * den);
    const Real a2 = (2.0 * std::sin(d) *
                     (w1 * w1 * L1 * (m1 + m2) + g * (m1 + m2) * std::cos(t1) + w2 * w2 * L2 * m2 * std::cos(d))) /
                    (L2 * den);
    return {w1, w2, a1, a2};
  }
  void rk4(std::array<Real, 4>& s, Real h) const {
    auto add = [](std::array<Real, 4> a, const std::array<Real, 4>& b, Real f) {
      for (int i = 0; i < 4; ++i) a[i] += f * b[i];
      return a;
    };
    const auto k1 = derivative(s), k2 = derivative(add(s, k1, h / 2)), k3 = derivative(add(s, k2, h / 2)),
               k4 = derivative(add(s, k3, h));
    for (int i = 0; i < 4; ++i) s[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  }
};

TEST(CoupledPendulum, DoublePendulumFollowsAnRk4OfTheClosedFormEquations) {
  const Real m1 = 1.0, m2 = 0.5, L1 = 1.0, L2 = 0.7, h = 1e-4;
  CoupledPendulum c = chain({m1, m2}, {L1, L2});
  setAngles(c, {0.6, -0.4});
  const DoublePendulum reference{m1, m2, L1, L2, 9.81};
  std::array<Real, 4> s{0.6, -0.4, 0.0, 0.0};
  Real worst = 0.0;
  for (int step = 1; step <= 20000; ++step) {  // 2 s
    c.step(Vec3(0.0), Vec3(0.0), kGravity, h);
    reference.rk4(s, h);
    if (step % 500 == 0) {
      const Vec3 p1 = L1 * Vec3(std::sin(s[0]), -std::cos(s[0]), 0.0);
      const Vec3 p2 = p1 + L2 * Vec3(std::sin(s[1]), -std::cos(s[1]), 0.0);
      worst = std::max({worst, glm::length(c.positions[0] - p1), glm::length(c.positions[1] - p2)});
    }
  }
  // RATTLE is second order: at h = 1e-4 s its error over 2 s is micrometres (RK4's is far below).
  EXPECT_LT(worst, 1e-5) << "largest bob distance from the reference [m]";
  std::cout << "largest distance from the RK4 reference " << worst << " m\n";
  EXPECT_LT(c.constraintError(), 1e-10);
}

/// Period [s] of θ1 from its upward zero crossings (linear interpolation) over `seconds`.
Real measuredPeriod(Real ratio, Real seconds) {
  const Real h = 1e-4, amplitude = 0.01;
  CoupledPendulum c = chain({1.0, 1.0}, {1.0, 1.0});
  setAngles(c, {amplitude, ratio * amplitude});
  std::vector<Real> crossings;
  Real last = angleOf(c, 0);
  for (int step = 1; step * h <= seconds; ++step) {
    c.step(Vec3(0.0), Vec3(0.0), kGravity, h);
    const Real now = angleOf(c, 0);
    if (last < 0.0 && now >= 0.0) crossings.push_back((step - 1 + last / (last - now)) * h);
    last = now;
  }
  if (crossings.size() < 2) return 0.0;
  return (crossings.back() - crossings.front()) / static_cast<Real>(crossings.size() - 1);
}

TEST(CoupledPendulum, EqualLinksSwingInTheNormalModesOfTheSmallAngleTheory) {
  // Linearised: M θ̈ + K θ = 0 with M = [[2, 1], [1, 1]] m L², K = diag(2, 1) m g L; the modes are
  // θ2/θ1 = ±√2 with ω² = (g/L)(2 ∓ √2).
  const Real g = 9.81, L = 1.0;
  const Real slow = 2.0 * kPi / std::sqrt(g / L * (2.0 - std::sqrt(2.0)));
  const Real fast = 2.0 * kPi / std::sqrt(g / L * (2.0 + std::sqrt(2.0)));
  const Real a = measuredPeriod(std::sqrt(2.0), 4.0 * slow), b = measuredPeriod(-std::sqrt(2.0), 4.0 * fast);
  // At 0.01 rad the amplitude's own correction is ~θ²/16 ≈ 1e-5 relative.
  std::cout << "periods " << a << " s (theory " << slow << " s), " << b << " s (theory " << fast << " s)\n";
  EXPECT_NEAR(a / slow, 1.0, 1e-3) << "in-phase mode: " << a << " s against " << slow << " s";
  EXPECT_NEAR(b / fast, 1.0, 1e-3) << "anti-phase mode: " << b << " s against " << fast << " s";
}

TEST(CoupledPendulum, UndampedEnergyStaysBoundedWithoutDrift) {
  CoupledPendulum c = chain({0.3, 0.2, 0.1}, {0.4, 0.3, 0.3});
  setAngles(c, {1.2, -0.5, 2.0});  // large, chaotic swings
  const Real h = 1.0 / 240.0, e0 = c.energy(kGravity);
  const Real scale = (0.3 + 0.2 + 0.1) * 9.81 * 1.0;  // [J] m g (total length): the energy's size
  Real worst = 0.0, firstSum = 0.0, lastSum = 0.0;
  const int steps = 240 * 60;  // one minute
  for (int step = 1; step <= steps; ++step) {
    c.step(Vec3(0.0), Vec3(0.0), kGravity, h);
    const Real e = c.energy(kGravity) - e0;
    worst = std::max(worst, std::abs(e));
    if (step <= steps / 6) firstSum += e;
    if (step > steps - steps / 6) lastSum += e;
  }
  const Real drift = (lastSum - firstSum) / (steps / 6);
  std::cout << "energy: largest excursion " << worst / scale << ", drift " << drift / scale << " of m g L\n";
  EXPECT_LT(worst / scale, 5e-3) << "largest energy excursion [J] " << worst;
  EXPECT_LT(std::abs(drift) / scale, 5e-4) << "mean energy of the last ten seconds minus the first " << drift;
  EXPECT_LT(c.constraintError(), 1e-10);
}

TEST(CoupledPendulum, TheLowerBobPullsTheUpperOne) {
  // The upper bob hangs straight down at rest, the lower is swung out: in a one-way chain (pendulum.h)
  // the upper link would not move; here the lower rod's tension pulls it sideways at once.
  CoupledPendulum c = chain({1.0, 1.0}, {1.0, 1.0});
  setAngles(c, {0.0, 0.8});
  for (int step = 0; step < 100; ++step) c.step(Vec3(0.0), Vec3(0.0), kGravity, 1e-3);
  EXPECT_GT(angleOf(c, 0), 1e-3) << "the upper link swings toward the lower bob";
}

TEST(CoupledPendulum, ADampedChainComesToRestBelowAMovingPivot) {
  CoupledPendulum c = chain({0.05, 0.05, 0.05, 0.05}, {0.1, 0.1, 0.1, 0.1});
  c.damping = 2.0;
  setAngles(c, {1.0, 0.5, -0.5, 1.0});
  const Vec3 v(0.5, 0.0, 0.0);  // [m/s] the pivot slides at a constant velocity
  const Real h = 1.0 / 240.0;
  for (int step = 1; step <= 240 * 10; ++step) c.step(v * (step * h), v, kGravity, h);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(std::abs(angleOf(c, k)), 0.0, 1e-3) << "link " << k;
    EXPECT_LT(glm::length(c.velocities[k] - v), 1e-3) << "link " << k;
  }
}

TEST(CoupledPendulum, BadDescriptionsNameTheField) {
  CoupledPendulum c = chain({1.0, 1.0}, {1.0, 1.0});
  EXPECT_TRUE(c.validate().ok());
  c.lengths = {1.0};
  EXPECT_NE(c.validate().error().find("lengths"), std::string::npos);
  c.lengths = {1.0, 0.0};
  EXPECT_NE(c.validate().error().find("lengths[1]"), std::string::npos);
  c.lengths = {1.0, 1.0};
  c.masses = {1.0, -2.0};
  EXPECT_NE(c.validate().error().find("masses[1]"), std::string::npos);
}

}  // namespace
}  // namespace pba::animation
