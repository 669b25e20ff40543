// Exercise tests of PART-5 (contact velocity with restitution and Coulomb friction). Closed forms:
// restitution reverses e·v_n; kinetic friction decelerates a sliding particle by μ_k g; a particle on a
// slope of angle θ sticks when tan θ ≤ μ_s and otherwise accelerates at g (sin θ − μ_k cos θ).
#include <algorithm>
#include <cmath>
#include <vector>

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

/// One particle on a plane through the origin with normal n: velocity Verlet (not an exercise) + the
/// obstacle contacts. A correct PART-5 never leaves work for the contact model's safety net; `held` counts
/// what it did, and the tests require 0.
struct Slide {
  ParticleSystem system;
  Obstacles obstacles;
  ode::Integrator integrator{ode::IntegratorKind::VelocityVerlet};
  std::size_t held = 0;
  Slide(const Vec3& normal, const Vec3& velocity, const ContactMaterial& m) {
    obstacles.planes.push_back({Vec3(0.0), normal});
    obstacles.material = m;
    system.particles.add(Vec3(0.0), velocity, 1.0);
    system.syncMasses();
  }
  void step(Real h) {
    integrator.step(system, h);
    held += collideWithObstacles(system.particles, obstacles, 0.0).heldBySafetyNet;
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
  EXPECT_EQ(s.held, 0u);
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
    EXPECT_EQ(s.held, 0u);
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
  // Energy: rebound speed e·√(2 g h0) ⇒ apex e² h0. Velocity Verlet is exact in flight; the impact is
  // taken at the end-of-step speed (no ContactStep here), up to g h faster: 1 mm at most.
  EXPECT_NEAR(apex, m.restitution * m.restitution * h0, 1e-3);
  EXPECT_EQ(s.held, 0u);
}

// Resting contact (Lobb notes §2 "Resting contact"): balls dropped at restitution 0.7 and 0.9 first
// bounce (the rebound apex is e² of the drop, within the projection's error), then stop (speed < 1e-3 m/s)
// and never sink more than 1 mm, under each integrator that is not an exercise (the exercises' own tests
// must not depend on PART-5, nor PART-5's on them: midpoint and adaptive are PART-7 and PART-8). Velocity
// Verlet, exact under gravity as midpoint and adaptive are, micro-bounced forever at ~0.1 m/s before the
// contact model used the approach speed at the contact time; implicit Euler is first order and dissipative.
TEST(PART_5_RestingContact, BallsBounceThenComeToRestWithoutSinkingUnderTheLibrarysIntegrators) {
  const Real radius = 0.05, h = 1.0 / 120.0, seconds = 20.0;
  for (const Real e : {0.7, 0.9}) {
    for (const ode::IntegratorKind kind : {ode::IntegratorKind::VelocityVerlet, ode::IntegratorKind::ImplicitEuler}) {
      SCOPED_TRACE(::testing::Message() << ode::integratorName(kind) << ", restitution " << e);
      ParticleSystem sys;
      Obstacles obstacles;
      obstacles.planes.push_back({});
      obstacles.material.restitution = e;
      std::vector<Real> drop;
      for (int i = 0; i < 10; ++i) {
        drop.push_back(0.5 + 0.2 * i);
        sys.particles.add(Vec3(0.3 * i, radius + drop.back(), 0.0), Vec3(0.0), 0.1);
      }
      sys.syncMasses();
      ode::Integrator integrator(kind);
      const ContactStep contactStep{sys.forces.gravity, h};
      // Height while rising after the first impact; the first apex once the particle falls again.
      std::vector<Real> rising(drop.size(), -1.0), firstApex(drop.size(), -1.0);
      Real lowest = 1.0;
      std::size_t held = 0;
      for (int step = 0; step < static_cast<int>(seconds / h); ++step) {
        integrator.step(sys, h);
        held += collideWithObstacles(sys.particles, obstacles, radius, contactStep).heldBySafetyNet;
        for (std::size_t i = 0; i < drop.size(); ++i) {
          const Vec3& x = sys.particles.position[i];
          lowest = std::min(lowest, x.y - radius);
          if (firstApex[i] >= 0.0) continue;
          if (sys.particles.velocity[i].y > 0.0)
            rising[i] = std::max(rising[i], x.y - radius);
          else if (rising[i] >= 0.0)
            firstApex[i] = rising[i];
        }
      }
      EXPECT_GT(lowest, -1e-3);
      EXPECT_EQ(held, 0u);
      // First rebound: e² of the drop. Exact under gravity for the 2nd-order and higher methods (0.2 %:
      // the apex is sampled at the steps); the 1st-order ones carry an O(g h T) flight error (5 %).
      const Real apexTolerance = ode::integratorOrder(kind) == 1 ? 0.05 : 0.002;
      for (std::size_t i = 0; i < drop.size(); ++i) {
        EXPECT_NEAR(firstApex[i], e * e * drop[i], apexTolerance * drop[i]) << "particle " << i;
        EXPECT_LT(glm::length(sys.particles.velocity[i]), 1e-3) << "particle " << i;
        EXPECT_NEAR(sys.particles.position[i].y, radius, 1e-3) << "particle " << i;
      }
    }
  }
}

}  // namespace
}  // namespace pba::particles
