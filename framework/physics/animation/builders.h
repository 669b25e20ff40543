#pragma once
// Scene builders of the animation lab (docs/architecture.md §1: the lab, the tests and the benchmarks
// use the same characters and clips): the built-in humanoid and procedural keyframed clips for it.
#include "physics/animation/clip.h"
#include "physics/animation/skeleton.h"

namespace pba::animation {

/// The built-in humanoid: the 21 joints of resources/models/humanoid.bvh (Hips root, spine, neck, head,
/// arms, legs, toes) with its offsets converted from centimetres to metres; identity rest rotations,
/// y up, facing +z, hips 0.95 m above the ground.
Skeleton buildHumanoid();

/// A keyframed walk or run cycle of the humanoid (keys every eighth of a cycle, squad rotations,
/// Catmull-Rom root translation), walking along +z.
struct GaitDesc {
  Real period = 1.1;     ///< [s] > 0: one full cycle (two steps)
  Real hipSwing = 0.45;  ///< [rad] thigh swing amplitude about x
  Real kneeFlex = 0.65;  ///< [rad] knee bend at mid-swing
  Real armSwing = 0.35;  ///< [rad] upper-arm swing amplitude (opposite to the leg)
  Real elbowFlex = 0.3;  ///< [rad] forearm bend
  Real lean = 0.05;      ///< [rad] forward lean of the spine
  Real bounce = 0.025;   ///< [m] vertical hip bounce amplitude (twice per cycle)
  Real speed = 1.3;      ///< [m/s] forward speed of the root
};
/// A run: shorter, larger and faster than the default walk.
GaitDesc runGait();
Clip buildGaitClip(const Skeleton& humanoid, const GaitDesc& gait, const std::string& name = "walk");

/// The humanoid standing and waving its right hand (2 s, loops).
Clip buildWaveClip(const Skeleton& humanoid);

/// World position of joint j at clip time t, and its acceleration by the second central difference
/// over ±h [s] (the pivot acceleration of a pendulum joint: root translation plus the keyframed
/// ancestors' rotations, CMU asst4 "reaction to the parent's motion").

}  // namespace pba::animation
