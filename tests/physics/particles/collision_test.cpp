// Collision tests of library code that hold whatever PART-5 does: position projection (no sinking, no
// tunnelling), the contact-time speed and resting rule, signed distances, the spatial hash, the fused
// kernel against a hand-written reference. Nothing here rests on the contact model's safety net: PART-5's
// behaviour is tested by PART_5_* (collision_exercise_test.cpp), which requires the net to stay idle.
#include <algorithm>
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

TEST(ParticleContact, ProjectionPutsEveryPenetratingParticleOnTheSurfaceAndReportsTheDepth) {
  // Steps 1–2 of the contact model (library code, whatever PART-5 does): a particle found below a plane,
  // inside a sphere or inside a box ends exactly one radius outside it, moved along the normal by its
  // depth; the deepest depth is reported, and particles outside reach are untouched.
  Obstacles o;
  o.planes.push_back({Vec3(0.0, 0.5, 0.0), glm::normalize(Vec3(0.1, 1.0, -0.2))});
  o.spheres.push_back({Vec3(3.0, 0.0, 0.0), 0.7});
  o.boxes.push_back({Vec3(-3.0, 2.0, 0.0), Vec3(0.4, 0.3, 0.5), glm::angleAxis(0.3, Vec3(0.0, 1.0, 0.0))});
  const Real r = 0.02;
  Particles p;
  p.add(Vec3(0.2, 0.4, 0.1), Vec3(0.0, -1.0, 0.0), 1.0);   // 0.1 m below the plane (along y)
  p.add(Vec3(3.3, 0.2, 0.0), Vec3(0.0), 1.0);              // inside the sphere
  p.add(Vec3(-3.0, 2.2, 0.1), Vec3(0.3, -0.5, 1.0), 1.0);  // inside the box, nearest its +y face
  p.add(Vec3(0.0, 5.0, 0.0), Vec3(1.0, 2.0, 3.0), 1.0);    // far from everything
  const Particles before = p;
  const CollisionStats stats = collideWithObstacles(p, o, r);
  EXPECT_NEAR(closestSurface(o.planes[0], p.position[0]).distance, r, 1e-14);
  EXPECT_NEAR(closestSurface(o.spheres[0], p.position[1]).distance, r, 1e-14);
  EXPECT_NEAR(closestSurface(o.boxes[0], p.position[2]).distance, r, 1e-14);
  for (std::size_t i = 0; i < 3; ++i) {  // moved along the normal only
    const Vec3 move = p.position[i] - before.position[i];
    const SurfacePoint s = i == 0 ? closestSurface(o.planes[0], p.position[i])
                                  : i == 1 ? closestSurface(o.spheres[0], p.position[i])
                                           : closestSurface(o.boxes[0], p.position[i]);
    EXPECT_NEAR(glm::length(glm::cross(move, s.normal)), 0.0, 1e-14) << "particle " << i;
  }
  EXPECT_VEC3_NEAR(p.position[3], before.position[3], 0.0);
  EXPECT_VEC3_NEAR(p.velocity[3], before.velocity[3], 0.0);
  const Real planeDepth = r - closestSurface(o.planes[0], before.position[0]).distance;
  const Real sphereDepth = r - closestSurface(o.spheres[0], before.position[1]).distance;
  const Real boxDepth = r - closestSurface(o.boxes[0], before.position[2]).distance;
  EXPECT_NEAR(stats.deepestPenetration, std::max({planeDepth, sphereDepth, boxDepth}), 1e-15);
  EXPECT_EQ(stats.contacts, 2u);  // the plane's and the box's particles move inward; the sphere's is at rest
}

