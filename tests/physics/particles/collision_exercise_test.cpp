// Exercise tests of PART-5 (contact velocity with restitution and Coulomb friction). Closed forms:
// restitution reverses e·v_n; kinetic friction decelerates a sliding particle by μ_k g; a particle on a
// slope of angle θ sticks when tan θ ≤ μ_s and otherwise accelerates at g (sin θ − μ_k cos θ).
#include <cmath>

#include <gtest/gtest.h>

#include "physics/ode/integrators.h"
#include "physics/particles/collision.h"
#include "physics/particles/particle_system.h"
#include "support/expect_helpers.h"

namespace pba::particles {
namespace {

TEST(PART_5_PlaneContact, ReversesTheNormalVelocityScaledByRestitution) {
  ContactMaterial m;
  m.restitution = 0.6;
  m.staticFriction = m.kineticFriction = 0.0;
  const Vec3 v = contactVelocity(Vec3(1.0, -3.0, 0.5), kUp, m);
  EXPECT_VEC3_NEAR(v, Vec3(1.0, 1.8, 0.5), 1e-15);
}

TEST(PART_5_PlaneContact, SlowImpactsRestWithoutBouncing) {
  ContactMaterial m;
  m.restitution = 0.9;
  const Vec3 v = contactVelocity(Vec3(0.0, -0.5 * m.restingSpeed, 0.0), kUp, m);
  EXPECT_VEC3_NEAR(v, Vec3(0.0), 0.0);
}

TEST(PART_5_PlaneContact, FrictionIsAnImpulseBoundedByMuTimesTheNormalImpulse) {
  ContactMaterial m;
  m.restitution = 0.5;
  m.staticFriction = 0.5;
  m.kineticFriction = 0.3;
  // Δv_n = (1 + e)·2 = 3 m/s. Sliding: |v_t| = 4 > μ_s Δv_n = 1.5 ⇒ loses μ_k Δv_n = 0.9 m/s.
  EXPECT_VEC3_NEAR(contactVelocity(Vec3(4.0, -2.0, 0.0), kUp, m), Vec3(3.1, 1.0, 0.0), 1e-14);
  // Sticking: |v_t| = 1 ≤ 1.5 ⇒ v_t' = 0.
  EXPECT_VEC3_NEAR(contactVelocity(Vec3(0.6, -2.0, 0.8), kUp, m), Vec3(0.0, 1.0, 0.0), 1e-14);
  // Leaving particles are untouched.
  EXPECT_VEC3_NEAR(contactVelocity(Vec3(4.0, 2.0, 0.0), kUp, m), Vec3(4.0, 2.0, 0.0), 0.0);
}

/// One particle on a plane through the origin with normal n, symplectic Euler + obstacle contacts.
struct Slide {
  ParticleSystem system;
  Obstacles obstacles;
  ode::Integrator integrator{ode::IntegratorKind::SymplecticEuler};
  Slide(const Vec3& normal, const Vec3& velocity, const ContactMaterial& m) {
    obstacles.planes.push_back({Vec3(0.0), normal});
    obstacles.material = m;
    system.particles.add(Vec3(0.0), velocity, 1.0);
    system.syncMasses();
  }
  void step(Real h) {
    integrator.step(system, h);
    collideWithObstacles(system.particles, obstacles, 0.0);
  }
};

TEST(PART_5_PlaneContact, KineticFrictionStopsASlidingParticleAfterVOverMuG) {
  ContactMaterial m;
  m.staticFriction = 0.5;
  m.kineticFriction = 0.4;
  const Real v0 = 3.0, h = 1e-3, g = kStandardGravity;
  Slide s(kUp, Vec3(v0, 0.0, 0.0), m);
  int steps = 0;
  while (s.system.particles.velocity[0].x > 0.0 && steps < 100000) {
    s.step(h);
    ++steps;
  }
  const Real stopTime = v0 / (m.kineticFriction * g);
  EXPECT_NEAR(steps * h, stopTime, 2 * h);
  // Distance v0²/(2 μ_k g), up to O(v0 h) from the discrete sum.
  EXPECT_NEAR(s.system.particles.position[0].x, v0 * v0 / (2.0 * m.kineticFriction * g), v0 * h);
}

TEST(PART_5_PlaneContact, StaticFrictionHoldsOnAGentleSlopeAndKineticFrictionActsOnASteepOne) {
  ContactMaterial m;
  m.staticFriction = 0.5;
  m.kineticFriction = 0.3;
  const Real g = kStandardGravity, h = 1e-3;
  for (Real angle : {degToRad(20.0), degToRad(40.0)}) {  // tan 20° = 0.36 < 0.5 < tan 40° = 0.84
    const Vec3 normal{-std::sin(angle), std::cos(angle), 0.0};
    Slide s(normal, Vec3(0.0), m);
    const int steps = 1000;
    for (int i = 0; i < steps; ++i) s.step(h);
    const Real speed = glm::length(s.system.particles.velocity[0]);
    if (std::tan(angle) <= m.staticFriction) {
      EXPECT_LT(speed, 1e-12) << "angle " << radToDeg(angle);
    } else {
      EXPECT_NEAR(speed, g * (std::sin(angle) - m.kineticFriction * std::cos(angle)) * steps * h, 1e-3);
    }
  }
}

TEST(PART_5_PlaneContact, ADroppedParticleReboundsToRestitutionSquaredOfItsHeight) {
  ContactMaterial m;
  m.restitution = 0.7;
  const Real h0 = 2.0, h = 1e-4;
  Slide s(kUp, Vec3(0.0), m);
  s.system.particles.position[0] = Vec3(0.0, h0, 0.0);
  bool bounced = false;
  Real apex = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const Real vy = s.system.particles.velocity[0].y;
    s.step(h);
    bounced = bounced || (vy < 0.0 && s.system.particles.velocity[0].y > 0.0);
    if (bounced) apex = std::max(apex, s.system.particles.position[0].y);
    if (bounced && s.system.particles.velocity[0].y < 0.0) break;
  }
  ASSERT_TRUE(bounced);
  // Energy: rebound speed e·√(2 g h0) ⇒ apex e² h0; O(g h) discretisation error ⇒ 2 mm.
  EXPECT_NEAR(apex, m.restitution * m.restitution * h0, 2e-3);
}

}  // namespace
}  // namespace pba::particles
