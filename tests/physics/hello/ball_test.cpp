// Tests of the hello lab's library code that is not an exercise: equilibrium, energy, validation.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/hello/ball.h"
#include "support/expect_helpers.h"

namespace pba::hello {
namespace {

TEST(HelloSpring, TheEquilibriumIsAStationaryPointOfTheSpringAndGravityPotential) {
  // U(x) = k (|x − a| − L)²/2 + m g y: its gradient (central differences, step 1e-6 m) vanishes at the
  // equilibrium the library computes. Independent of the spring force itself (PART-4).
  const SpringDesc desc;
  const Vec3 x = springEquilibrium(desc).position;
  auto potential = [&](const Vec3& p) {
    const Real e = glm::length(p - desc.anchor) - desc.restLength;
    return 0.5 * desc.stiffness * e * e + desc.mass * desc.gravity * p.y;
  };
  const Real step = 1e-6;
  for (int i = 0; i < 3; ++i) {
    Vec3 dx(0.0);
    dx[i] = step;
    // Rounding of U ≈ 30 J over 2·step: 1e-8 N.
    EXPECT_NEAR((potential(x + dx) - potential(x - dx)) / (2 * step), 0.0, 1e-7) << "axis " << i;
  }
  EXPECT_EQ(springEquilibrium(desc).velocity, Vec3(0.0));
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
  desc = BallDesc{};
  desc.restingSpeed = -0.1;
  EXPECT_NE(validate(desc).error().find("restingSpeed"), std::string::npos);
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
