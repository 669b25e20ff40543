// ANIM-4: the pendulum joint step with the reaction term. References: the small-angle period
// 2π√(I/(m g L)) of a compound pendulum, the energy of the undamped motion, the equilibrium angle
// atan(a/g) of a pendulum whose pivot accelerates uniformly, and the angular spring's frequency √(k/I).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/animation/pendulum.h"

namespace {

using pba::kPi;
using pba::Real;
using pba::Vec3;
namespace an = pba::animation;

/// Swing in the xy plane from `angle` [rad] off the vertical.
an::PendulumState swungBy(Real angle) { return {Vec3(std::sin(angle), -std::cos(angle), 0.0), Vec3(0.0)}; }

/// Times at which the x component of d changes sign from + to − (one per period).
Real measuredPeriod(const an::PendulumDesc& desc, Real dt, Real seconds) {
  an::PendulumState s = swungBy(0.02);
  const an::PendulumDrive drive;
  std::vector<Real> crossings;
  for (int k = 0; k * dt < seconds; ++k) {
    const an::PendulumState next = an::stepPendulum(desc, s, drive, dt);
    if (s.direction.x > 0.0 && next.direction.x <= 0.0) {
      const Real f = s.direction.x / (s.direction.x - next.direction.x);
      crossings.push_back((k + f) * dt);
    }
    s = next;
  }
  if (crossings.size() < 2) return 0.0;
  return (crossings.back() - crossings.front()) / static_cast<Real>(crossings.size() - 1);
}

TEST(ANIM_4_Pendulum, SmallAnglePeriodMatchesTheCompoundPendulum) {
  for (const Real inertia : {0.0, 0.05}) {  // a point mass (I = m L²), then a rod-like body
    an::PendulumDesc desc;
    desc.mass = 0.4;
    desc.length = 0.3;
    desc.inertia = inertia;
    desc.damping = 0.0;
    const Real expected =
        2.0 * kPi * std::sqrt(desc.momentOfInertia() / (desc.mass * pba::kStandardGravity * desc.length));
    // 0.02 rad amplitude: the finite-amplitude correction θ²/16 is 2.5e-5; symplectic Euler's period
    // error is O((ω dt)²) ≈ 1e-6 at dt = 1e-4 s.
    EXPECT_NEAR(measuredPeriod(desc, 1e-4, 10.0 * expected) / expected, 1.0, 1e-4) << "inertia " << inertia;
  }
}

TEST(ANIM_4_Pendulum, UndampedEnergyStaysBoundedWithoutDrift) {
  an::PendulumDesc desc;
  desc.damping = 0.0;
  an::PendulumState s = swungBy(1.2);
  const an::PendulumDrive drive;
  const Real e0 = an::pendulumEnergy(desc, s, drive);
  const Real dt = 1e-3;
  Real firstWindowMax = 0.0, lastWindowMax = 0.0, leftmost = 1.0;
  const int steps = 100000;  // 100 s, about 100 periods
  for (int k = 0; k < steps; ++k) {
    s = an::stepPendulum(desc, s, drive, dt);
    leftmost = std::min(leftmost, s.direction.x);
    const Real err = std::abs(an::pendulumEnergy(desc, s, drive) - e0);
    if (k < steps / 10) firstWindowMax = std::max(firstWindowMax, err);
    if (k >= steps - steps / 10) lastWindowMax = std::max(lastWindowMax, err);
  }
  // It swings: released at +1.2 rad, it reaches −1.2 rad on the other side (energy conserved).
  EXPECT_LT(leftmost, -0.9 * std::sin(1.2));
  const Real scale = desc.mass * pba::kStandardGravity * desc.length;
  EXPECT_LT(firstWindowMax, 0.01 * scale) << "the symplectic step keeps the energy error small";
  // No drift: the error of the last 10 s is no larger than that of the first 10 s (plus 10 %).
  EXPECT_LT(lastWindowMax, 1.1 * firstWindowMax + 1e-12);
}

TEST(ANIM_4_Pendulum, UniformlyAcceleratedPivotHoldsTheBobAtAtanAOverG) {
  an::PendulumDesc desc;
  desc.damping = 3.0;
  an::PendulumDrive drive;
  const Real a = 4.0;  // [m/s²] along +x
  drive.pivotAcceleration = Vec3(a, 0.0, 0.0);
  an::PendulumState s = swungBy(0.0);
  for (int k = 0; k < 20000; ++k) s = an::stepPendulum(desc, s, drive, 1e-3);
  const Real angle = std::atan2(-s.direction.x, -s.direction.y);  // trailing behind: toward −x
  EXPECT_NEAR(angle, std::atan(a / pba::kStandardGravity), 1e-6);
  EXPECT_NEAR(s.direction.z, 0.0, 1e-12);
  // Without the reaction term the pivot's acceleration is not felt: the bob hangs straight down.
  drive.reaction = false;
  an::PendulumState free = swungBy(0.0);
  for (int k = 0; k < 2000; ++k) free = an::stepPendulum(desc, free, drive, 1e-3);
  EXPECT_NEAR(free.direction.x, 0.0, 1e-12);
}

TEST(ANIM_4_Pendulum, SpringJointOscillatesAtSqrtKOverIWithoutGravity) {
  an::PendulumDesc desc;
  desc.damping = 0.0;
  desc.stiffness = 0.8;  // [N m/rad]
  an::PendulumDrive drive;
  drive.gravity = Vec3(0.0);
  drive.restDirection = Vec3(0.0, 1.0, 0.0);  // an antenna standing up
  an::PendulumState s{glm::normalize(Vec3(0.01, 1.0, 0.0)), Vec3(0.0)};
  const Real omega = std::sqrt(desc.stiffness / desc.momentOfInertia());
  const Real period = 2.0 * kPi / omega, dt = 1e-4;
  Real t = 0.0, firstCrossing = -1.0;
  int crossings = 0;
  for (int k = 0; t < 5.25 * period; ++k, t += dt) {
    const an::PendulumState next = an::stepPendulum(desc, s, drive, dt);
    if (s.direction.x > 0.0 && next.direction.x <= 0.0) {
      if (firstCrossing < 0.0)
        firstCrossing = t;
      else
        ++crossings;
      if (crossings == 5) {
        EXPECT_NEAR((t - firstCrossing) / 5.0 / period, 1.0, 1e-3);
        return;
      }
    }
    s = next;
  }
  FAIL() << "the spring joint did not oscillate";
}

TEST(ANIM_4_Pendulum, DampingScalesTheAngularVelocityByExpMinusCdt) {
  an::PendulumDesc desc;
  desc.damping = 2.0;
  an::PendulumDrive drive;
  drive.gravity = Vec3(0.0);  // no torque: only damping acts
  const an::PendulumState s{Vec3(0.0, -1.0, 0.0), Vec3(0.0, 0.0, 3.0)};
  const an::PendulumState next = an::stepPendulum(desc, s, drive, 0.01);
  EXPECT_NEAR(next.omega.z, 3.0 * std::exp(-0.02), 1e-14);
  EXPECT_NEAR(glm::length(next.direction), 1.0, 1e-14);
}

}  // namespace
