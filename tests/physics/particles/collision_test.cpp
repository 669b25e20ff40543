// Collision tests that hold whatever PART-5 does (position projection and the safety net are library
// code): no sinking, no tunnelling, resting contact, signed distances, spatial hash.
#include <cmath>
#include <random>
#include <set>
#include <tuple>

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

TEST(NeighbourList, HoldsEveryTouchingPairUntilAParticleMovesHalfTheSkin) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  std::vector<Vec3> x(1500);
  for (Vec3& p : x) p = Vec3(u(rng), u(rng), u(rng));
  const Real contact = 0.08, skin = 0.04;
  SpatialHash hash;
  NeighbourList list;
  ASSERT_TRUE(list.update(x, contact, skin, hash));
  auto listed = [&] { return std::set<NeighbourList::Pair>(list.pairs().begin(), list.pairs().end()); };
  // Built: exactly the pairs closer than contact + skin (brute force).
  std::set<NeighbourList::Pair> within;
  for (std::uint32_t i = 0; i < x.size(); ++i)
    for (std::uint32_t j = i + 1; j < x.size(); ++j)
      if (glm::length(x[i] - x[j]) < contact + skin) within.insert({i, j});
  EXPECT_EQ(listed(), within);
  // Every particle moves up to 0.49·skin in a random direction, five times over from the built
  // positions: the list is kept, and still holds every pair now closer than the contact distance.
  const std::vector<Vec3> built = x;
  for (int round = 0; round < 5; ++round) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Vec3 dir = glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(1e-9));
      x[i] = built[i] + 0.49 * skin * (0.5 * (u(rng) + 1.0)) * dir;
    }
    EXPECT_FALSE(list.update(x, contact, skin, hash)) << "round " << round;
    const std::set<NeighbourList::Pair> have = listed();
    std::size_t touching = 0;
    for (std::uint32_t i = 0; i < x.size(); ++i)
      for (std::uint32_t j = i + 1; j < x.size(); ++j)
        if (glm::length(x[i] - x[j]) < contact) {
          ++touching;
          EXPECT_TRUE(have.count({i, j})) << i << " " << j;
        }
    EXPECT_GT(touching, 100u);
  }
  // One particle beyond skin/2: rebuilt. So is a list asked for another contact distance.
  x[3] = built[3] + Vec3(0.51 * skin, 0.0, 0.0);
  EXPECT_TRUE(list.update(x, contact, skin, hash));
  EXPECT_FALSE(list.update(x, contact, skin, hash));
  EXPECT_TRUE(list.update(x, 0.9 * contact, skin, hash));
  EXPECT_EQ(list.builds(), 3u);
}

TEST(NeighbourList, APileSweptThroughItSettlesLikeOneSweptThroughTheHashEverySweep) {
  // 400 grains poured into a bin, three sweeps per step: once with the hash rebuilt and queried every
  // sweep (the reference), once through a neighbour list. Both must end inside the bin, on the floor,
  // with bounded overlaps, and packed alike (mean height); the order of the pair visits differs
  // slightly, so the piles are alike, not identical.
  const Real radius = 0.04, h = 1.0 / 120.0, bin = 0.5;
  // The floor and walls by hand (inelastic, frictionless), so that the test does not depend on PART-5.
  auto walls = [&](Particles& p) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      Vec3& x = p.position[i];
      Vec3& v = p.velocity[i];
      if (x.y < radius) x.y = radius, v.y = std::max(v.y, 0.0);
      for (int axis : {0, 2}) {
        if (x[axis] < -bin + radius) x[axis] = -bin + radius, v[axis] = std::max(v[axis], 0.0);
        if (x[axis] > bin - radius) x[axis] = bin - radius, v[axis] = std::min(v[axis], 0.0);
      }
    }
  };
  auto pile = [&](bool useList) {
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<Real> u(-1.0, 1.0);
    Particles p;
    for (int i = 0; i < 400; ++i) {
      p.add(Vec3(0.4 * bin * u(rng), 0.3 + 1.0 * (u(rng) + 1.0), 0.4 * bin * u(rng)), Vec3(0.0), 0.01);
    }
    SpatialHash hash;
    NeighbourList list;
    Real deepest = 0.0;
    for (int step = 0; step < 360; ++step) {
      for (std::size_t i = 0; i < p.size(); ++i) {  // symplectic Euler under gravity, by hand
        p.velocity[i].y -= h * kStandardGravity;
        p.position[i] += h * p.velocity[i];
      }
      for (int sweep = 0; sweep < 3; ++sweep) {
        PairCollisionStats s;
        if (useList) {
          list.update(p.position, 2.0 * radius, radius, hash);
          s = collideParticlePairs(p, radius, 0.1, list.pairs());
        } else {
          s = collideParticlePairs(p, radius, 0.1, hash);
        }
        walls(p);
        if (step == 359 && sweep == 2) deepest = s.deepestPenetration;
      }
    }
    Real meanHeight = 0.0;
    for (const Vec3& x : p.position) {
      EXPECT_GE(x.y, radius - 1e-9);
      EXPECT_LE(std::max(std::abs(x.x), std::abs(x.z)), bin - radius + 1e-9);
      meanHeight += x.y / static_cast<Real>(p.size());
    }
    return std::make_tuple(deepest, meanHeight, list.builds());
  };
  const auto [deepHash, heightHash, buildsHash] = pile(false);
  const auto [deepList, heightList, builds] = pile(true);
  // Three sweeps leave frictionless grains overlapping by 0.3–0.6 r at the deepest pair either way (ten
  // seeds: hash 12–21 mm, list 14–25 mm); a list that missed pairs would let grains pass through each
  // other, sink the pile towards one layer (mean height r instead of ≈ 2.2 r) and overlap up to 2r.
  EXPECT_LT(deepHash, 0.75 * radius);
  EXPECT_LT(deepList, 0.75 * radius);
  EXPECT_NEAR(heightList, heightHash, 0.1 * radius);  // mean grain height: the pile's packing
  EXPECT_EQ(buildsHash, 0u);
  EXPECT_LT(builds, 360u);  // fewer hash queries than steps, let alone sweeps (3 × 360)
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
