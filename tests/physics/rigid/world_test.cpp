// World-level checks: continuous collision (the bullet never tunnels with it and does without), bad
// input rejected with messages that name the field, non-finite state named, determinism, and the same
// simulation whichever broad phase finds the pairs.
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "physics/core/byte_hash.h"
#include "physics/rigid/builders.h"
#include "support/expect_helpers.h"
#include "support/fp_traps.h"

namespace pba::rigid {
namespace {

// Fires `shots` 1 cm spheres at 100 m/s at a 1 cm static wall; returns how many ended behind it.
int tunnelled(bool continuous, int shots) {
  World w;
  BodyDesc wall;
  wall.type = BodyType::Static;
  wall.shape = collision::makeBox(Vec3(0.005, 1.0, 1.0)).value();
  wall.position = Vec3(3.0, 1.0, 0.0);
  w.addBody(wall).value();
  std::vector<int> bullets;
  for (int i = 0; i < shots; ++i) {
    BodyDesc b;
    b.shape = collision::makeSphere(0.005).value();
    // Spread the starting points so the wall is met at every phase of a step.
    b.position = Vec3(-0.0167 * i, 1.0 + 0.01 * (i % 7), 0.02 * (i % 5) - 0.04);
    b.linearVelocity = Vec3(100.0, 0.0, 0.0);
    b.gravityScale = 0.0;
    b.bullet = continuous;
    b.continuous = continuous;
    b.density = 7800.0;
    bullets.push_back(w.addBody(b).value());
  }
  for (int i = 0; i < 90; ++i) w.step(1.0 / 60.0);
  int behind = 0;
  for (int b : bullets) behind += w.body(b).position.x > 3.005;
  return behind;
}

TEST(ContinuousCollision, AFastSphereNeverPassesAThinWallWithItAndDoesWithout) {
  EXPECT_EQ(tunnelled(true, 20), 0);
  EXPECT_GT(tunnelled(false, 20), 15);
}

TEST(ContinuousCollision, AFastBoxHitsTheGroundPlaneInsteadOfSinkingIn) {
  World w;
  addGround(w);
  const int box = addBox(w, Vec3(0.05), Vec3(0.0, 3.0, 0.0), Quat(1, 0, 0, 0), 500.0, 0.5, colors::kRed);
  w.setVelocity(box, Vec3(0.0, -40.0, 0.0), Vec3(0.0));
  Real lowest = 1e9;
  for (int i = 0; i < 60; ++i) {
    w.step(1.0 / 60.0);
    lowest = std::min(lowest, w.body(box).position.y);
  }
  EXPECT_GT(lowest, 0.05 - 0.01);  // never more than 1 cm into the ground (0.67 m per step at 40 m/s)
}

// A thin box (the head bone of the ragdoll of humanoid.bvh: 18 × 5 × 5 cm, 1.3 kg) dropped flat from 1.46 m with the
// ragdoll's settings (8 cm speculative margin): it lands fast enough for continuous collision (more than half
// its 5 cm thickness per step) and spinning. It used to freeze for good at a time of impact of 0 with its
// landing velocity (the kinetic energy stayed at ~3 J); it must come to rest on the ground.
TEST(ContinuousCollision, AThinBoxLandingFastComesToRestInsteadOfFreezingAtTheTimeOfImpact) {
  WorldSettings s;  // the ragdoll's (physics/ragdoll/constraint_ragdoll.cpp, ragdollWorldSettings)
  s.speculativeDistance = 0.08;
  s.contactHertz = 60.0;
  s.jointHertz = 60.0;
  World w(s);
  addGround(w, 0.5);
  const Vec3 half(0.091071428571428581, 0.025, 0.025);
  const Real density = 1.2730910135465596 / (8.0 * half.x * half.y * half.z);  // [kg/m³]
  const int box = addBox(w, half, Vec3(0.0, 1.4571779225174808, 0.0), Quat(1, 0, 0, 0), density, 0.5, colors::kRed);
  Real energy = 0.0;
  for (int i = 0; i < 240; ++i) {
    w.step(1.0 / 60.0);
    energy = kineticEnergy(w.body(box));
  }
  EXPECT_LT(energy, 0.01);  // [J] settled 3.5 s after landing with 14 J (the frozen box kept about 3 J)
  EXPECT_NEAR(w.body(box).position.y, half.y, 0.01);  // lying on a 5 cm face
}

TEST(BadInput, BodiesWithBadNumbersAreRejectedNamingTheField) {
  World w;
  BodyDesc d;
  d.shape = collision::makeBox(Vec3(0.5)).value();
  d.density = 0.0;
  EXPECT_EQ(w.addBody(d, "crate").error(), "crate.density: must be a finite number > 0, got 0");
  d.density = 1000.0;
  d.mass = -2.0;
  EXPECT_NE(w.addBody(d, "crate").error().find("crate.mass"), std::string::npos);
  d.mass = 0.0;
  d.orientation = Quat(1.0, 0.2, 0.0, 0.0);
  EXPECT_NE(w.addBody(d, "crate").error().find("crate.orientation: must be a unit quaternion"), std::string::npos);
  d.orientation = Quat(1, 0, 0, 0);
  d.position = Vec3(0.0, NAN, 0.0);
  EXPECT_NE(w.addBody(d, "crate").error().find("crate.position: must be finite"), std::string::npos);
  d.position = Vec3(0.0);
  d.restitution = 1.5;
  EXPECT_NE(w.addBody(d, "crate").error().find("crate.restitution"), std::string::npos);
  BodyDesc plane;
  plane.shape = collision::makePlane();
  EXPECT_NE(w.addBody(plane, "floor").error().find("floor.type: a plane can only be static"), std::string::npos);
  EXPECT_EQ(w.bodyCount(), 0);
  // Shapes with zero or negative extents cannot be made at all.
  EXPECT_FALSE(collision::makeBox(Vec3(0.5, -0.1, 0.5)).ok());
  EXPECT_FALSE(collision::makeSphere(-1.0).ok());
}

TEST(BadInput, JointsWithBadBodiesOrAxesAreRejected) {
  World w;
  const int a = addBox(w, Vec3(0.5), Vec3(0.0, 1.0, 0.0), Quat(1, 0, 0, 0), 1000.0, 0.5, colors::kRed);
  JointDesc j;
  j.kind = JointKind::Hinge;
  j.bodyB = 7;
  EXPECT_NE(w.addJoint(j, "hinge").error().find("hinge.bodyB: no body 7"), std::string::npos);
  j.bodyB = a;
  j.axis = Vec3(0.0);
  EXPECT_NE(w.addJoint(j, "hinge").error().find("hinge.axis: must not be zero"), std::string::npos);
  j.axis = Vec3(0.0, 0.0, 1.0);
  j.enableLimit = true;
  j.lower = 1.0;
  j.upper = -1.0;
  EXPECT_NE(w.addJoint(j, "hinge").error().find("hinge.lower"), std::string::npos);
}

TEST(NonFiniteState, NamesTheBodyWhoseStateIsNotFinite) {
  World w;
  addGround(w);
  BodyDesc d;
  d.shape = collision::makeSphere(0.2).value();
  d.position = Vec3(0.0, 1.0, 0.0);
  d.name = "ball";
  const int b = w.addBody(d).value();
  EXPECT_FALSE(w.nonFiniteState().has_value());
  testing::FloatingPointTrapsOff off;
  w.setVelocity(b, Vec3(NAN, 0.0, 0.0), Vec3(0.0));
  const std::optional<std::string> what = w.nonFiniteState();
  ASSERT_TRUE(what.has_value());
  EXPECT_EQ(*what, "body 'ball' velocity is not finite");
}

// A hash of every body's state (bit patterns, so any difference shows).
std::uint64_t stateHash(const World& w) {
  ByteHash h;
  for (const Body& b : w.bodies()) {
    h.add(b.position);
    h.add(b.linearVelocity);
    h.add(b.angularVelocity);
    h.add(b.orientation);
  }
  return h.value();
}

std::uint64_t runPile(collision::BroadPhaseKind kind) {
  WorldSettings s;
  s.broadPhase = kind;
  World w(s);
  addGround(w);
  buildPile(w, 60, 3);
  for (int i = 0; i < 120; ++i) w.step(1.0 / 60.0);
  return stateHash(w);
}

TEST(Determinism, TheSameInputsGiveBitIdenticalStates) {
  EXPECT_EQ(runPile(collision::BroadPhaseKind::Tree), runPile(collision::BroadPhaseKind::Tree));
}

TEST(Determinism, EveryBroadPhaseGivesTheSameSimulation) {
  // The pair lists are sorted, so the solver sees the same constraints in the same order.
  const std::uint64_t tree = runPile(collision::BroadPhaseKind::Tree);
  EXPECT_EQ(runPile(collision::BroadPhaseKind::SweepAndPrune), tree);
  EXPECT_EQ(runPile(collision::BroadPhaseKind::BruteForce), tree);
}

TEST(RayCasts, TheWorldReportsTheFirstHitAndAllHitsInOrder) {
  World w;
  addGround(w);
  const int near = addBox(w, Vec3(0.5), Vec3(0.0, 0.5, 0.0), Quat(1, 0, 0, 0), 1000.0, 0.5, colors::kRed);
  const int far = addBox(w, Vec3(0.5), Vec3(0.0, 0.5, -3.0), Quat(1, 0, 0, 0), 1000.0, 0.5, colors::kRed);
  const Ray ray{Vec3(0.0, 0.5, 5.0), Vec3(0.0, 0.0, -1.0)};
  const std::optional<WorldRayHit> first = w.rayCast(ray, 100.0);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->body, near);
  EXPECT_NEAR(first->hit.t, 4.5, 1e-12);
  EXPECT_VEC3_NEAR(first->hit.normal, Vec3(0.0, 0.0, 1.0), 1e-12);
  const std::vector<WorldRayHit> all = w.rayCastAll(ray, 100.0);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[1].body, far);
  EXPECT_NEAR(all[1].hit.t, 7.5, 1e-12);
  // Straight down: the ground plane.
  const std::optional<WorldRayHit> down = w.rayCast({Vec3(3.0, 2.0, 0.0), Vec3(0.0, -1.0, 0.0)}, 100.0);
  ASSERT_TRUE(down.has_value());
  EXPECT_EQ(down->body, 0);
  EXPECT_NEAR(down->hit.t, 2.0, 1e-12);
}

