#pragma once
// What a ragdoll test measures from the bones' poses alone, never from a solver's own statistics, so the
// two methods (particle and constraint) are judged by one ruler:
//   * joint gap: the joint's anchor carried by bone A and by bone B (its offset in each box's frame at
//     the start), |p_A − p_B|;
//   * limits: the bodies' relative rotation. Hinge: the angle of B about the axis (seen in A), from a
//     reference direction ⟂ axis fixed in both bones at the start, must lie in [lower, upper] (the angle
//     between its axis carried by A and by B is reported: the joint gap bounds it). Ball with a cone: the
//     angle between the cone axis carried by A and the bone axis carried by B must stay below the cone
//     angle (twist is free);
//   * penetration: the lowest of the eight corners of every box against the ground plane y = 0;
//   * energy: each box's potential m g y of its centre, and its kinetic energy ½ m |v|² + ½ ωᵀ I ω with
//     the box's own inertia, v and ω by central differences of three poses one step apart (exact for a
//     body in free fall, whose centre moves on a parabola).
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "physics/collision/transform.h"
#include "physics/ragdoll/ragdoll_desc.h"

namespace pba::test {

/// The eight corners of a box of half sizes h at pose t.
inline std::array<Vec3, 8> boxCorners(const collision::Transform& t, const Vec3& h) {
  std::array<Vec3, 8> c{};
  for (int i = 0; i < 8; ++i) c[i] = t.apply(Vec3(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z));
  return c;
}

inline Real angleBetween(const Vec3& u, const Vec3& v) {
  return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

/// A joint seen from each of its bones: anchor, axis and (hinges) a reference direction ⟂ axis, each in
/// the bone's own frame at the start.
struct JointInBones {
  const ragdoll::JointDesc* desc = nullptr;
  Vec3 anchorA{0.0}, anchorB{0.0}, axisA{0.0}, axisB{0.0}, refA{0.0}, refB{0.0};
};

inline std::vector<JointInBones> jointsInBones(const ragdoll::RagdollDesc& d) {
  std::vector<JointInBones> out;
  for (const ragdoll::JointDesc& j : d.joints) {
    const collision::Transform a{d.bones[j.boneA].center, d.bones[j.boneA].orientation};
    const collision::Transform b{d.bones[j.boneB].center, d.bones[j.boneB].orientation};
    const Vec3 axis = glm::normalize(j.axis);
    const Vec3 helper = std::abs(axis.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
    const Vec3 ref = glm::normalize(glm::cross(axis, helper));
    out.push_back({&j, a.applyInverse(j.anchor), b.applyInverse(j.anchor), a.rotateInverse(axis), b.rotateInverse(axis),
                   a.rotateInverse(ref), b.rotateInverse(ref)});
  }
  return out;
}

struct PoseMeasure {
  Real jointGap = 0.0;       // [m] largest
  Real limitExcess = 0.0;    // [rad] largest angle beyond a limit
  Real hingeTilt = 0.0;      // [rad] largest angle between a hinge's axis carried by A and by B (reported)
  Real penetration = 0.0;    // [m] deepest corner below y = 0
  Real lowestCorner = 0.0;   // [m]
  Real fastestCorner = 0.0;  // [m/s] since the previous pose (0 for the first)
  std::string worstLimit;    // the joint (bone B's name) with the largest limit excess
  std::string worstGap;      // the joint (bone B's name) with the largest gap
};

/// Measures `pose` (one transform per bone of `d`); `corners` carries the corners of the previous pose
/// between calls (start with an empty vector) for the fastest corner over the step `dt`.
inline PoseMeasure measurePose(const ragdoll::RagdollDesc& d, const std::vector<JointInBones>& joints,
                               const std::vector<collision::Transform>& pose, Real dt, std::vector<Vec3>& corners) {
  PoseMeasure m;
  m.lowestCorner = 1e300;
  std::vector<Vec3> now;
  for (std::size_t i = 0; i < pose.size(); ++i)
    for (const Vec3& c : boxCorners(pose[i], d.bones[i].halfExtents)) now.push_back(c);
  for (std::size_t k = 0; k < now.size(); ++k) {
    m.lowestCorner = std::min(m.lowestCorner, now[k].y);
    if (!corners.empty()) m.fastestCorner = std::max(m.fastestCorner, glm::length(now[k] - corners[k]) / dt);
  }
  corners = std::move(now);
  m.penetration = std::max(0.0, -m.lowestCorner);
  for (const JointInBones& j : joints) {
    const collision::Transform& a = pose[j.desc->boneA];
    const collision::Transform& b = pose[j.desc->boneB];
    const Real gap = glm::length(a.apply(j.anchorA) - b.apply(j.anchorB));
    if (gap > m.jointGap) m.jointGap = gap, m.worstGap = d.bones[j.desc->boneB].name;
    const Vec3 axisA = a.rotate(j.axisA), axisB = b.rotate(j.axisB);
    Real excess = 0.0;
    if (j.desc->kind == ragdoll::JointKind::Hinge) {
      const Vec3 refA = a.rotate(j.refA), refB = b.rotate(j.refB);
      const Vec3 inPlane = refB - glm::dot(refB, axisA) * axisA;
      const Real angle = std::atan2(glm::dot(axisA, glm::cross(refA, inPlane)), glm::dot(refA, inPlane));
      m.hingeTilt = std::max(m.hingeTilt, angleBetween(axisA, axisB));
      if (j.desc->limited) excess = std::max({0.0, j.desc->lower - angle, angle - j.desc->upper});
    } else if (j.desc->limited) {
      excess = std::max(0.0, angleBetween(axisA, axisB) - j.desc->coneAngle);
    }
    if (excess > m.limitExcess) m.limitExcess = excess, m.worstLimit = d.bones[j.desc->boneB].name;
  }
  return m;
}

struct PoseEnergy {
  Real kinetic = 0.0, potential = 0.0;  // [J]
};

/// The energy of the boxes at `now`, from the poses one step `dt` before and after (central differences).
/// Fixed bones count for neither term; `gravity` is the scene's acceleration (e.g. (0, −9.81, 0)).
inline PoseEnergy energyFromPoses(const ragdoll::RagdollDesc& d, const std::vector<collision::Transform>& before,
                                  const std::vector<collision::Transform>& now,
                                  const std::vector<collision::Transform>& after, Real dt, const Vec3& gravity) {
  PoseEnergy e;
  for (std::size_t i = 0; i < now.size(); ++i) {
    const ragdoll::BoneDesc& b = d.bones[i];
    if (b.fixed) continue;
    const Vec3 v = (after[i].position - before[i].position) / (2.0 * dt);
    Quat turn = after[i].rotation * glm::conjugate(before[i].rotation);  // world rotation over 2 dt
    if (turn.w < 0.0) turn = -turn;
    const Real sinHalf = glm::length(Vec3(turn.x, turn.y, turn.z));
    const Real angle = 2.0 * std::atan2(sinHalf, turn.w);
    const Vec3 omegaWorld = sinHalf > 0.0 ? Vec3(turn.x, turn.y, turn.z) / sinHalf * (angle / (2.0 * dt)) : Vec3(0.0);
    const Vec3 w = glm::conjugate(now[i].rotation) * omegaWorld;  // in the box's frame
    const Vec3 h2 = b.halfExtents * b.halfExtents;
    const Vec3 inertia = b.mass / 3.0 * Vec3(h2.y + h2.z, h2.x + h2.z, h2.x + h2.y);  // solid box, half sizes h
    e.kinetic += 0.5 * b.mass * glm::dot(v, v) + 0.5 * glm::dot(w * inertia, w);
    e.potential -= b.mass * glm::dot(gravity, now[i].position);
  }
  return e;
}

}  // namespace pba::test
