#pragma once
// Motion clips: one translation and one rotation channel per joint of a skeleton, sampled into a
// Pose at any time (CMU asst4 "Keyframes"; Workbook §2.7 advanced: "load an animated skeleton").
// Clips come from the keyframe editor, from the builders (builders.h) or from files through the
// graphics import (the lab converts; the physics library never sees Assimp).
//
// Playback: looping wraps the clip time into [0, duration); root motion is the root's horizontal
// (x, z) displacement over one cycle, which a loop either keeps as in the file (the character jumps
// back every cycle), accumulates (cycle k is shifted by k times the displacement: a walk keeps going),
// or removes (in place: a treadmill). Time warping maps the scene's time onto the clip's time through
// a monotone piecewise-linear channel. Blending mixes two poses of one skeleton: translations by lerp,
// rotations by slerp, with weights (1 − w, w) that sum to one; a cross-fade ramps w smoothly.
#include <string>
#include <vector>

#include "physics/animation/channel.h"
#include "physics/animation/skeleton.h"

namespace pba::animation {

struct JointTrack {
  Channel<Vec3> translation{Interpolation::Linear};        ///< [m]; empty: the rest translation
  RotationChannel rotation{RotationInterpolation::Slerp};  ///< empty: the rest rotation
};

struct Clip {
  std::string name;
  Real duration = 0.0;             ///< [s] > 0
  std::vector<JointTrack> tracks;  ///< one per joint of the skeleton
  int frames = 0;                  ///< [1] sample count of a captured clip (0 for a keyframed one)
};

/// Errors name the source and the field: "walk.bvh: clip 'walk' has 24 tracks for a skeleton of 31
/// joints", "walk.bvh: tracks[3] (LeftLeg).rotation: keys 4 and 5 at equal times (0.5 s)".
Status validate(const Clip& clip, const Skeleton& skeleton, const std::string& source);

enum class RootMotion {
  AsRecorded,  ///< the root follows the clip; a loop jumps back to the start
  Accumulate,  ///< each loop continues from where the last one ended
  InPlace,     ///< the root's horizontal motion is removed
};

struct Playback {
  bool loop = true;
  RootMotion rootMotion = RootMotion::AsRecorded;
};

/// The root's horizontal displacement over the whole clip [m] (y = 0).
Vec3 rootDisplacement(const Clip& clip, const Skeleton& skeleton);

/// The pose at clip time t [s] (no looping: t is clamped to [0, duration]).
void samplePose(const Skeleton& skeleton, const Clip& clip, Real t, Pose& pose);
/// The pose at playback time t with looping and root motion.
void playPose(const Skeleton& skeleton, const Clip& clip, Real t, const Playback& playback, Pose& pose);

/// A monotone map from scene time to clip time (piecewise linear through its keys; outside them the
/// end slopes continue). Empty: the identity.
struct TimeWarp {
  Channel<Real> map{Interpolation::Linear};
  Real operator()(Real t) const;
};
/// Errors when the map decreases anywhere: "time warp: key 2 goes back in clip time".
Status validate(const TimeWarp& warp);

/// Weights (1 − w, w) of two clips; they sum to one.
struct BlendWeights {
  Real first = 1.0;
  Real second = 0.0;
};
/// A cross-fade from the first clip to the second that starts at `start` and lasts `duration` [s]:
/// w = smoothstep((t − start)/duration), 0 before, 1 after.
BlendWeights crossFadeWeights(Real t, Real start, Real duration);
/// Pose mixing a (weight 1 − w) and b (weight w); w = 0 gives a, w = 1 gives b exactly.
void blendPoses(const Pose& a, const Pose& b, Real w, Pose& out);

// ANIM-6
/// Two looping cycles of one skeleton (a walk and a run) blended at one phase: advances the shared phase
/// [0, 1) by dt [s] at the cycle length blended with weight w, then writes to `out` the pose that mixes a
/// (weight 1 − w) and b (weight w), both sampled at the new phase with the root kept in place. Returns the
/// new phase. dt = 0 gives the pose at `phase` itself.
Real blendAtPhase(const Skeleton& skeleton, const Clip& a, const Clip& b, Real w, Real phase, Real dt, Pose& out);

}  // namespace pba::animation
