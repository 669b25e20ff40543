#include "physics/animation/clip.h"

#include <algorithm>
#include <cmath>

#include "physics/exercises/not_implemented.h"

namespace pba::animation {

Status validate(const Clip& clip, const Skeleton& skeleton, const std::string& source) {
  const std::string where = source.empty() ? std::string() : source + ": ";
  if (clip.tracks.size() != skeleton.names.size())
    return Error{where + "clip '" + clip.name + std::string("' has ") + std::to_string(clip.tracks.size()) +
                 std::string(" tracks for a skeleton of ") + std::to_string(skeleton.names.size()) +
                 " joints (a clip of another skeleton?)"};
  if (!(clip.duration > 0.0) || !std::isfinite(clip.duration))
    return Error{where + "clip '" + clip.name + "'.duration: must be a positive number of seconds"};
  for (size_t j = 0; j < clip.tracks.size(); ++j) {
    const std::string field = where + std::string("tracks[") + std::to_string(j) + "] (" + skeleton.names[j] + ")";
    const JointTrack& track = clip.tracks[j];
    if (Status s = detail::checkIncreasing(track.translation.times(), field + ".translation"); !s.ok()) return s;
    if (Status s = detail::checkIncreasing(track.rotation.times(), field + ".rotation"); !s.ok()) return s;
    for (const Vec3& v : track.translation.values())
      if (!isFinite(v)) return Error{field + ".translation: a key is not finite"};
  }
  return Status::success();
}

Vec3 rootDisplacement(const Clip& clip, const Skeleton& skeleton) {
  if (clip.tracks.empty() || clip.tracks[0].translation.empty()) return Vec3(0.0);
  static_cast<void>(skeleton);
  const Channel<Vec3>& c = clip.tracks[0].translation;
  const Vec3 d = c.valueAt(clip.duration) - c.valueAt(0.0);
  return {d.x, 0.0, d.z};
}

void samplePose(const Skeleton& skeleton, const Clip& clip, Real t, Pose& pose) {
  const size_t n = skeleton.names.size();
  pose.translations.resize(n);
  pose.rotations.resize(n);
  const Real tc = std::clamp(t, 0.0, clip.duration);
  for (size_t j = 0; j < n; ++j) {
    const JointTrack* track = j < clip.tracks.size() ? &clip.tracks[j] : nullptr;
    pose.translations[j] =
        track && !track->translation.empty() ? track->translation.valueAt(tc) : skeleton.restTranslations[j];
    pose.rotations[j] = track && !track->rotation.empty() ? track->rotation.valueAt(tc) : skeleton.restRotations[j];
  }
}

void playPose(const Skeleton& skeleton, const Clip& clip, Real t, const Playback& playback, Pose& pose) {
  Real cycles = 0.0;
  Real tc = t;
  if (playback.loop && clip.duration > 0.0) {
    cycles = std::floor(t / clip.duration);
    tc = t - cycles * clip.duration;
  }
  samplePose(skeleton, clip, tc, pose);
  if (pose.translations.empty()) return;
  switch (playback.rootMotion) {
    case RootMotion::AsRecorded:
      break;
    case RootMotion::Accumulate:
      pose.translations[0] += cycles * rootDisplacement(clip, skeleton);
      break;
    case RootMotion::InPlace: {
      const Vec3 start = clip.tracks.empty() || clip.tracks[0].translation.empty()
                             ? skeleton.restTranslations[0]
                             : clip.tracks[0].translation.valueAt(0.0);
      pose.translations[0].x = start.x;
      pose.translations[0].z = start.z;
      break;
    }
  }
}

Real TimeWarp::operator()(Real t) const {
  const int n = map.size();
  if (n == 0) return t;
  if (n == 1) return map.value(0) + (t - map.time(0));
  if (t < map.time(0)) {
    const Real slope = (map.value(1) - map.value(0)) / (map.time(1) - map.time(0));
    return map.value(0) + slope * (t - map.time(0));
  }
  if (t > map.time(n - 1)) {
    const Real slope = (map.value(n - 1) - map.value(n - 2)) / (map.time(n - 1) - map.time(n - 2));
    return map.value(n - 1) + slope * (t - map.time(n - 1));
  }
  return map.valueAt(t);
}

Status validate(const TimeWarp& warp) {
  if (Status s = detail::checkIncreasing(warp.map.times(), "time warp"); !s.ok()) return s;
  for (int k = 1; k < warp.map.size(); ++k)
    if (warp.map.value(k) < warp.map.value(k - 1))
      return Error{std::string("time warp: key ") + std::to_string(k) + " goes back in clip time"};
  return Status::success();
}

BlendWeights crossFadeWeights(Real t, Real start, Real duration) {
  Real x = duration > 0.0 ? (t - start) / duration : (t >= start ? 1.0 : 0.0);
  x = std::clamp(x, 0.0, 1.0);
  const Real w = x * x * (3.0 - 2.0 * x);
  return {1.0 - w, w};
}

void blendPoses(const Pose& a, const Pose& b, Real w, Pose& out) {
  const size_t n = std::min(a.rotations.size(), b.rotations.size());
  out.translations.resize(n);
  out.rotations.resize(n);
  for (size_t j = 0; j < n; ++j) {
    out.translations[j] = w <= 0.0   ? a.translations[j]
                          : w >= 1.0 ? b.translations[j]
                                     : glm::mix(a.translations[j], b.translations[j], w);
    out.rotations[j] = w <= 0.0 ? a.rotations[j] : w >= 1.0 ? b.rotations[j] : slerp(a.rotations[j], b.rotations[j], w);
  }
}

// ***** ANIM-6: two clips blended at the same phase (CMU asst4 "Keyframes"; Kovar & Gleicher 2003, §3) *****
// Inputs: the skeleton, two looping clips of it (durations in seconds, different in general), the weight w
// ∈ [0, 1] of b, the phase in [0, 1) (the fraction of a cycle both clips have done) and the time step dt [s].
// (1) The blended character walks one cycle in a blended time: find its cycle length [s] from the two
//     clips' durations with the weights (1 − w, w), and advance the phase by the fraction of a cycle that
//     dt is. Keep the phase in [0, 1).
// (2) Turn the new phase into each clip's own time [s] (the same fraction of each clip's duration), and
//     sample both poses looping, with the root held in place (playPose, RootMotion::InPlace), so that the
//     two cycles' feet stay in step whatever their lengths.
// (3) Mix the two poses with the weights (blendPoses) into `out`, and return the new phase.
// Check: w = 0 plays a alone and w = 1 plays b alone, each at its own speed; halfway, one cycle takes the
// mean of the two durations; the phase wraps from just below 1 to just above 0.
// *****
Real blendAtPhase(const Skeleton& skeleton, const Clip& a, const Clip& b, Real w, Real phase, Real dt, Pose& out) {
  // BEGIN SOLUTION
  const Real period = (1.0 - w) * a.duration + w * b.duration;
  const Real next = dt == 0.0 ? phase : std::fmod(phase + dt / period, 1.0);
  const Playback inPlace{true, RootMotion::InPlace};
  Pose poseA, poseB;
  playPose(skeleton, a, next * a.duration, inPlace, poseA);
  playPose(skeleton, b, next * b.duration, inPlace, poseB);
  blendPoses(poseA, poseB, w, out);
  return next;
  // END SOLUTION
  // STUB: return exercises::notImplemented("ANIM-6", phase, skeleton, a, b, w, dt, out);  // nothing moves
}

}  // namespace pba::animation

namespace {
pba::animation::Skeleton probeBlendSkeleton() {
  pba::animation::Skeleton s;
  s.add("root", -1, pba::Vec3(0.0));
  return s;
}
pba::Real probeBlend() {
  const pba::animation::Skeleton s = probeBlendSkeleton();
  pba::animation::Clip c;
  c.duration = 1.0;
  c.tracks.resize(1);
  pba::animation::Pose out;
  return pba::animation::blendAtPhase(s, c, c, 0.5, 0.0, 0.1, out);
}
}  // namespace
// Start-up probe: tells the lab whether ANIM-6 is still a stub.
PBA_EXERCISE_PROBE(probeBlend());