TEST(Dragging, TheMouseConstraintPullsTheBodyPointToTheTarget) {
  World w;
  addGround(w);
  const int box = addBox(w, Vec3(0.2), Vec3(0.0, 0.2, 0.0), Quat(1, 0, 0, 0), 500.0, 0.5, colors::kRed);
  w.beginDrag(box, Vec3(0.0, 0.4, 0.0));  // the top face's centre
  w.dragTo(Vec3(1.0, 1.5, 0.0));
  for (int i = 0; i < 240; ++i) w.step(1.0 / 60.0);
  const Body& b = w.body(box);
  EXPECT_LT(glm::length(b.position + b.orientation * Vec3(0.0, 0.2, 0.0) - Vec3(1.0, 1.5, 0.0)), 0.02);
  w.endDrag();
  EXPECT_EQ(w.draggedBody(), -1);
}

TEST(Dragging, PlacingPutsTheGrabbedPointOnTheTargetAtRestAndRayCastsFindItThere) {
  World w;
  addGround(w);
  const int box = addBox(w, Vec3(0.2), Vec3(0.0, 0.2, 0.0), Quat(1, 0, 0, 0), 500.0, 0.5, colors::kRed);
  w.placeDragged();  // nothing dragged: nothing moves
  EXPECT_EQ(w.body(box).position, Vec3(0.0, 0.2, 0.0));
  w.beginDrag(box, Vec3(0.1, 0.4, 0.0));  // a point on the top face, off the centre
  w.dragTo(Vec3(2.1, 1.4, -1.0));
  w.placeDragged();
  const Body& b = w.body(box);
  EXPECT_VEC3_NEAR(b.position, Vec3(2.0, 1.2, -1.0), 1e-12);  // translated by target − grabbed point
  EXPECT_EQ(b.linearVelocity, Vec3(0.0));
  EXPECT_EQ(b.angularVelocity, Vec3(0.0));
  const std::optional<WorldRayHit> hit = w.rayCast(Ray{Vec3(2.0, 5.0, -1.0), Vec3(0.0, -1.0, 0.0)}, 100.0, true);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->body, box);
  EXPECT_NEAR(hit->hit.point.y, 1.4, 1e-9);
}

}  // namespace
}  // namespace pba::rigid
