// Exercise tests of PART-4 (the damped spring force, Lobb notes) and of what depends on it: a stiff rope
// under implicit Euler settling to its static sag.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/ode/integrators.h"
#include "physics/springs/builders.h"
#include "physics/springs/spring_network.h"
#include "support/expect_helpers.h"

namespace pba::springs {
namespace {

TEST(PART_4_DampedSpring, UndampedForceIsMinusTheGradientOfTheSpringEnergy) {
  const Vec3 xi{0.1, 0.2, -0.3}, xj{1.0, -0.4, 0.5};
  const Real k = 150.0, L = 0.7;
  auto energy = [&](const Vec3& x) {
    const Real e = glm::length(xj - x) - L;
    return 0.5 * k * e * e;
  };
  Vec3 gradient;
  const Real step = 1e-6;
  for (int a = 0; a < 3; ++a) {
    Vec3 d(0.0);
    d[a] = step;
    gradient[a] = (energy(xi + d) - energy(xi - d)) / (2.0 * step);
  }
  // Central differences: truncation O(k step²), rounding O(1e-16 k/step) ≈ 1e-8.
  EXPECT_VEC3_NEAR(dampedSpringForce(xi, xj, Vec3(0.0), Vec3(0.0), k, L, 0.0), -gradient, 1e-7);
}

TEST(PART_4_DampedSpring, DampingActsAlongTheSpringOnTheRateOfChangeOfLength) {
  const Vec3 xi{0.0, 0.0, 0.0}, xj{2.0, 0.0, 0.0};  // at rest length 2: only damping acts
  const Real kd = 3.0;
  // j moves away at 1.5 m/s along the spring and sideways at 4 m/s: only the 1.5 counts.
  const Vec3 f = dampedSpringForce(xi, xj, Vec3(0.0), Vec3(1.5, 4.0, 0.0), 100.0, 2.0, kd);
  EXPECT_VEC3_NEAR(f, Vec3(kd * 1.5, 0.0, 0.0), 1e-14);
  // A stretched spring pulls i toward j with k (l − L).
  EXPECT_VEC3_NEAR(dampedSpringForce(xi, xj, Vec3(0.0), Vec3(0.0), 100.0, 1.5, kd), Vec3(50.0, 0.0, 0.0), 1e-13);
}

TEST(PART_4_DampedSpring, StiffRopeUnderImplicitEulerSettlesToItsStaticSagAtTenTimesTheExplicitLimit) {
  // A vertical rope of N particles hanging from a pinned top. At rest, segment s (counted from the
  // bottom, s = 1…N−1) carries the weight of the s particles below it: extension s m g / k.
  RopeDesc desc;
  desc.segments = 10;
  desc.start = Vec3(0.0, 5.0, 0.0);
  desc.end = Vec3(0.0, 4.0, 0.0);
  desc.mass = 1.1;  // 0.1 kg per particle
  desc.stiffness = 1e4;
  desc.damping = 5.0;
  particles::ParticleSystem sys;
  ASSERT_TRUE(appendRope(desc, sys).ok());
  const Real m = 0.1, k = desc.stiffness, g = kStandardGravity;
  // Explicit stability limit of the stiffest mode ≈ 2/ω_max, ω_max ≤ 2√(k/m) (chain of equal springs).
  const Real explicitLimit = 2.0 / (2.0 * std::sqrt(k / m));
  const Real h = 10.0 * explicitLimit;
  ode::Integrator integrator(ode::IntegratorKind::ImplicitEuler);
  Real previous = sys.energy();
  for (int i = 0; i < 400; ++i) {
    integrator.step(sys, h);
    ASSERT_TRUE(!particles::describeNonFinite(sys.particles));
    // Dissipative: backward Euler never adds energy to a damped system (tolerance: CG residual).
    EXPECT_LE(sys.energy(), previous + 1e-9) << "step " << i;
    previous = sys.energy();
  }
  const std::size_t n = sys.particles.size();
  for (std::size_t s = 1; s < n; ++s) {  // segment between particles n−1−s and n−s
    const Real length = glm::length(sys.particles.position[n - s] - sys.particles.position[n - 1 - s]);
    EXPECT_NEAR(length - 0.1, static_cast<Real>(s) * m * g / k, 1e-6) << "segment " << s << " from the bottom";
  }
}

}  // namespace
}  // namespace pba::springs
