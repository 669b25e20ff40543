// Free flight of rigid bodies: linear momentum exact, angular momentum conserved by the midpoint
// gyroscopic step (|L| to 1e-9 over 10 s), the intermediate-axis flip of the T-handle, energy that never
// grows. References: closed forms (P(t) = P₀ + m g t, L constant without torque).
#include <cmath>

#include <gtest/gtest.h>

#include "physics/rigid/builders.h"
#include "support/expect_helpers.h"

namespace pba::rigid {
namespace {

World freeWorld(GyroscopicMode mode, THandle& handle, Real spin = 6.0) {
  WorldSettings s;
  s.gyroscopic = mode;
  s.sleeping = false;
  World w(s);
  handle = buildTHandle(w, spin, 0.01);
  return w;
}

TEST(FreeFlight, LinearMomentumFollowsGravityExactly) {
  World w;
  BodyDesc d;
  d.shape = collision::makeBox(Vec3(0.3, 0.1, 0.2)).value();
  d.position = Vec3(0.0, 100.0, 0.0);
  d.linearVelocity = Vec3(1.0, 2.0, -3.0);
  d.angularVelocity = Vec3(3.0, -1.0, 2.0);
  const int b = w.addBody(d).value();
  const Real m = w.body(b).mass;
  const Vec3 p0 = m * d.linearVelocity;
  for (int i = 0; i < 120; ++i) w.step(1.0 / 60.0);
  // Symplectic Euler under constant gravity: v is exact at every step; the tolerance is rounding.
  EXPECT_VEC3_NEAR(w.stats().momentum, p0 + m * w.settings().gravity * w.time(), 1e-9 * m);
}

TEST(FreeFlight, MidpointGyroscopicStepKeepsAngularMomentumAndEnergyOverTenSeconds) {
  THandle t;
  World w = freeWorld(GyroscopicMode::Midpoint, t);
  const Vec3 l0 = angularMomentum(w.body(t.body));
  const Real e0 = kineticEnergy(w.body(t.body));
  Real worstL = 0.0, worstE = 0.0;
  for (int i = 0; i < 600; ++i) {
    w.step(1.0 / 60.0);
    const Vec3 l = angularMomentum(w.body(t.body));
    worstL = std::max(worstL, std::abs(glm::length(l) / glm::length(l0) - 1.0));
    worstL = std::max(worstL, glm::length(l - l0) / glm::length(l0));  // the vector itself, not only |L|
    worstE = std::max(worstE, std::abs(kineticEnergy(w.body(t.body)) / e0 - 1.0));
  }
  EXPECT_LT(worstL, 1e-9);
  EXPECT_LT(worstE, 1e-9);
}

int countFlips(World& w, const THandle& t, int steps) {
  int flips = 0, last = 1;
  for (int i = 0; i < steps; ++i) {
    w.step(1.0 / 60.0);
    const Body& b = w.body(t.body);
    const int sign = glm::dot(b.orientation * Vec3(1, 0, 0), angularMomentum(b)) >= 0.0 ? 1 : -1;
    if (sign != last) ++flips, last = sign;
  }
  return flips;
}

TEST(FreeFlight, TheTHandleFlipsAboutItsIntermediateAxisWithTheGyroscopicTerm) {
  THandle t;
  World w = freeWorld(GyroscopicMode::Midpoint, t);
  // The principal moments bracket the spin axis x: I_y < I_x < I_z.
  EXPECT_LT(t.principalMoments.y, t.principalMoments.x);
  EXPECT_LT(t.principalMoments.x, t.principalMoments.z);
  EXPECT_GE(countFlips(w, t, 600), 2);
  THandle t2;
  World implicit = freeWorld(GyroscopicMode::Implicit, t2);
  EXPECT_GE(countFlips(implicit, t2, 600), 2);
}

TEST(FreeFlight, WithoutTheGyroscopicTermTheHandleSpinsOnWithoutFlipping) {
  THandle t;
  World w = freeWorld(GyroscopicMode::Off, t);
  const Vec3 w0 = w.body(t.body).angularVelocity;
  EXPECT_EQ(countFlips(w, t, 600), 0);
  EXPECT_VEC3_NEAR(w.body(t.body).angularVelocity, w0, 1e-12);  // ω constant: the wrong physics, on purpose
}

TEST(FreeFlight, CattosImplicitStepNeverGainsEnergyOrAngularMomentum) {
  THandle t;
  World w = freeWorld(GyroscopicMode::Implicit, t, 15.0);
  Real e = kineticEnergy(w.body(t.body)), l = glm::length(angularMomentum(w.body(t.body)));
  for (int i = 0; i < 600; ++i) {
    w.step(1.0 / 60.0);
    const Real e1 = kineticEnergy(w.body(t.body)), l1 = glm::length(angularMomentum(w.body(t.body)));
    EXPECT_LE(e1, e * (1.0 + 1e-12)) << "step " << i;
    EXPECT_LE(l1, l * (1.0 + 1e-12)) << "step " << i;
    e = e1, l = l1;
  }
}

}  // namespace
}  // namespace pba::rigid
