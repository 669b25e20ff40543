// Joints: the error of a 10-link hinge chain under gravity, limits, motors, the slider, the cone, the
// distance joint; all from measurements of the bodies' poses (the anchors recomputed here).
#include <cmath>

#include <gtest/gtest.h>

#include "physics/rigid/builders.h"
#include "support/expect_helpers.h"

namespace pba::rigid {
namespace {

// Distance between the two anchors of joint j, from the bodies' poses.
Real anchorGap(const World& w, int j) {
  const Joint& joint = w.joints()[j];
  const Body& b = w.body(joint.desc.bodyB);
  const Vec3 pb = b.position + b.orientation * joint.localB;
  const Vec3 pa = joint.desc.bodyA < 0
                      ? joint.localA
                      : w.body(joint.desc.bodyA).position + w.body(joint.desc.bodyA).orientation * joint.localA;
  return glm::length(pb - pa);
}

WorldSettings jointSettings() {
  WorldSettings s;
  s.sleeping = false;
  s.iterations = 2;  // the lab's joints scene setting
  return s;
}

TEST(HingeChain, TenLinksUnderGravityKeepTheirJointsWithinAMillimetreAtSixtyHertz) {
  for (Real tilt : {0.3, 0.8}) {  // released 17° and 39° from hanging straight down
    World w(jointSettings());
    buildChain(w, Vec3(0.0, 6.0, 0.0), 10, 0.4, false, 500.0, glm::normalize(Vec3(tilt, -1.0, 0.0)));
    Real worst = 0.0;
    for (int i = 0; i < 600; ++i) {
      w.step(1.0 / 60.0);
      for (int j = 0; j < static_cast<int>(w.joints().size()); ++j) worst = std::max(worst, anchorGap(w, j));
    }
    EXPECT_LT(worst, 1e-3) << "tilt " << tilt;
  }
}

int addHingedBar(World& w, const JointDesc& extra, Vec3 anchor, int& joint) {
  const int bar =
      addBox(w, Vec3(0.5, 0.05, 0.05), anchor + Vec3(0.5, 0.0, 0.0), Quat(1, 0, 0, 0), 500.0, 0.5, colors::kRed);
  JointDesc j = extra;
  j.kind = JointKind::Hinge;
  j.bodyB = bar;
  j.anchor = anchor;
  j.axis = Vec3(0.0, 0.0, 1.0);
  joint = w.addJoint(j).value();
  return bar;
}

TEST(HingeLimits, HoldWithinOneDegreeWhenABarFallsOntoThem) {
  for (Real limitDeg : {10.0, 30.0, 60.0}) {
    World w(jointSettings());
    JointDesc d;
    d.enableLimit = true;
    d.lower = -degToRad(limitDeg);
    d.upper = degToRad(limitDeg);
    int joint = -1;
    const int bar = addHingedBar(w, d, Vec3(0.0, 3.0, 0.0), joint);
    Real worst = 0.0;
    for (int i = 0; i < 300; ++i) {
      w.step(1.0 / 60.0);
      // The bar's angle about z from its direction (independent of the joint's own measure).
      const Vec3 x = w.body(bar).orientation * Vec3(1.0, 0.0, 0.0);
      const Real angle = std::atan2(x.y, x.x);
      worst = std::max({worst, d.lower - angle, angle - d.upper});
    }
    EXPECT_LT(radToDeg(worst), 1.0) << "limit " << limitDeg << "°";
    // And it rests on the lower limit.
    const Vec3 x = w.body(bar).orientation * Vec3(1.0, 0.0, 0.0);
    EXPECT_NEAR(radToDeg(std::atan2(x.y, x.x)), -limitDeg, 1.0);
  }
}

TEST(HingeMotor, ReachesItsSpeedAndRespectsItsTorque) {
  World w(jointSettings());
  w.settings().gravity = Vec3(0.0);
  JointDesc d;
  d.enableMotor = true;
  d.motorSpeed = 3.0;       // [rad/s]
  d.maxMotorTorque = 50.0;  // [N·m]
  int joint = -1;
  const int bar = addHingedBar(w, d, Vec3(0.0, 3.0, 0.0), joint);
  // Spin-up at the torque limit: ω̇ = τ / I about the hinge (I from the bar's inertia + parallel axis).
  const Body& b = w.body(bar);
  const Real iz = b.inertiaBody[2][2] + b.mass * 0.25;
  w.step(1.0 / 60.0);
  EXPECT_NEAR(w.body(bar).angularVelocity.z, 50.0 / iz / 60.0, 0.02 * 50.0 / iz / 60.0);
  for (int i = 0; i < 300; ++i) w.step(1.0 / 60.0);
  EXPECT_NEAR(w.body(bar).angularVelocity.z, 3.0, 0.01 * 3.0);
}

TEST(Slider, StaysOnItsAxisWithinItsLimits) {
  World w(jointSettings());
  const Vec3 axis = glm::normalize(Vec3(1.0, -0.5, 0.0));
  const int box = addBox(w, Vec3(0.2), Vec3(0.0, 3.0, 0.0), Quat(1, 0, 0, 0), 500.0, 0.5, colors::kRed);
  JointDesc d;
  d.kind = JointKind::Slider;
  d.bodyB = box;
  d.anchor = Vec3(0.0, 3.0, 0.0);
  d.axis = axis;
  d.enableLimit = true;
  d.lower = -0.5;
  d.upper = 0.7;
  w.addJoint(d).value();
  for (int i = 0; i < 300; ++i) {
    w.step(1.0 / 60.0);
    const Vec3 offset = w.body(box).position - d.anchor;
    const Real along = glm::dot(offset, axis);
    EXPECT_LT(glm::length(offset - along * axis), 1e-3);  // on the axis
    EXPECT_LT(along, d.upper + 2e-3);                     // within the limits (2 mm)
    EXPECT_GT(along, d.lower - 2e-3);
    // No rotation.
    EXPECT_GT(std::abs(w.body(box).orientation.w), 1.0 - 1e-6);
  }
  EXPECT_NEAR(glm::dot(w.body(box).position - d.anchor, axis), d.upper, 2e-3);  // slid down to the end
}

TEST(ConeTwist, TheSwingStaysInsideTheCone) {
  World w(jointSettings());
  BodyDesc cap;
  cap.shape = collision::makeCapsule(0.4, 0.1).value();
  cap.position = Vec3(0.0, 4.0, 0.0);
  cap.angularVelocity = Vec3(8.0, 0.0, 6.0);
  const int c = w.addBody(cap).value();
  JointDesc d;
  d.kind = JointKind::ConeTwist;
  d.bodyB = c;
  d.anchor = Vec3(0.0, 4.5, 0.0);
  d.axis = Vec3(0.0, -1.0, 0.0);
  d.swingSpan = degToRad(25.0);
  w.addJoint(d).value();
  Real worst = 0.0;
  for (int i = 0; i < 300; ++i) {
    w.step(1.0 / 60.0);
    const Vec3 down = w.body(c).orientation * Vec3(0.0, -1.0, 0.0);  // the capsule's axis, from the anchor
    worst = std::max(worst, std::acos(std::clamp(glm::dot(down, Vec3(0.0, -1.0, 0.0)), -1.0, 1.0)));
  }
  EXPECT_LT(radToDeg(worst), 25.0 + 1.0);
  EXPECT_GT(radToDeg(worst), 20.0);  // it did swing out to the cone
}

TEST(DistanceJoint, ARigidRodKeepsItsLengthWithinAMillimetre) {
  World w(jointSettings());
  const int ball = w.addBody([] {
                      BodyDesc b;
                      b.shape = collision::makeSphere(0.1).value();
                      b.position = Vec3(1.0, 5.0, 0.0);
                      return b;
                    }())
                       .value();
  JointDesc rod;
  rod.kind = JointKind::Distance;
  rod.bodyB = ball;
  rod.anchor = Vec3(0.0, 5.0, 0.0);
  rod.anchorB = Vec3(1.0, 5.0, 0.0);
  const int j = w.addJoint(rod).value();
  Real worst = 0.0;
  for (int i = 0; i < 300; ++i) {
    w.step(1.0 / 60.0);
    worst = std::max(worst, std::abs(anchorGap(w, j) - 1.0));
  }
  EXPECT_LT(worst, 1e-3);
}

}  // namespace
}  // namespace pba::rigid
