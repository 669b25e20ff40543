// Exercise tests of the hello lab's spring ball: HELLO-3 (its forces), HELLO-4 (one frame in stable substeps)
// and HELLO-5 (its energy). Each suite calls its own exercise only; expected values come from potentials
// differentiated numerically, closed forms of the discrete recurrences (workbook chapter 0, §6.5–6.6) and
// invariants. springEquilibrium() is library code (the closed form k (l − L) = m g), not an exercise.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "physics/hello/ball.h"
#include "support/expect_helpers.h"

namespace pba::hello {
namespace {

// ----- HELLO-3: the forces on the spring ball -----

TEST(HELLO_3_SpringBallForce, IsMinusTheGradientOfTheSpringAndGravityPotentialsMinusTheDrag) {
  // U(x) = k (|x − a| − L)²/2 + m g y; without spring damping F = −∇U − c v. Central differences of U,
  // step 1e-6 m: truncation O(k step²), rounding O(1e-16 U/step) ≈ 1e-9 N.
  SpringDesc desc;
  desc.damping = 0.0;
  const BallState s{{0.3, 1.2, -0.4}, {0.5, -0.2, 0.1}};
  auto potential = [&](const Vec3& x) {
    const Real e = glm::length(x - desc.anchor) - desc.restLength;
    return 0.5 * desc.stiffness * e * e + desc.mass * desc.gravity * x.y;
  };
  const Real step = 1e-6;
  Vec3 gradient(0.0);
  for (int i = 0; i < 3; ++i) {
    Vec3 dx(0.0);
    dx[i] = step;
    gradient[i] = (potential(s.position + dx) - potential(s.position - dx)) / (2 * step);
  }
  EXPECT_VEC3_NEAR(springBallForce(desc, s), -gradient - desc.drag * s.velocity, 1e-7);
  // A compressed spring (closer to the anchor than L) pushes the ball away from it.
  const BallState compressed{desc.anchor - Vec3(0.0, 0.5 * desc.restLength, 0.0), Vec3(0.0)};
  desc.gravity = 0.0;
  EXPECT_LT(springBallForce(desc, compressed).y, 0.0);
}

TEST(HELLO_3_SpringBallForce, SpringDampingResistsOnlyTheRateOfChangeOfTheLength) {
  // Without air drag and gravity, the damping's share is F(c_s) − F(0). A velocity across the spring does
  // not change its length: no share. A velocity u along the spring's direction changes the length at the
  // rate u: the share is c_s u against that direction.
  SpringDesc desc;
  desc.drag = 0.0;
  desc.gravity = 0.0;
  desc.damping = 2.5;
  SpringDesc undamped = desc;
  undamped.damping = 0.0;
  const Vec3 direction = glm::normalize(Vec3(0.6, -1.5, 0.3));  // from the anchor to the ball
  const Vec3 position = desc.anchor + 1.9 * direction;
  const Vec3 across = glm::normalize(glm::cross(direction, Vec3(0.0, 0.0, 1.0)));
  const BallState sideways{position, 3.0 * across};
  EXPECT_VEC3_NEAR(springBallForce(desc, sideways), springBallForce(undamped, sideways), 1e-12);
  const Real u = -1.7;  // shortening
  const BallState along{position, u * direction};
  EXPECT_VEC3_NEAR(springBallForce(desc, along) - springBallForce(undamped, along), -desc.damping * u * direction,
                   1e-12);
}

TEST(HELLO_3_SpringBallForce, VanishesAtTheEquilibriumAndStaysFiniteOnTheAnchor) {
  const SpringDesc desc;
  EXPECT_VEC3_NEAR(springBallForce(desc, springEquilibrium(desc)), Vec3(0.0), 1e-12);
  // On the anchor the spring has no direction: only the weight and the drag are left.
  const BallState onAnchor{desc.anchor, Vec3(0.2, 0.0, 0.0)};
  EXPECT_VEC3_NEAR(springBallForce(desc, onAnchor),
                   Vec3(0.0, -desc.mass * desc.gravity, 0.0) - desc.drag * onAnchor.velocity, 1e-12);
}

// ----- HELLO-4: one frame of the spring ball in stable substeps -----

// Closed form of the symplectic Euler recurrence under a constant acceleration a: v_n = v0 + n h a and
// x_n = x0 + h (v_1 + … + v_n) = x0 + n h v0 + h² a n(n+1)/2.
BallState symplecticClosedForm(const BallState& s0, const Vec3& a, Real h, int n) {
  return {s0.position + Real(n) * h * s0.velocity + h * h * a * (Real(n) * Real(n + 1) / 2.0),
          s0.velocity + Real(n) * h * a};
}

/// A spring whose rates the test chooses: stiffness k and mass m give ω = √(k/m), damping + drag over m
/// the damping rate. The force the frame integrates is the test's own, so HELLO-3 is not involved.
SpringDesc springWithRates(Real stiffness, Real mass, Real damping, Real drag) {
  SpringDesc desc;
  desc.stiffness = stiffness;
  desc.mass = mass;
  desc.damping = damping;
  desc.drag = drag;
  return desc;
}

/// Runs one frame under a constant force and returns how many times the force was asked for.
int substepsUnderConstantForce(const SpringDesc& desc, Real dt, const Vec3& force, BallState* end = nullptr) {
  const BallState s0{{1.0, 2.0, 3.0}, {0.5, -1.0, 2.0}};
  int calls = 0;
  const BallState s = stepSpringBall(desc, s0, dt, [&](const BallState&) {
    ++calls;
    return force;
  });
  if (end) *end = s;
  return calls;
}

TEST(HELLO_4_SpringBallSubsteps, AConstantForceFrameIsTheSummedRecurrenceOfTheFewestStableSubsteps) {
  // ω = √(60/2) = 5.477 rad/s, dt = 0.3 s: ω dt / 0.05 = 32.86, so 33 substeps (32 would give
  // ω h = 0.0513 > 0.05). Under a constant force the end of the frame is the closed form with n = 33.
  const SpringDesc desc = springWithRates(60.0, 2.0, 0.0, 0.0);
  const Vec3 force{1.0, -19.6, 0.5};
  const BallState s0{{1.0, 2.0, 3.0}, {0.5, -1.0, 2.0}};
  std::vector<BallState> seen;
  const BallState s = stepSpringBall(desc, s0, 0.3, [&](const BallState& b) {
    seen.push_back(b);
    return force;
  });
  ASSERT_EQ(seen.size(), 33u);
  EXPECT_EQ(seen.front().position, s0.position);  // the first force is taken at the frame's start
  EXPECT_EQ(seen.front().velocity, s0.velocity);
  const BallState expected = symplecticClosedForm(s0, force / desc.mass, 0.3 / 33.0, 33);
  // 33 substeps of O(10) values: rounding well under 1e-12.
  EXPECT_VEC3_NEAR(s.position, expected.position, 1e-12);
  EXPECT_VEC3_NEAR(s.velocity, expected.velocity, 1e-12);
  // Each later force sees the state the recurrence reached after the substeps before it.
  for (int n = 1; n < 33; ++n) {
    SCOPED_TRACE("substep " + std::to_string(n));
    const BallState mid = symplecticClosedForm(s0, force / desc.mass, 0.3 / 33.0, n);
    EXPECT_VEC3_NEAR(seen[static_cast<std::size_t>(n)].position, mid.position, 1e-12);
  }
}

TEST(HELLO_4_SpringBallSubsteps, DampingAndDragLimitTheSubstepWhenTheyAreTheFasterRate) {
  // ω = 1 rad/s but (c_s + c)/m = (3.3 + 1)/1 = 4.3 /s: 4.3 × 0.26 / 0.05 = 22.36, so 23 substeps.
  EXPECT_EQ(substepsUnderConstantForce(springWithRates(1.0, 1.0, 3.3, 1.0), 0.26, Vec3(0.0, -9.8, 0.0)), 23);
  // The same spring without damping or drag: ω dt / 0.05 = 0.26 / 0.05 = 5.2, so 6 substeps.
  EXPECT_EQ(substepsUnderConstantForce(springWithRates(1.0, 1.0, 0.0, 0.0), 0.26, Vec3(0.0, -9.8, 0.0)), 6);
}

TEST(HELLO_4_SpringBallSubsteps, TheSceneDefaultsNeedOneSubstepAndAnAbsurdFrameIsCapped) {
  // The scene's spring (ω = √40 = 6.32 rad/s, (0.6 + 0.05)/1 /s) at dt = 1/240 s: ω dt = 0.026, one
  // substep, which is one symplectic Euler step of the whole frame.
  BallState end;
  const Vec3 force{0.3, -9.0, 0.1};
  ASSERT_EQ(substepsUnderConstantForce(SpringDesc{}, 1.0 / 240.0, force, &end), 1);
  const BallState expected = symplecticClosedForm({{1.0, 2.0, 3.0}, {0.5, -1.0, 2.0}}, force, 1.0 / 240.0, 1);
  EXPECT_VEC3_NEAR(end.position, expected.position, 1e-14);
  EXPECT_VEC3_NEAR(end.velocity, expected.velocity, 1e-14);
  // ω = √(10⁶/10⁻³) ≈ 31623 rad/s over 1 s would want 158114 substeps: capped.
  EXPECT_EQ(substepsUnderConstantForce(springWithRates(1e6, 1e-3, 0.0, 0.0), 1.0, Vec3(0.0)), kMaxSpringSubsteps);
}

TEST(HELLO_4_SpringBallSubsteps, AStiffSpringKeepsItsModifiedEnergyWhereOneStepWouldExplode) {
  // Workbook §6.6: on ẍ = −ω² x symplectic Euler with step h conserves ω²x² + v² − h ω² x v exactly, and
  // is unstable for ω h > 2. Here ω = 10 rad/s and dt = 0.3125 s (ω dt = 3.125: one step per frame would
  // grow without bound); 3.125 / 0.05 = 62.5 gives 63 substeps of h = dt/63, on every axis. The force is
  // the test's own linear spring about the origin (no gravity, no damping).
  const Real k = 100.0, m = 1.0, omega = 10.0, dt = 0.3125, h = dt / 63.0;
  const SpringDesc desc = springWithRates(k, m, 0.0, 0.0);
  auto modified = [&](const BallState& s) {
    Real sum = 0.0;
    for (int i = 0; i < 3; ++i) {
      const Real x = s.position[i], v = s.velocity[i];
      sum += omega * omega * x * x + v * v - h * omega * omega * x * v;
    }
    return sum;
  };
  BallState s{{0.7, -0.2, 0.1}, {-0.4, 0.3, 0.0}};
  const Real invariant = modified(s);
  for (int frame = 0; frame < 200; ++frame) {
    s = stepSpringBall(desc, s, dt, [&](const BallState& b) { return -k * b.position; });
    // Rounding only: a few ulps of O(50) per substep, summed over 12600 substeps.
    ASSERT_NEAR(modified(s), invariant, 1e-9) << "frame " << frame;
  }
  EXPECT_NE(s.position.x, 0.7);  // the ball moved
}

// ----- HELLO-5: the spring ball's energy -----

TEST(HELLO_5_SpringEnergy, AtTheEquilibriumIsTheClosedForm) {
  // At rest at l = L + m g / k below the anchor: ½ k (m g / k)² − m g l.
  SpringDesc desc;
  desc.anchor = Vec3(0.3, 2.0, -0.1);
  const Real stretch = desc.mass * desc.gravity / desc.stiffness;
  const Real expected =
      0.5 * desc.stiffness * stretch * stretch - desc.mass * desc.gravity * (desc.restLength + stretch);
  EXPECT_NEAR(springEnergy(desc, springEquilibrium(desc)), expected, 1e-12);
}

TEST(HELLO_5_SpringEnergy, GrowsByTheKineticEnergyAndHasTheForceAsMinusItsGradient) {
  SpringDesc desc;
  const BallState still{{0.4, 1.1, 0.2}, Vec3(0.0)};
  const Vec3 v{0.5, -1.5, 2.0};
  EXPECT_NEAR(springEnergy(desc, {still.position, v}) - springEnergy(desc, still), 0.5 * desc.mass * 6.5, 1e-12);
  // Straight below the anchor at a distance l the spring pulls up with k (l − L) and gravity down with
  // m g, so dE/dy = m g − k (l − L) (a stretched spring's energy falls as the ball rises).
  const Real l = 2.2;
  const Vec3 x = desc.anchor - Vec3(0.0, l, 0.0);
  const Real step = 1e-6;
  const Real dEdy = (springEnergy(desc, {x + Vec3(0.0, step, 0.0), Vec3(0.0)}) -
                     springEnergy(desc, {x - Vec3(0.0, step, 0.0), Vec3(0.0)})) /
                    (2.0 * step);
  EXPECT_NEAR(dEdy, desc.mass * desc.gravity - desc.stiffness * (l - desc.restLength), 1e-6);
  // Stretch and compression by the same amount store the same elastic energy (gravity off).
  desc.gravity = 0.0;
  const Real e = 0.3;
  EXPECT_NEAR(springEnergy(desc, {desc.anchor - Vec3(0.0, desc.restLength + e, 0.0), Vec3(0.0)}),
              springEnergy(desc, {desc.anchor + Vec3(desc.restLength - e, 0.0, 0.0), Vec3(0.0)}), 1e-12);
}

TEST(HELLO_5_SpringEnergy, IsConstantAlongTheExactUndampedVerticalOscillation) {
  // Without damping and drag the ball released A below the equilibrium moves as y(t) = y_eq − A cos ω t,
  // ω = √(k/m), for as long as the spring stays stretched: every sample must give the same energy.
  SpringDesc desc;
  desc.damping = 0.0;
  desc.drag = 0.0;
  const Real A = 0.2, omega = std::sqrt(desc.stiffness / desc.mass);
  const Vec3 rest = springEquilibrium(desc).position;
  auto at = [&](Real t) {
    return BallState{rest - Vec3(0.0, A * std::cos(omega * t), 0.0), Vec3(0.0, A * omega * std::sin(omega * t), 0.0)};
  };
  const Real e0 = springEnergy(desc, at(0.0));
  EXPECT_LT(e0, 0.0);  // below the anchor the gravitational part, −m g × about 2 m, outweighs the rest
  for (int i = 1; i <= 40; ++i) EXPECT_NEAR(springEnergy(desc, at(0.037 * i)), e0, 1e-12) << "sample " << i;
}

}  // namespace
}  // namespace pba::hello
