#include "physics/animation/builders.h"

#include <cmath>

namespace pba::animation {

namespace {

struct JointRow {
  const char* name;
  const char* parent;
  Real x, y, z;  // [cm] OFFSET of humanoid.bvh
};

// resources/models/humanoid.bvh, HIERARCHY section (the End Sites are left out).
constexpr JointRow kHumanoid[] = {
    {"Hips", "", 0, 95, 0},
    {"Spine", "Hips", 0, 10, 0},
    {"Chest", "Spine", 0, 15, 0},
    {"Neck", "Chest", 0, 22, 0},
    {"Head", "Neck", 0, 10, 0},
    {"LeftShoulder", "Chest", 3, 18, 0},
    {"LeftArm", "LeftShoulder", 14, 0, 0},
    {"LeftForeArm", "LeftArm", 10, -26, 0},
    {"LeftHand", "LeftForeArm", 8, -24, 2},
    {"RightShoulder", "Chest", -3, 18, 0},
    {"RightArm", "RightShoulder", -14, 0, 0},
    {"RightForeArm", "RightArm", -10, -26, 0},
    {"RightHand", "RightForeArm", -8, -24, 2},
    {"LeftUpLeg", "Hips", 9, -3, 0},
    {"LeftLeg", "LeftUpLeg", 0, -44, 1},
    {"LeftFoot", "LeftLeg", 0, -42, -3},
    {"LeftToeBase", "LeftFoot", 0, -4, 12},
    {"RightUpLeg", "Hips", -9, -3, 0},
    {"RightLeg", "RightUpLeg", 0, -44, 1},
    {"RightFoot", "RightLeg", 0, -42, -3},
    {"RightToeBase", "RightFoot", 0, -4, 12},
};

Quat axisAngle(const Vec3& axis, Real angle) { return glm::angleAxis(angle, glm::normalize(axis)); }
const Vec3 kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

Clip emptyClip(const Skeleton& s, const std::string& name, Real duration) {
  Clip c;
  c.name = name;
  c.duration = duration;
  c.tracks.resize(static_cast<size_t>(s.size()));
  for (JointTrack& t : c.tracks) {
    t.translation = Channel<Vec3>(Interpolation::CatmullRom);
    t.rotation = RotationChannel(RotationInterpolation::Squad);
  }
  return c;
}

void key(Clip& c, const Skeleton& s, const char* joint, Real t, const Quat& q) {
  const int j = s.find(joint);
  if (j >= 0) static_cast<void>(c.tracks[static_cast<size_t>(j)].rotation.insert(t, q));
}

}  // namespace

Skeleton buildHumanoid() {
  Skeleton s;
  for (const JointRow& r : kHumanoid) s.add(r.name, s.find(r.parent), 0.01 * Vec3(r.x, r.y, r.z));
  return s;
}

GaitDesc runGait() {
  GaitDesc g;
  g.period = 0.72;
  g.hipSwing = 0.7;
  g.kneeFlex = 1.3;
  g.armSwing = 0.6;
  g.elbowFlex = 1.2;
  g.lean = 0.2;
  g.bounce = 0.05;
  g.speed = 3.2;
  return g;
}

Clip buildGaitClip(const Skeleton& s, const GaitDesc& g, const std::string& name) {
  Clip c = emptyClip(s, name, g.period);
  constexpr int kKeys = 8;
  // One key beyond each end (k = −1 and k = 9): the spline tangents at 0 and at the period then come
  // from the cycle's own neighbours, so a looping cycle is C¹ across the loop too (no velocity jump).
  for (int k = -1; k <= kKeys + 1; ++k) {
    const Real t = g.period * k / kKeys;
    const Real phase = 2.0 * kPi * k / kKeys;
    const Real s1 = std::sin(phase);
    // Left knee bends while the left thigh swings forward (cos > 0), the right one half a cycle later.
    const Real leftSwing = std::max(0.0, std::cos(phase));
    const Real rightSwing = std::max(0.0, -std::cos(phase));
    key(c, s, "LeftUpLeg", t, axisAngle(kX, -g.hipSwing * s1 - 0.1 * g.hipSwing));
    key(c, s, "RightUpLeg", t, axisAngle(kX, g.hipSwing * s1 - 0.1 * g.hipSwing));
    key(c, s, "LeftLeg", t, axisAngle(kX, 0.08 + g.kneeFlex * leftSwing * leftSwing));
    key(c, s, "RightLeg", t, axisAngle(kX, 0.08 + g.kneeFlex * rightSwing * rightSwing));
    key(c, s, "LeftFoot", t, axisAngle(kX, -0.15 * s1));
    key(c, s, "RightFoot", t, axisAngle(kX, 0.15 * s1));
    key(c, s, "LeftArm", t, axisAngle(kX, g.armSwing * s1));
    key(c, s, "RightArm", t, axisAngle(kX, -g.armSwing * s1));
    key(c, s, "LeftForeArm", t, axisAngle(kX, -g.elbowFlex - 0.3 * g.elbowFlex * std::max(0.0, s1)));
    key(c, s, "RightForeArm", t, axisAngle(kX, -g.elbowFlex - 0.3 * g.elbowFlex * std::max(0.0, -s1)));
    key(c, s, "Spine", t, axisAngle(kX, g.lean) * axisAngle(kY, 0.12 * s1));
    key(c, s, "Chest", t, axisAngle(kY, -0.2 * s1));
    key(c, s, "Hips", t, axisAngle(kY, -0.08 * s1) * axisAngle(kZ, 0.04 * std::cos(phase)));
    const Real dropForKnees = 0.95 - 0.02 - 0.01 * g.kneeFlex;
    static_cast<void>(
        c.tracks[0].translation.insert(t, Vec3(0.0, dropForKnees + g.bounce * std::cos(2.0 * phase), g.speed * t)));
  }
  return c;
}

Clip buildWaveClip(const Skeleton& s) {
  Clip c = emptyClip(s, "wave", 2.0);
  constexpr int kKeys = 8;
  for (int k = 0; k <= kKeys; ++k) {
    const Real t = 2.0 * k / kKeys;
    const Real phase = 2.0 * kPi * k / kKeys;
    key(c, s, "RightArm", t, axisAngle(kZ, -2.2) * axisAngle(kX, -0.3));
    key(c, s, "RightForeArm", t, axisAngle(kZ, -0.35 + 0.5 * std::sin(2.0 * phase)));
    key(c, s, "LeftArm", t, axisAngle(kZ, -0.1) * axisAngle(kX, 0.1));
    key(c, s, "Spine", t, axisAngle(kZ, 0.05 * std::sin(phase)));
    key(c, s, "Head", t, axisAngle(kY, 0.25 * std::sin(phase)));
    static_cast<void>(c.tracks[0].translation.insert(t, Vec3(0.0, 0.95 + 0.01 * std::cos(2.0 * phase), 0.0)));
  }
  return c;
}

}  // namespace pba::animation