TEST(ParticleContact, TheContactTimeSpeedAndTheRestingRuleFollowConstantAccelerationKinematics) {
  // Steps 3–4 (classifyApproach, library code): a particle that fell a depth d past the surface under a_n
  // arrived at √(s² − 2 a_n d); it rests when that is at most restingSpeed + a_n h.
  const Real g = kStandardGravity, h = 0.01;
  const ContactApproach impact = classifyApproach(0.02, 3.0, g, 0.1, h);
  EXPECT_EQ(impact.kind, ContactKind::Impact);
  EXPECT_NEAR(impact.contactSpeed, std::sqrt(9.0 - 2.0 * g * 0.02), 1e-15);
  // A fall from 1 m found 5 mm below the surface at the end of the step: it hit at √(2 g · 1 m).
  const Real u = std::sqrt(2.0 * g * 1.005);
  EXPECT_NEAR(classifyApproach(0.005, u, g, 0.1, h).contactSpeed, std::sqrt(2.0 * g * 1.0), 1e-12);
  // One step of gravity from rest on the surface: speed g h at depth g h²/2 (exact flight, s_c = 0) or at
  // depth 0 (explicit Euler moves with the old velocity, s_c = g h): both rest, at any resting speed ≥ 0.
  EXPECT_EQ(classifyApproach(0.5 * g * h * h, g * h, g, 0.0, h).kind, ContactKind::Resting);
  EXPECT_EQ(classifyApproach(0.0, g * h, g, 0.0, h).kind, ContactKind::Resting);
  // Just above and below the threshold, no gravity.
  EXPECT_EQ(classifyApproach(0.0, 0.1 + 1e-9, 0.0, 0.1, h).kind, ContactKind::Impact);
  EXPECT_EQ(classifyApproach(0.0, 0.1, 0.0, 0.1, h).kind, ContactKind::Resting);
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

TEST(FusedKernel, MatchesAHandWrittenVelocityVerletLoopWithAnInelasticFrictionlessGround) {
  // Reference loop written here: velocity Verlet under a = g − k v (two half kicks around a drift, the
  // force at the half-step velocity), and for the ground the response of an inelastic frictionless
  // contact — out of the ground, no inward speed, the tangential speed kept. With restitution 0 and no
  // friction that is what the library's contact model gives, impact or resting, whatever PART-5 is
  // (a stub leaves the inward speed to the model's safety net, which removes it the same way).
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
  desc.material = ContactMaterial{0.0, 0.0, 0.0, 0.1};
  const Real h = 1.0 / 120.0;
  std::size_t grounded = 0;
  for (int s = 0; s < 240; ++s) {
    stepGravityDragPlane(x, v, desc, h);
    for (std::size_t i = 0; i < xr.size(); ++i) {
      vr[i] += 0.5 * h * (desc.gravity - desc.dragRate * vr[i]);
      xr[i] += h * vr[i];
      vr[i] += 0.5 * h * (desc.gravity - desc.dragRate * vr[i]);
      if (xr[i].y < desc.radius + kContactSlop) {
        xr[i].y = std::max(xr[i].y, desc.radius);
        vr[i].y = std::max(vr[i].y, 0.0);
        ++grounded;
      }
    }
  }
  EXPECT_GT(grounded, 10000u);  // most of the 300 particles land within the 2 s
  for (std::size_t i = 0; i < x.size(); ++i) {
    // Same arithmetic up to the order of operations: 1e-12.
    EXPECT_VEC3_NEAR(x[i], xr[i], 1e-12);
    EXPECT_VEC3_NEAR(v[i], vr[i], 1e-12);
  }
}

TEST(FusedKernel, MatchesTheGenericPathOfForcesVelocityVerletAndTheContactModel) {
  // With a bouncy, rough ground: the generic path (ParticleSystem forces, ode::velocityVerletStep,
  // collideWithObstacles with the step's gravity and h) is the reference of the kernel's wiring of the
  // one contact model (the model itself is tested above and by PART-5).
  std::mt19937_64 rng(10);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  FusedStepDesc desc;
  desc.dragRate = 0.25;
  desc.radius = 0.01;
  desc.material = ContactMaterial{0.6, 0.5, 0.3, 0.1};
  ParticleSystem sys;
  sys.forces.gravity = desc.gravity;
  sys.forces.drag.linear = desc.dragRate * 0.1;  // c = (c/m)·m for particles of 0.1 kg
  for (int i = 0; i < 300; ++i) sys.particles.add(Vec3(u(rng), 0.5 + u(rng), u(rng)), 3.0 * Vec3(u(rng), u(rng), u(rng)), 0.1);
  sys.syncMasses();
  std::vector<Vec3> x = sys.particles.position, v = sys.particles.velocity;
  Obstacles ground;
  ground.planes.push_back(desc.ground);
  ground.material = desc.material;
  ode::Integrator integrator(ode::IntegratorKind::VelocityVerlet);
  const Real h = 1.0 / 120.0;
  std::size_t impacts = 0;
  for (int s = 0; s < 240; ++s) {
    stepGravityDragPlane(x, v, desc, h);
    integrator.step(sys, h);
    impacts += collideWithObstacles(sys.particles, ground, desc.radius, {desc.gravity, h}).impacts;
  }
  EXPECT_GT(impacts, 200u);  // every particle lands at least once
  for (std::size_t i = 0; i < x.size(); ++i) {
    // The same formulas grouped differently ((1 − hk/2) v + (h/2) g against v + (h/2) a): rounding of
    // 1e-16 relative per step, amplified by the bounces.
    EXPECT_VEC3_NEAR(x[i], sys.particles.position[i], 1e-11);
    EXPECT_VEC3_NEAR(v[i], sys.particles.velocity[i], 1e-11);
  }
}

}  // namespace
}  // namespace pba::particles
