// Tests of the hello lab's library code that is not an exercise: spring force, energy, validation.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/hello/ball.h"
#include "support/expect_helpers.h"

namespace pba::hello {
namespace {

TEST(HelloSpring, ForceIsMinusTheGradientOfTheSpringEnergyWithoutDamping) {
  SpringDesc desc;
  desc.damping = 0.0;
  const BallState s{{0.3, 1.2, -0.4}, {0.0, 0.0, 0.0}};
  // Spring potential U(x) = k (|x − a| − L)² / 2; central differences, step 1e-6: error O(1e-12 k).
  auto potential = [&](const Vec3& x) {
    const Real e = glm::length(x - desc.anchor) - desc.restLength;
    return 0.5 * desc.stiffness * e * e;
  };
  const Real step = 1e-6;
  Vec3 gradient;
  for (int i = 0; i < 3; ++i) {
    Vec3 dx(0.0);
    dx[i] = step;
    gradient[i] = (potential(s.position + dx) - potential(s.position - dx)) / (2 * step);
  }
  EXPECT_VEC3_NEAR(springForce(desc, s), -gradient, 1e-7);
}

TEST(HelloSpring, DampingOpposesTheRateOfChangeOfLengthOnly) {
  SpringDesc desc;
  desc.stiffness = 1e-6;  // isolate the damping term (spring force ≈ 0 at rest length)
  BallState s;
  s.position = desc.anchor + Vec3(0.0, -desc.restLength, 0.0);
  s.velocity = Vec3(3.0, -2.0, 0.0);  // sideways part does not change the length
  const Vec3 f = springForce(desc, s);
  EXPECT_NEAR(f.x, 0.0, 1e-12);
  // d = (0, −L, 0), d̂·v = 2 m/s (lengthening) ⇒ F = −c·2·d̂ = (0, 2c, 0): pulls back up.
  EXPECT_NEAR(f.y, 2.0 * desc.damping, 1e-9);
}

TEST(HelloSpring, EquilibriumHasZeroNetForce) {
  const SpringDesc desc;
  EXPECT_VEC3_NEAR(springBallForce(desc, springEquilibrium(desc)), Vec3(0.0), 1e-12);
}

TEST(HelloSpring, SymplecticEulerKeepsTheUndampedEnergyBounded) {
  SpringDesc desc;
  desc.damping = 0.0;
  desc.drag = 0.0;
  BallState s = springEquilibrium(desc);
  s.position += Vec3(0.0, -0.5, 0.0);  // vertical oscillation
  const Real e0 = springEnergy(desc, s);
  const Real h = 1.0 / 240.0;
  const Real omega = std::sqrt(desc.stiffness / desc.mass);
  Real worst = 0.0;
  for (int i = 0; i < 240 * 60; ++i) {  // one minute, ~60 periods
    s = symplecticEulerStep(desc, s, h);
    worst = std::max(worst, std::abs(springEnergy(desc, s) - e0));
  }
  // Symplectic Euler's energy error on an oscillator stays bounded by O(ω h) of the oscillation energy
  // (it samples a nearby conserved quantity); the oscillation energy is k A²/2 with A = 0.5 m.
  const Real oscillationEnergy = 0.5 * desc.stiffness * 0.25;
  EXPECT_LT(worst, omega * h * oscillationEnergy);
}

TEST(HelloBall, ValidationNamesTheOffendingField) {
  BallDesc desc;
  desc.restitution = 1.5;
  const Status s = validate(desc);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("restitution"), std::string::npos) << s.error();
  desc = BallDesc{};
  desc.mass = std::nan("");
  EXPECT_NE(validate(desc).error().find("mass"), std::string::npos);
  EXPECT_TRUE(validate(BallDesc{}).ok());
  SpringDesc spring;
  spring.stiffness = -1.0;
  EXPECT_NE(validate(spring).error().find("stiffness"), std::string::npos);
}

TEST(HelloBall, EnergyIsPotentialAtRestAtTheDropHeight) {
  const BallDesc desc;
  EXPECT_NEAR(energy(desc, initialState(desc)), desc.mass * desc.gravity * desc.dropHeight, 1e-12);
}

}  // namespace
}  // namespace pba::hello
