// The fountain's one-pass pool step (particles::stepFountain): ageing and removal, motion, contacts, the
// guard's finiteness test and the energy sums, each against an independent reference: the generic path
// (ParticleSystem, ode::velocityVerletStep, collideWithObstacles), closed sums, describeNonFinite.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "physics/particles/collision.h"
#include "physics/particles/emitter.h"
#include "physics/particles/forces.h"
#include "physics/particles/kernels.h"
#include "physics/particles/particle_system.h"
#include "physics/ode/integrators.h"
#include "support/expect_helpers.h"
#include "support/fp_traps.h"

namespace pba::particles {
namespace {

constexpr Real kMass = 0.01;  // [kg] every particle's (an emitter's pool)

/// A pool of 400 particles around two spheres above the ground, lifetimes from 0.5 s to 3 s.
Particles makePool(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  Particles p;
  for (int i = 0; i < 400; ++i) {
    p.add(Vec3(1.5 * u(rng), 1.0 + u(rng), 1.5 * u(rng)), 3.0 * Vec3(u(rng), u(rng), u(rng)), kMass, colors::kBlue,
          1.75 + 1.25 * u(rng));
  }
  return p;
}

struct Scene {
  std::vector<PlaneObstacle> planes{PlaneObstacle{}};
  std::vector<SphereObstacle> spheres{{Vec3(0.5, 0.4, 0.0), 0.5}, {Vec3(-0.7, 0.3, 0.6), 0.3}};
  FusedFountainDesc desc() const {
    FusedFountainDesc d;
    d.dragRate = 0.5;
    d.wind = Vec3(2.0, 0.0, -0.5);
    d.vortexCenter = Vec3(0.1, 0.0, -0.2);
    d.vortexStrength = 3.0;
    d.vortexCore = 0.5;
    d.planes = planes;
    d.spheres = spheres;
    d.material = ContactMaterial{0.4, 0.3, 0.2, 0.1};
    d.radius = 0.02;
    return d;
  }
};

/// The reference of the fused step: ageing and removal written here (keeping the order), then the generic
/// path — ParticleSystem forces (uniform wind), ode::velocityVerletStep and collideWithObstacles with the
/// step's gravity and h. Returns the contacts it resolved.
std::size_t referenceStep(ParticleSystem& ref, const ForceDesc& forces, const Obstacles& obstacles, Real radius, Real h,
                          ode::Workspace& w) {
  Particles next;
  for (std::size_t i = 0; i < ref.particles.size(); ++i) {
    if (ref.particles.age[i] + h >= ref.particles.lifetime[i]) continue;
    next.add(ref.particles.position[i], ref.particles.velocity[i], kMass, ref.particles.color[i],
             ref.particles.lifetime[i]);
    next.age.back() = ref.particles.age[i] + h;
  }
  ref.particles = next;
  ref.forces = forces;
  ref.syncMasses();
  ode::velocityVerletStep(ref, h, w);
  return collideWithObstacles(ref.particles, obstacles, radius, {forces.gravity, h}).contacts;
}

/// The fused kernel's forces as a ForceDesc for the generic accumulateFieldForces (c = (c/m)·m).
ForceDesc genericForces(const FusedFountainDesc& d) {
  ForceDesc forces;
  forces.gravity = d.gravity;
  forces.drag.linear = d.dragRate * kMass;
  forces.wind.base = d.wind;  // no gusts: uniform wind, as the fused kernel assumes
  forces.vortices.push_back({d.vortexCenter, kUp, d.vortexStrength, d.vortexCore});
  return forces;
}

TEST(FountainKernel, MatchesAgeingThenTheGenericForcesVelocityVerletAndObstacleContacts) {
  const Scene scene;
  const FusedFountainDesc d = scene.desc();
  const ForceDesc forces = genericForces(d);
  const Obstacles obstacles{scene.planes, scene.spheres, {}, d.material};
  Particles fused = makePool(4);
  ParticleSystem ref;
  ref.particles = fused;
  ode::Workspace w;
  const Real h = 1.0 / 120.0;
  std::size_t removed = 0, contacts = 0, referenceContacts = 0;
  for (int step = 0; step < 300; ++step) {
    const FountainStepStats stats = stepFountain(fused, d, h);
    removed += stats.expired;
    contacts += stats.contacts;
    referenceContacts += referenceStep(ref, forces, obstacles, d.radius, h, w);
    ASSERT_EQ(fused.size(), ref.particles.size()) << "step " << step;
  }
  EXPECT_GT(removed, 100u);   // lifetimes 0.5–3 s over 2.5 s: most expire
  EXPECT_GT(contacts, 500u);  // and the rest meet the ground and the spheres
  EXPECT_EQ(contacts, referenceContacts);
  ASSERT_GT(fused.size(), 20u);
  for (std::size_t i = 0; i < fused.size(); ++i) {
    // The same formulas grouped differently (e.g. (1 − hk/2) v + (h/2)(g + k w) against v + (h/2) a):
    // rounding of 1e-16 relative per step, amplified by the sphere contacts over 300 steps; 1e-12 still
    // catches any change of formula.
    EXPECT_VEC3_NEAR(fused.position[i], ref.particles.position[i], 1e-12);
    EXPECT_VEC3_NEAR(fused.velocity[i], ref.particles.velocity[i], 1e-12);
    EXPECT_EQ(fused.age[i], ref.particles.age[i]);
    EXPECT_EQ(fused.lifetime[i], ref.particles.lifetime[i]);
  }
}

TEST(FountainKernel, MeetsEveryObstacleHoweverMany) {
  // Forty small spheres in a ring and three planes (a floor and two walls): more than any fixed table of
  // the kernel would hold. Against the generic path, and nothing ends inside any obstacle.
  Scene scene;
  scene.planes = {PlaneObstacle{}, {Vec3(1.6, 0.0, 0.0), Vec3(-1.0, 0.0, 0.0)}, {Vec3(-1.6, 0.0, 0.0), Vec3(1.0, 0.0, 0.0)}};
  scene.spheres.clear();
  for (int k = 0; k < 40; ++k) {
    const Real a = 2.0 * kPi * k / 40.0;
    scene.spheres.push_back({Vec3(1.2 * std::cos(a), 0.6 + 0.3 * std::sin(3.0 * a), 1.2 * std::sin(a)), 0.15});
  }
  const FusedFountainDesc d = scene.desc();
  const Obstacles obstacles{scene.planes, scene.spheres, {}, d.material};
  Particles fused = makePool(5);
  for (Real& life : fused.lifetime) life = kImmortal;
  ParticleSystem ref;
  ref.particles = fused;
  ode::Workspace w;
  const Real h = 1.0 / 120.0;
  std::size_t contacts = 0;
  for (int step = 0; step < 240; ++step) {
    contacts += stepFountain(fused, d, h).contacts;
    referenceStep(ref, genericForces(d), obstacles, d.radius, h, w);
  }
  EXPECT_GT(contacts, 1000u);
  for (std::size_t i = 0; i < fused.size(); ++i) {
    EXPECT_VEC3_NEAR(fused.position[i], ref.particles.position[i], 1e-10);
    for (const SphereObstacle& sphere : scene.spheres) {
      EXPECT_GE(closestSurface(sphere, fused.position[i]).distance, d.radius - 1e-9) << "particle " << i;
    }
  }
}

TEST(FountainKernel, ItsEnergySumsAreTheKineticAndGravitationalEnergyPerUnitMass) {
  const Scene scene;
  FusedFountainDesc d = scene.desc();
  d.gravity = Vec3(0.3, -9.0, 0.2);  // not along an axis, so every component of x counts
  Particles p = makePool(7);
  FountainStepStats stats;
  for (int step = 0; step < 30; ++step) stats = stepFountain(p, d, 1.0 / 120.0);
  ForceDesc gravityOnly;
  gravityOnly.gravity = d.gravity;
  EXPECT_NEAR(stats.kineticPerMass * kMass, p.kineticEnergy(), 1e-12 * p.kineticEnergy());
  const Real potential = fieldPotentialEnergy(gravityOnly, p.position, p.inverseMass);
  EXPECT_NEAR(stats.potentialPerMass * kMass, potential, 1e-12 * std::abs(potential) + 1e-12);
  EXPECT_FALSE(stats.nonFinite);
}

TEST(FountainKernel, ReportsANanOrInfiniteParticleWhichDescribeNonFiniteThenNames) {
  pba::testing::FloatingPointTrapsOff trapsOff;  // NaN and ∞ on purpose
  const Scene scene;
  for (const bool inPosition : {true, false}) {
    SCOPED_TRACE(inPosition ? "NaN position" : "infinite velocity");
    Particles p = makePool(9);
    for (Real& life : p.lifetime) life = kImmortal;  // no removals: particle 123 keeps its index
    EXPECT_FALSE(stepFountain(p, scene.desc(), 1.0 / 120.0).nonFinite);
    if (inPosition) {
      p.position[123].x = std::numeric_limits<Real>::quiet_NaN();
    } else {
      p.velocity[123].z = -std::numeric_limits<Real>::infinity();
    }
    const FountainStepStats stats = stepFountain(p, scene.desc(), 1.0 / 120.0);
    EXPECT_TRUE(stats.nonFinite);
    const std::optional<std::string> message = describeNonFinite(p);
    ASSERT_TRUE(message.has_value());
    EXPECT_NE(message->find("particle 123 "), std::string::npos) << *message;
  }
}

TEST(Emitter, ColourOverLifeBlendsFromStartToEndAndSpawnOnlyAppends) {
  EmitterDesc desc;
  desc.startColor = Color{0.0f, 0.2f, 1.0f, 1.0f};
  desc.endColor = Color{1.0f, 0.6f, 0.0f, 0.5f};
  const Color start = colorOverLife(desc, 0.0, 2.0), middle = colorOverLife(desc, 1.0, 2.0),
              end = colorOverLife(desc, 5.0, 2.0);  // past the end: held at the end colour
  EXPECT_FLOAT_EQ(start.b, 1.0f);
  EXPECT_FLOAT_EQ(middle.r, 0.5f);
  EXPECT_FLOAT_EQ(middle.g, 0.4f);
  EXPECT_FLOAT_EQ(middle.a, 0.75f);
  EXPECT_FLOAT_EQ(end.r, 1.0f);
  EXPECT_FLOAT_EQ(end.a, 0.5f);
  // spawn(): rate·h particles per call, fractions carried over, nobody aged or removed.
  desc.rate = 160.0;
  Emitter emitter(desc, 5);
  Particles p;
  p.add(Vec3(0.0), Vec3(0.0), 1.0, colors::kRed, 0.001);
  p.age[0] = 1.0;  // long expired: update() would remove it, spawn() must not
  std::size_t spawned = 0;
  for (int i = 0; i < 100; ++i) spawned += emitter.spawn(p, 1.0 / 64.0);
  EXPECT_EQ(spawned, 250u);  // 100 × 160/64 = 100 × 2.5 (exact in binary)
  EXPECT_EQ(p.size(), 251u);
  EXPECT_EQ(p.age[0], 1.0);
}

}  // namespace
}  // namespace pba::particles
