// Collision tests that hold whatever PART-5 does (position projection and the safety net are library
// code): no sinking, no tunnelling, resting contact, signed distances, spatial hash.
#include <cmath>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "physics/ode/integrators.h"
#include "physics/particles/collision.h"
#include "physics/particles/kernels.h"
#include "physics/particles/particle_system.h"
#include "physics/particles/spatial_hash.h"
#include "support/expect_helpers.h"

namespace pba::particles {
namespace {

TEST(ParticleContact, DroppedParticlesComeToRestAndNeverSinkMoreThanAMillimetre) {
  ParticleSystem sys;
  Obstacles obstacles;
  obstacles.planes.push_back({});
  const Real radius = 0.05;
  for (int i = 0; i < 10; ++i) sys.particles.add(Vec3(0.3 * i, 0.5 + 0.2 * i, 0.0), Vec3(0.0), 0.1);
  sys.syncMasses();
  ode::Integrator integrator(ode::IntegratorKind::VelocityVerlet);  // not an exercise
  const Real h = 1.0 / 120.0;
  Real lowest = 1.0;
  for (int step = 0; step < 8 * 120; ++step) {
    integrator.step(sys, h);
    collideWithObstacles(sys.particles, obstacles, radius);
    for (const Vec3& x : sys.particles.position) lowest = std::min(lowest, x.y - radius);
  }
  EXPECT_GT(lowest, -1e-3);
  for (std::size_t i = 0; i < sys.particles.size(); ++i) {
    EXPECT_LT(glm::length(sys.particles.velocity[i]), 1e-3) << "particle " << i;
    EXPECT_NEAR(sys.particles.position[i].y, radius, 1e-3) << "particle " << i;
  }
}

TEST(ParticleContact, AThousandParticlesDroppedFromAHundredMetresNeverTunnel) {
  // Impact speed √(2 g 100 m) ≈ 44 m/s moves 0.37 m per step at 120 Hz, far more than the radius:
  // a swept test is not needed because the plane is a half-space and the projection uses the signed
  // distance (it cannot be "passed").
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<Real> u(-5.0, 5.0);
  ParticleSystem sys;
  for (int i = 0; i < 1000; ++i) sys.particles.add(Vec3(u(rng), 100.0 + u(rng), u(rng)), Vec3(u(rng), 0.0, u(rng)), 0.05);
  sys.syncMasses();
  Obstacles obstacles;
  obstacles.planes.push_back({});
  obstacles.material.restitution = 0.8;
  ode::Integrator integrator(ode::IntegratorKind::VelocityVerlet);  // not an exercise
  const Real radius = 0.02, h = 1.0 / 120.0;
  for (int step = 0; step < 6 * 120; ++step) {
    integrator.step(sys, h);
    collideWithObstacles(sys.particles, obstacles, radius);
    for (std::size_t i = 0; i < sys.particles.size(); ++i) {
      ASSERT_GE(sys.particles.position[i].y, radius - 1e-12) << "particle " << i << " step " << step << " (seed 42)";
    }
  }
}

TEST(ParticleContact, SignedDistancesOfSphereAndRotatedBoxMatchTheGeometry) {
  const SphereObstacle sphere{Vec3(1.0, 2.0, 3.0), 0.5};
  const SurfacePoint s = closestSurface(sphere, Vec3(1.0, 3.0, 3.0));
  EXPECT_NEAR(s.distance, 0.5, 1e-15);
  EXPECT_VEC3_NEAR(s.normal, kUp, 1e-15);
  const Quat q = glm::angleAxis(0.3, Vec3(0.0, 0.0, 1.0));
  const BoxObstacle box{Vec3(0.0), Vec3(1.0, 0.5, 2.0), q};
  // A point 0.2 m beyond the +x face, in the box frame.
  const SurfacePoint face = closestSurface(box, q * Vec3(1.2, 0.1, 0.0));
  EXPECT_NEAR(face.distance, 0.2, 1e-14);
  EXPECT_VEC3_NEAR(face.normal, q * Vec3(1.0, 0.0, 0.0), 1e-14);
  // Inside, nearest to the +y face (0.1 m away).
  const SurfacePoint inside = closestSurface(box, q * Vec3(0.0, 0.4, 0.0));
  EXPECT_NEAR(inside.distance, -0.1, 1e-14);
  EXPECT_VEC3_NEAR(inside.normal, q * kUp, 1e-14);
  // Beyond an edge: distance to the edge.
  const SurfacePoint edge = closestSurface(box, q * Vec3(1.3, 0.9, 0.0));
  EXPECT_NEAR(edge.distance, 0.5, 1e-14);
}

TEST(ParticleContact, ParticlesEndOutsideSpheresAndBoxes) {
  ParticleSystem sys;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) sys.particles.add(Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)), 1.0);
  Obstacles o;
  o.spheres.push_back({Vec3(0.5, 0.0, 0.0), 0.4});
  o.boxes.push_back({Vec3(-0.5, 0.0, 0.0), Vec3(0.3), glm::angleAxis(0.5, glm::normalize(Vec3(1.0, 1.0, 0.0)))});
  const Real r = 0.01;
  collideWithObstacles(sys.particles, o, r);
  for (std::size_t i = 0; i < sys.particles.size(); ++i) {
    const Vec3& x = sys.particles.position[i];
    // One projection can push a particle from one obstacle into the other only where they overlap;
    // they are apart here, so every particle must be outside both (to rounding).
    EXPECT_GE(closestSurface(o.spheres[0], x).distance - r, -1e-12) << i;
    EXPECT_GE(closestSurface(o.boxes[0], x).distance - r, -1e-12) << i;
  }
}

