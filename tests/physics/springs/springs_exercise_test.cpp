// Exercise tests of PART-4 (the damped spring force, Lobb notes) and of what depends on it, stepped only by
// methods that are not exercises (implicit Euler, velocity Verlet): a stiff rope settling to its static
// sag, a stiff beam's energy balance, stability above the explicit limit.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/ode/integrators.h"
#include "physics/springs/builders.h"
#include "physics/springs/spring_network.h"
#include "support/expect_helpers.h"
#include "support/fp_traps.h"

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

/// The stiff-spring scene's cantilever: a 10 × 3 × 3 lattice of 0.05 kg particles, k = 1e5 N/m, damping
/// 1 N·s/m, the first layer (9 particles) pinned.
particles::ParticleSystem cantilever() {
  particles::ParticleSystem sys;
  const LatticeDesc beam{Vec3(-1.0, 2.0, -0.2), 10, 3, 3, 0.2, 0.05, 1e5, 1.0, true, false};
  EXPECT_TRUE(appendLattice(beam, sys).ok());
  for (std::size_t i = 0; i < 9; ++i) sys.particles.inverseMass[i] = 0.0;
  sys.syncMasses();
  return sys;
}

TEST(PART_4_DampedSpring, AStiffBeamUnderImplicitEulerSettlesHavingDissipatedItsStoredSpringEnergy) {
  // Released from rest, straight, under gravity: at static equilibrium a linear elastic structure has
  // stored U = W/2 of the work W that gravity did (Clapeyron's theorem), so a damped one has dissipated the
  // other half, E₀ − E = W − U = U. The beam's E₀ is almost all gravitational potential (≈ 40 J against
  // U ≈ 0.05 J), which is why the drift of E itself says nothing; the dissipated energy against the
  // stored spring energy does. Tolerance 0.5 % for the beam's small geometric nonlinearity (observed
  // 1 + 3.5·10⁻⁶: the sag is 0.2 % of the spring lengths).
  particles::ParticleSystem sys = cantilever();
  ode::Integrator integrator(ode::IntegratorKind::ImplicitEuler);
  const Real e0 = sys.energy();
  Real previous = e0;
  for (int i = 0; i < 240; ++i) {  // 2 s at the scene's step
    integrator.step(sys, 1.0 / 120.0);
    ASSERT_TRUE(integrator.lastImplicitStats().converged) << "step " << i;
    EXPECT_LE(sys.energy(), previous + 1e-9) << "step " << i;  // backward Euler never adds energy here
    previous = sys.energy();
  }
  const Real stored = springPotentialEnergy(sys.springs, sys.particles.position);
  const Real kinetic = sys.particles.kineticEnergy();
  ASSERT_GT(stored, 1e-3);
  EXPECT_LT(kinetic, 1e-6 * stored);  // at rest
  EXPECT_NEAR((e0 - sys.energy()) / stored, 1.0, 0.005);
}

TEST(PART_4_DampedSpring, VelocityVerletBlowsUpAboveItsLimitWhereImplicitEulerFollowsTheConvergedSwing) {
  // A 2 m rope of 20 stiff springs (k = 1e5 N/m, undamped), pinned at one end, released horizontally
  // with its last particle kicked 5 cm down. At h = 1/120 s, far above the explicit limit
  // 2/ω_max ≈ 7·10⁻⁴ s, velocity Verlet (not an exercise) explodes; implicit Euler stays stable and
  // follows the rope's swing: its tip after 0.5 s is where a converged run (velocity Verlet at
  // h = 10⁻⁴ s, inside its limit) puts it, within 6 cm (observed 3.1 cm after a 1.3 m swing: implicit
  // Euler damps the fast stretching vibrations that the converged run keeps, and lags its swing by O(h)).
  pba::testing::FloatingPointTrapsOff trapsOff;  // the explicit run overflows on purpose
  RopeDesc desc;
  desc.stiffness = 1e5;
  desc.damping = 0.0;
  auto run = [&](ode::IntegratorKind kind, Real h, int steps) {
    particles::ParticleSystem sys;
    EXPECT_TRUE(appendRope(desc, sys).ok());
    sys.particles.position.back().y -= 0.05;  // a kick
    ode::Integrator integrator(kind);
    for (int i = 0; i < steps; ++i) integrator.step(sys, h);
    return sys;
  };
  const particles::ParticleSystem exploded = run(ode::IntegratorKind::VelocityVerlet, 1.0 / 120.0, 60);
  EXPECT_FALSE(glm::length(exploded.particles.position.back()) < 100.0);  // numerical explosion (NaN counts)
  const particles::ParticleSystem implicit = run(ode::IntegratorKind::ImplicitEuler, 1.0 / 120.0, 60);
  const particles::ParticleSystem converged = run(ode::IntegratorKind::VelocityVerlet, 1e-4, 5000);
  const Vec3 tip = implicit.particles.position.back(), reference = converged.particles.position.back();
  EXPECT_LT(glm::length(tip - reference), 0.06) << "implicit tip " << tip.x << ", " << tip.y;
  EXPECT_LT(springs::maxRelativeStretch(implicit.springs, implicit.particles.position), 0.01);  // observed 0.2 %
}

}  // namespace
}  // namespace pba::springs
