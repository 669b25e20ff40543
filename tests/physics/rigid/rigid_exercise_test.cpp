// Exercise tests of RIGID-1 to RIGID-5. Each uses only reference code besides its own exercise:
//  RIGID-1 against Mirtich's polyhedral integrals of the box (physics/collision/mass.h) and against the
//          definition I_world ω = R (I_body (Rᵀ ω));
//  RIGID-2 against glm's rotation by the whole angle, B&W's derivative, and unit norm;
//  RIGID-3 by its defining properties: after the impulse the normal relative velocity is −e times the one
//          before, and linear and angular momentum (about the contact point) are unchanged;
//  RIGID-4 by Coulomb's law: sticking stops the tangential slip, sliding gets exactly μ j against it;
//  RIGID-5 by its meaning: an impulse of the effective mass applied to both bodies (velocity changes
//          written out here) changes their relative velocity along the row by exactly 1 m/s; and by
//          closed forms (a central hit, a sphere hit at right angles, two bodies that cannot move).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "physics/collision/mass.h"
#include "physics/rigid/exercises.h"
#include "support/expect_helpers.h"
#include "support/random_rotation.h"

namespace pba::rigid {
namespace {

using pba::test::randomRotation;

void expectMatNear(const Mat3& a, const Mat3& b, Real tol) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(a[c][r], b[c][r], tol) << "entry (" << r << ", " << c << ")";
}

TEST(RIGID_1_BoxInertia, MatchesMirtichsIntegralsForSeveralBoxes) {
  for (const Vec3& h : {Vec3(0.5), Vec3(0.1, 0.7, 0.3), Vec3(2.0, 0.05, 1.0)}) {
    const collision::MassProperties ref = collision::polyhedronMass(collision::boxHull(h), 300.0);
    expectMatNear(boxInertiaTensor(ref.mass, h, Quat(1, 0, 0, 0)), ref.inertia, 1e-12 * ref.mass);
  }
}

TEST(RIGID_1_WorldInertia, ActsLikeRotatingIntoTheBodyFrameAndBack) {
  std::mt19937_64 rng(21);
  std::normal_distribution<Real> n(0.0, 1.0);
  const Vec3 h(0.2, 0.5, 0.9);
  const collision::MassProperties ref = collision::polyhedronMass(collision::boxHull(h), 1000.0);
  const Mat3 body = ref.inertia;
  for (int trial = 0; trial < 50; ++trial) {
    const Quat q = randomRotation(rng);
    const Mat3 world = boxInertiaTensor(ref.mass, h, q);
    const Vec3 w(n(rng), n(rng), n(rng));
    // The definition: L = R I_body Rᵀ ω, computed by rotating the vector (seed 21).
    SCOPED_TRACE(trial);
    EXPECT_VEC3_NEAR(world * w, q * (body * (glm::conjugate(q) * w)), 1e-11 * ref.mass);
    // Symmetric, and the same trace (the principal moments do not change under rotation).
    EXPECT_NEAR(world[0][1], world[1][0], 1e-12);
    EXPECT_NEAR(world[0][0] + world[1][1] + world[2][2], body[0][0] + body[1][1] + body[2][2], 1e-9);
  }
}

// For a constant ω every step is the exact turn by h|ω| about ω/|ω|: N steps agree with glm's
// angleAxis of the whole angle (checked to 1e-12 whatever the step), and the norm stays 1.
TEST(RIGID_2_QuaternionIntegration, StepsComposeToTheExactRotationAboutTheWorldAxis) {
  const Vec3 omega(0.3, 2.0, -0.7);  // [rad/s]
  const Vec3 axis = glm::normalize(omega);
  const Quat q0 = glm::normalize(Quat(0.9, 0.1, -0.3, 0.2));
  const Real t = 1.0;
  auto distance = [](const Quat& a, const Quat& b) {
    return std::min(glm::length(Vec4(a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z)),
                    glm::length(Vec4(a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z)));
  };
  const Quat exact = glm::angleAxis(glm::length(omega) * t, axis) * q0;
  for (int steps : {1, 7, 100, 400}) {
    Quat q = q0;
    const Real h = t / steps;
    for (int i = 0; i < steps; ++i) {
      q = integrateOrientation(q, omega, h);
      ASSERT_NEAR(glm::length(q), 1.0, 1e-12);
    }
    EXPECT_LT(distance(q, exact), 1e-12) << steps << " steps";
  }
}

TEST(RIGID_2_QuaternionIntegration, NoTurnKeepsTheOrientationAndTinyTurnsStayFinite) {
  const Quat q0 = glm::normalize(Quat(0.9, 0.1, -0.3, 0.2));
  const Quat still = integrateOrientation(q0, Vec3(0.0), 0.01);
  EXPECT_EQ(still.w, q0.w);
  EXPECT_EQ(still.x, q0.x);
  // About 2e-14 rad over the step: an angle far below the axis cut-off, the result moves by that much.
  const Quat tiny = integrateOrientation(q0, Vec3(1e-12, -2e-12, 0.0), 0.01);
  EXPECT_TRUE(std::isfinite(tiny.w) && std::isfinite(tiny.x));
  EXPECT_NEAR(tiny.w, q0.w, 1e-13);
  EXPECT_NEAR(tiny.y, q0.y, 1e-13);
  // The first-order term is B&W's derivative ½ ω q: (q(h) − q)/h → ½ (0, ω) q.
  const Vec3 omega(0.4, -1.1, 0.6);
  const Real h = 1e-6;
  const Quat q1 = integrateOrientation(q0, omega, h);
  const Quat derivative = 0.5 * (Quat(0.0, omega.x, omega.y, omega.z) * q0);
  EXPECT_NEAR((q1.w - q0.w) / h, derivative.w, 1e-5);
  EXPECT_NEAR((q1.x - q0.x) / h, derivative.x, 1e-5);
  EXPECT_NEAR((q1.y - q0.y) / h, derivative.y, 1e-5);
  EXPECT_NEAR((q1.z - q0.z) / h, derivative.z, 1e-5);
}

TEST(RIGID_2_QuaternionIntegration, ASmallStepRotatesAboutTheWorldAxis) {
  const Quat q = integrateOrientation(Quat(1, 0, 0, 0), Vec3(0.0, 1.0, 0.0), 1e-3);
  // 1 mrad about +y: x turns toward −z.
  const Vec3 x = q * Vec3(1.0, 0.0, 0.0);
  EXPECT_NEAR(x.z, -1e-3, 1e-9);
  const Quat r = integrateOrientation(glm::angleAxis(0.5 * kPi, Vec3(1, 0, 0)), Vec3(0.0, 0.0, 1.0), 1e-3);
  // ω in world axes multiplies on the left: the body's y axis (now world +z) stays put.
  EXPECT_VEC3_NEAR(r * Vec3(0.0, 1.0, 0.0), Vec3(0.0, 0.0, 1.0), 1e-6);
}

struct TwoBodies {
  ImpulseBody a, b;
  Vec3 point, normal;
};

TwoBodies randomCollision(std::mt19937_64& rng) {
  std::normal_distribution<Real> n(0.0, 1.0);
  std::uniform_real_distribution<Real> u(0.5, 3.0);
  TwoBodies t;
  const Mat3 ia = collision::polyhedronMass(collision::boxHull(Vec3(u(rng), u(rng), u(rng)) * 0.2), 500.0).inertia;
  const Mat3 ib = collision::polyhedronMass(collision::boxHull(Vec3(u(rng), u(rng), u(rng)) * 0.2), 500.0).inertia;
  const Quat qa = randomRotation(rng), qb = randomRotation(rng);
  // World inverse inertia by rotating the vector (not RIGID-1): columns I⁻¹_world e_k = q I⁻¹ q⁻¹ e_k.
  auto worldInverse = [](const Mat3& body, const Quat& q) {
    Mat3 m(0.0);
    const Mat3 inv = glm::inverse(body);
    for (int k = 0; k < 3; ++k) {
      Vec3 e(0.0);
      e[k] = 1.0;
      m[k] = q * (inv * (glm::conjugate(q) * e));
    }
    return m;
  };
  t.a = {1.0 / u(rng), worldInverse(ia, qa), Vec3(0.0, 0.5, 0.0), Vec3(n(rng), n(rng) - 2.0, n(rng)),
         Vec3(n(rng), n(rng), n(rng))};
  t.b = {1.0 / u(rng), worldInverse(ib, qb), Vec3(0.3, -0.6, 0.2), Vec3(n(rng), n(rng) + 2.0, n(rng)),
         Vec3(n(rng), n(rng), n(rng))};
  t.point = Vec3(0.1 * n(rng), 0.0, 0.1 * n(rng));
  t.normal = glm::normalize(Vec3(0.2 * n(rng), 1.0, 0.2 * n(rng)));  // from B toward A
  return t;
}

void apply(ImpulseBody& body, const Vec3& point, const Vec3& impulse) {
  body.velocity += body.inverseMass * impulse;
  body.angularVelocity += body.inverseInertia * glm::cross(point - body.position, impulse);
}

TEST(RIGID_3_CollisionImpulse, LeavesMinusETimesTheApproachSpeedAndConservesMomentum) {
  std::mt19937_64 rng(31);
  int approaching = 0;
  for (int trial = 0; trial < 200; ++trial) {
    TwoBodies t = randomCollision(rng);
    const Real e = std::uniform_real_distribution<Real>(0.0, 1.0)(rng);
    const Real before = glm::dot(t.normal, t.a.velocityAt(t.point) - t.b.velocityAt(t.point));
    const Real j = collisionImpulse(t.a, t.b, t.point, t.normal, e);
    if (before >= 0.0) {
      EXPECT_EQ(j, 0.0) << "trial " << trial;
      continue;
    }
    ++approaching;
    EXPECT_GT(j, 0.0);
    const Vec3 p0 = t.a.velocity / t.a.inverseMass + t.b.velocity / t.b.inverseMass;
    apply(t.a, t.point, j * t.normal);
    apply(t.b, t.point, -j * t.normal);
    const Real after = glm::dot(t.normal, t.a.velocityAt(t.point) - t.b.velocityAt(t.point));
    EXPECT_NEAR(after, -e * before, 1e-9 * std::abs(before)) << "seed 31, trial " << trial;
    EXPECT_VEC3_NEAR(t.a.velocity / t.a.inverseMass + t.b.velocity / t.b.inverseMass, p0, 1e-9);
  }
  EXPECT_GT(approaching, 50);
}

TEST(RIGID_3_CollisionImpulse, AHeadOnHitOfEqualBallsSwapsTheirVelocitiesWhenElastic) {
  ImpulseBody a{1.0, Mat3(2.5), Vec3(0.0, 1.0, 0.0), Vec3(0.0, -3.0, 0.0), Vec3(0.0)};
  ImpulseBody b{1.0, Mat3(2.5), Vec3(0.0, -1.0, 0.0), Vec3(0.0), Vec3(0.0)};
  const Real j = collisionImpulse(a, b, Vec3(0.0), kUp, 1.0);
  EXPECT_NEAR(j, 3.0, 1e-12);  // m Δv = 1 kg × 3 m/s
}

TEST(RIGID_4_FrictionImpulse, StopsTheSlipWhenThatTakesLessThanMuJ) {
  std::mt19937_64 rng(41);
  for (int trial = 0; trial < 100; ++trial) {
    TwoBodies t = randomCollision(rng);
    const Vec3 vr = t.a.velocityAt(t.point) - t.b.velocityAt(t.point);
    const Vec3 slip = vr - glm::dot(vr, t.normal) * t.normal;
    const Vec3 f = frictionImpulse(t.a, t.b, t.point, t.normal, 1e6, 1.0);  // a huge normal impulse: sticks
    EXPECT_NEAR(glm::dot(f, t.normal), 0.0, 1e-9);
    apply(t.a, t.point, f);
    apply(t.b, t.point, -f);
    const Vec3 vr2 = t.a.velocityAt(t.point) - t.b.velocityAt(t.point);
    const Vec3 slip2 = vr2 - glm::dot(vr2, t.normal) * t.normal;
    // The impulse is along the slip only, so the slip may turn a little (the tangent K is not isotropic)
    // but its component along the original slip direction vanishes.
    EXPECT_NEAR(glm::dot(slip2, glm::normalize(slip)), 0.0, 1e-9) << "seed 41, trial " << trial;
  }
}

TEST(RIGID_4_FrictionImpulse, IsExactlyMuJAgainstTheSlipWhenSliding) {
  ImpulseBody a{1.0, Mat3(1.0), Vec3(0.0, 0.5, 0.0), Vec3(4.0, -1.0, 0.0), Vec3(0.0)};
  const ImpulseBody ground{};
  const Vec3 f = frictionImpulse(a, ground, Vec3(0.0), kUp, 0.5, 0.4);
  EXPECT_VEC3_NEAR(f, Vec3(-0.2, 0.0, 0.0), 1e-12);  // μ j = 0.4 × 0.5 against +x
  EXPECT_VEC3_NEAR(frictionImpulse(ImpulseBody{1.0, Mat3(1.0), Vec3(0.0, 0.5, 0.0), Vec3(0.0, -1.0, 0.0), Vec3(0.0)},
                                   ground, Vec3(0.0), kUp, 0.5, 0.4),
                   Vec3(0.0), 0.0);  // no slip: no friction
}

// RIGID-5: the impulse m_eff d (+ on B, − on A, the contact solver's convention) changes the relative
// velocity of the two points along d by exactly 1 m/s. The velocity changes are applied as impulses
// (apply above), not through the row's K. Random boxes, arms and directions; 1e-12 relative.
TEST(RIGID_5_ContactEffectiveMass, ItsImpulseChangesTheRelativeVelocityAlongTheRowByOne) {
  std::mt19937_64 rng(55);
  std::normal_distribution<Real> n(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    TwoBodies t = randomCollision(rng);
    if (trial % 4 == 3) t.b.inverseMass = 0.0, t.b.inverseInertia = Mat3(0.0);  // against a static body
    const Vec3 d = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
    const Vec3 ra = t.point - t.a.position, rb = t.point - t.b.position;
    const Real m =
        contactEffectiveMass(t.a.inverseMass, t.a.inverseInertia, ra, t.b.inverseMass, t.b.inverseInertia, rb, d);
    ASSERT_GT(m, 0.0);
    auto along = [&](const ImpulseBody& a, const ImpulseBody& b) {
      return glm::dot(d, b.velocityAt(t.point) - a.velocityAt(t.point));
    };
    const Real before = along(t.a, t.b);
    ImpulseBody a = t.a, b = t.b;
    apply(a, t.point, -m * d);
    apply(b, t.point, m * d);
    EXPECT_NEAR(along(a, b) - before, 1.0, 1e-12 * (1.0 + std::abs(before)));
    // The row is the same seen from the other side, or along −d.
    EXPECT_NEAR(
        contactEffectiveMass(t.b.inverseMass, t.b.inverseInertia, rb, t.a.inverseMass, t.a.inverseInertia, ra, -d), m,
        1e-12 * m);
  }
}

TEST(RIGID_5_ContactEffectiveMass, MatchesClosedFormsAndIsZeroWhenNothingCanMove) {
  const Vec3 up(0.0, 1.0, 0.0);
  // A hit on the line through both centres: no rotation, the reduced mass m_A m_B / (m_A + m_B).
  EXPECT_NEAR(
      contactEffectiveMass(1.0 / 2.0, Mat3(3.0), Vec3(0.0, -0.5, 0.0), 1.0 / 6.0, Mat3(5.0), Vec3(0.0, 0.7, 0.0), up),
      2.0 * 6.0 / 8.0, 1e-14);
  // A solid ball (m = 2 kg, radius 0.5 m: I = 2/5 m R² = 0.2 kg·m²) hit on the ground at its rim, with the
  // row along the tangent: the arm is perpendicular to it, 1/m_eff = 1/m + R²/I = 0.5 + 1.25.
  const Mat3 ballInverse(1.0 / 0.2);
  EXPECT_NEAR(contactEffectiveMass(0.5, ballInverse, Vec3(0.0, -0.5, 0.0), 0.0, Mat3(0.0), Vec3(1.0, 2.0, 3.0),
                                   Vec3(1.0, 0.0, 0.0)),
              1.0 / 1.75, 1e-14);
  // Along the normal at the same point the arm is parallel to the row: only the translation, m = 2 kg.
  EXPECT_NEAR(contactEffectiveMass(0.5, ballInverse, Vec3(0.0, -0.5, 0.0), 0.0, Mat3(0.0), Vec3(0.0), up), 2.0, 1e-14);
  // Two sides that cannot move: the row applies nothing.
  EXPECT_EQ(contactEffectiveMass(0.0, Mat3(0.0), Vec3(1.0, 0.0, 0.0), 0.0, Mat3(0.0), Vec3(0.0, 1.0, 0.0), up), 0.0);
}

}  // namespace
}  // namespace pba::rigid