TEST(SpatialHash, FindsExactlyThePairsThatBruteForceFinds) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  std::vector<Vec3> x(2000);
  for (Vec3& p : x) p = Vec3(u(rng), u(rng), u(rng));
  const Real diameter = 0.08;
  SpatialHash hash;
  hash.build(x, diameter);
  std::set<std::pair<std::uint32_t, std::uint32_t>> fromHash, brute;
  for (std::uint32_t i = 0; i < x.size(); ++i) {
    hash.forEachNear(x[i], [&](std::uint32_t j) {
      if (j > i && glm::length(x[i] - x[j]) < diameter) fromHash.insert({i, j});
    });
    for (std::uint32_t j = i + 1; j < x.size(); ++j) {
      if (glm::length(x[i] - x[j]) < diameter) brute.insert({i, j});
    }
  }
  EXPECT_FALSE(brute.empty());
  EXPECT_EQ(fromHash, brute);
}

TEST(SpatialHash, PairCollisionsSeparateParticlesAndConserveMomentum) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<Real> u(-0.3, 0.3);
  Particles p;
  for (int i = 0; i < 500; ++i) p.add(Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)), 0.5 + u(rng));
  const Vec3 before = p.momentum();
  SpatialHash hash;
  const Real radius = 0.02;
  PairCollisionStats first = collideParticlePairs(p, radius, 0.3, hash);
  EXPECT_GT(first.contacts, 0u);
  for (int k = 0; k < 30; ++k) collideParticlePairs(p, radius, 0.3, hash);
  EXPECT_VEC3_NEAR(p.momentum(), before, 1e-12);
  const PairCollisionStats last = collideParticlePairs(p, radius, 0.3, hash);
  EXPECT_LT(last.deepestPenetration, 0.1 * first.deepestPenetration);
}

TEST(FusedKernel, MatchesAHandWrittenReferenceLoop) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  std::vector<Vec3> x(300), v(300);
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = Vec3(u(rng), 0.5 + u(rng), u(rng));
    v[i] = 3.0 * Vec3(u(rng), u(rng), u(rng));
  }
  std::vector<Vec3> xr = x, vr = v;
  FusedStepDesc desc;
  desc.dragRate = 0.25;
  desc.radius = 0.01;
  const Real h = 1.0 / 120.0;
  for (int s = 0; s < 240; ++s) {
    stepGravityDragPlane(x, v, desc, h);
    for (std::size_t i = 0; i < xr.size(); ++i) {  // symplectic Euler, then the plane contact model
      vr[i] += h * (desc.gravity - desc.dragRate * vr[i]);
      xr[i] += h * vr[i];
      if (xr[i].y < desc.radius) xr[i].y = desc.radius;
      if (xr[i].y < desc.radius + kContactSlop && vr[i].y < 0.0) {
        vr[i] = contactVelocity(vr[i], kUp, desc.material);
        vr[i].y = std::max(vr[i].y, 0.0);
      }
    }
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    // Same arithmetic up to the order of operations: 1e-12.
    EXPECT_VEC3_NEAR(x[i], xr[i], 1e-12);
    EXPECT_VEC3_NEAR(v[i], vr[i], 1e-12);
  }
}

}  // namespace
}  // namespace pba::particles
