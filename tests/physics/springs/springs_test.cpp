// Mass-spring tests that do not depend on the PART-4 exercise: momentum conservation, the analytic
// Jacobian against finite differences, builders and their validation.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "physics/ode/integrators.h"
#include "physics/springs/builders.h"
#include "physics/springs/spring_network.h"
#include "support/expect_helpers.h"
#include "support/fp_traps.h"

namespace pba::springs {
namespace {

particles::ParticleSystem freeLattice(std::uint64_t seed) {
  particles::ParticleSystem sys;
  LatticeDesc desc;
  desc.nx = desc.ny = desc.nz = 4;
  desc.stiffness = 200.0;
  desc.damping = 0.3;
  (void)appendLattice(desc, sys);
  sys.forces.gravity = Vec3(0.0);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<Real> u(-0.5, 0.5);
  for (std::size_t i = 0; i < sys.particles.size(); ++i) {
    sys.particles.velocity[i] = Vec3(u(rng), u(rng), u(rng));
    sys.particles.position[i] += 0.02 * Vec3(u(rng), u(rng), u(rng));
    sys.particles.inverseMass[i] = 1.0 / (0.01 * (1.5 + u(rng)));  // unequal masses
  }
  sys.syncMasses();
  return sys;
}

TEST(SpringNetwork, FreeNetworkConservesMomentumUnderEveryIntegrator) {
  for (ode::IntegratorKind kind : ode::kAllIntegrators) {
    particles::ParticleSystem sys = freeLattice(17);
    const Vec3 p0 = sys.momentum();
    ode::Integrator integrator(kind);
    for (int i = 0; i < 100; ++i) integrator.step(sys, 1e-3);
    // Internal forces cancel in pairs: only rounding remains (|p| ~ 0.1 kg·m/s, 100 steps).
    EXPECT_VEC3_NEAR(sys.momentum(), p0, 1e-12);
  }
}

TEST(SpringNetwork, AnalyticJacobianMatchesFiniteDifferencesOfHookesLaw) {
  particles::ParticleSystem sys = freeLattice(4);
  // Stretch everything so that (1 − L/l) > 0 everywhere: the definiteness clamp is then inactive.
  for (Vec3& x : sys.particles.position) x *= 1.1;
  // Independent reference: Hooke's law written here (undamped), differentiated by central differences.
  auto hooke = [&](const std::vector<Vec3>& x) {
    std::vector<Vec3> f(x.size(), Vec3(0.0));
    for (const Spring& s : sys.springs) {
      const Vec3 r = x[s.j] - x[s.i];
      const Vec3 fi = s.stiffness * (glm::length(r) - s.restLength) * r / glm::length(r);
      f[s.i] += fi;
      f[s.j] -= fi;
    }
    return f;
  };
  const std::size_t count = sys.particles.size();
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  std::vector<Vec3> dx(count), zero(count, Vec3(0.0)), analytic(count, Vec3(0.0));
  for (Vec3& d : dx) d = Vec3(u(rng), u(rng), u(rng));
  accumulateSpringDifferential(sys.springs, sys.particles.position, dx, zero, analytic);
  const Real eps = 1e-6;
  std::vector<Vec3> plus = sys.particles.position, minus = sys.particles.position;
  for (std::size_t i = 0; i < count; ++i) {
    plus[i] += eps * dx[i];
    minus[i] -= eps * dx[i];
  }
  const std::vector<Vec3> fp = hooke(plus), fm = hooke(minus);
  // Truncation O(k eps²) and rounding O(1e-16 k / eps) with k = 200 N/m: 1e-6 is ample.
  for (std::size_t i = 0; i < count; ++i) EXPECT_VEC3_NEAR(analytic[i], (fp[i] - fm[i]) / (2.0 * eps), 1e-6);
}

TEST(PART_4_DampedSpring, SymplecticEulerBlowsUpAboveItsLimitWhereImplicitEulerStaysBounded) {
  pba::testing::FloatingPointTrapsOff trapsOff;  // the explicit run overflows on purpose
  RopeDesc desc;
  desc.stiffness = 1e5;
  desc.damping = 0.0;
  for (ode::IntegratorKind kind : {ode::IntegratorKind::SymplecticEuler, ode::IntegratorKind::ImplicitEuler}) {
    particles::ParticleSystem sys;
    ASSERT_TRUE(appendRope(desc, sys).ok());
    sys.particles.position.back().y -= 0.05;  // a kick
    ode::Integrator integrator(kind);
    const Real h = 1.0 / 120.0;  // ≫ 2/ω_max ≈ 2·10⁻³ s
    const particles::ParticleSystem start = sys;
    for (int i = 0; i < 60; ++i) integrator.step(sys, h);
    const Real drift = glm::length(sys.particles.position.back() - start.particles.position.back());
    if (kind == ode::IntegratorKind::ImplicitEuler) {
      EXPECT_LT(drift, 5.0);
    } else {
      EXPECT_FALSE(drift < 100.0) << drift;  // numerical explosion (NaN counts)
    }
  }
}

TEST(Builders, BuildTheRequestedTopology) {
  particles::ParticleSystem sys;
  RopeDesc rope;
  rope.segments = 8;
  rope.bending = true;
  ASSERT_TRUE(appendRope(rope, sys).ok());
  EXPECT_EQ(sys.particles.size(), 9u);
  EXPECT_EQ(sys.springs.size(), 8u + 7u);
  EXPECT_EQ(sys.particles.inverseMass[0], 0.0);  // pinned start
  LatticeDesc lattice;
  lattice.nx = 3;
  lattice.ny = 2;
  lattice.nz = 2;
  lattice.shear = false;
  const auto first = appendLattice(lattice, sys);
  ASSERT_TRUE(first.ok());
  EXPECT_EQ(first.value(), 9u);
  EXPECT_EQ(sys.particles.size(), 9u + 12u);
  // Structural springs of a 3×2×2 grid: 2·2·2 + 3·1·2 + 3·2·1 = 20.
  EXPECT_EQ(sys.springs.size(), 15u + 20u);
  BlobDesc blob;
  ASSERT_TRUE(appendBlob(blob, sys).ok());
  EXPECT_EQ(sys.dofCount(), 3 * sys.particles.size());
  for (const Spring& s : sys.springs) EXPECT_GT(s.restLength, 0.0);
}

TEST(Builders, ValidationNamesTheOffendingField) {
  particles::ParticleSystem sys;
  RopeDesc rope;
  rope.segments = 0;
  EXPECT_NE(appendRope(rope, sys).error().find("rope.segments"), std::string::npos);
  rope = RopeDesc{};
  rope.stiffness = -1.0;
  EXPECT_NE(appendRope(rope, sys).error().find("rope.stiffness"), std::string::npos);
  LatticeDesc lattice;
  lattice.spacing = std::nan("");
  EXPECT_NE(appendLattice(lattice, sys).error().find("lattice.spacing"), std::string::npos);
  BlobDesc blob;
  blob.neighbours = 1000;
  EXPECT_NE(appendBlob(blob, sys).error().find("blob.neighbours"), std::string::npos);
  EXPECT_TRUE(sys.particles.empty());
}

}  // namespace
}  // namespace pba::springs
