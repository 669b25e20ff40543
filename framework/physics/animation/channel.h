#pragma once
// Keyframe channels (CMU asst4, "Keyframes"): a value that changes over time through keys, edited by
// insert, delete and move, and evaluated (value, velocity, acceleration) at any time by one of the
// interpolants of catmull_rom.h and cubic_spline.h. Channel<T> serves scalars, vectors and colours;
// RotationChannel serves joint rotations (rotation.h). Times are strictly increasing: an edit that
// would put two keys at one time is refused with a message naming the field.
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "physics/animation/catmull_rom.h"
#include "physics/animation/cubic_spline.h"
#include "physics/animation/rotation.h"
#include "physics/core/format.h"
#include "physics/core/result.h"

namespace pba::animation {

enum class Interpolation {
  Step,
  Linear,
  CatmullRom,    ///< C¹ (ANIM-1, ANIM-2)
  NaturalCubic,  ///< C², zero second derivative at the ends
};

namespace detail {
/// Index at which a key at `time` goes, or an error when a key already sits there (within 1e-9 s).
Result<int> insertionIndex(const std::vector<Real>& times, Real time, const std::string& field);
Status checkIncreasing(const std::vector<Real>& times, const std::string& field);
}  // namespace detail

template <typename T>
class Channel {
 public:
  Channel() = default;
  explicit Channel(Interpolation mode, T defaultValue = T(0.0)) : mode_(mode), default_(defaultValue) {}

  int size() const { return static_cast<int>(times_.size()); }
  bool empty() const { return times_.empty(); }
  Real time(int k) const { return times_[static_cast<size_t>(k)]; }
  const T& value(int k) const { return values_[static_cast<size_t>(k)]; }
  const std::vector<Real>& times() const { return times_; }
  const std::vector<T>& values() const { return values_; }
  Interpolation mode() const { return mode_; }
  void setMode(Interpolation mode) { mode_ = mode; }

  /// Adds a key; its index, or an error when a key is already at that time.
  Result<int> insert(Real time, const T& v) {
    if (!std::isfinite(time)) return Error{"key time: must be finite"};
    const Result<int> at = detail::insertionIndex(times_, time, "key time");
    if (!at.ok()) return at;
    times_.insert(times_.begin() + at.value(), time);
    values_.insert(values_.begin() + at.value(), v);
    return at;
  }
  /// Sets the value of key k (its time unchanged).
  void setValue(int k, const T& v) { values_[static_cast<size_t>(k)] = v; }
  void remove(int k) {
    times_.erase(times_.begin() + k);
    values_.erase(values_.begin() + k);
  }
  /// Moves key k to a new time; its new index, or an error (and no change) when that time is taken.
  Result<int> move(int k, Real time) {
    const T v = value(k);
    const Real old = times_[static_cast<size_t>(k)];
    remove(k);
    const Result<int> at = insert(time, v);
    if (!at.ok()) static_cast<void>(insert(old, v));
    return at;
  }

  T valueAt(Real t) const { return evaluate(t, 0); }
  T velocityAt(Real t) const { return evaluate(t, 1); }      ///< per second
  T accelerationAt(Real t) const { return evaluate(t, 2); }  ///< per second²

  T evaluate(Real t, int derivative) const {
    const std::span<const Real> ts(times_);
    switch (mode_) {
      case Interpolation::Step:
        return derivative == 0 ? stepInterpolate(ts, values_, t, default_) : default_ * 0.0;
      case Interpolation::Linear:
        return linearInterpolate(ts, values_, t, derivative, default_);
      case Interpolation::CatmullRom:
        return catmullRom(ts, values_, t, derivative, default_);
      case Interpolation::NaturalCubic: {
        const std::vector<T> m = cubicSplineMoments(ts, values_, CubicEnds::Natural, default_ * 0.0, default_ * 0.0);
        return cubicSplineEvaluate(ts, values_, m, t, derivative, default_);
      }
    }
    return default_;
  }

 private:
  Interpolation mode_ = Interpolation::CatmullRom;
  T default_ = T(0.0);
  std::vector<Real> times_;
  std::vector<T> values_;
};

/// A joint rotation over time: unit quaternion keys, step, slerp or squad between them.
class RotationChannel {
 public:
  explicit RotationChannel(RotationInterpolation mode = RotationInterpolation::Squad) : mode_(mode) {}
  int size() const { return static_cast<int>(times_.size()); }
  bool empty() const { return times_.empty(); }
  Real time(int k) const { return times_[static_cast<size_t>(k)]; }
  const Quat& value(int k) const { return keys_[static_cast<size_t>(k)]; }
  const std::vector<Real>& times() const { return times_; }
  RotationInterpolation mode() const { return mode_; }
  void setMode(RotationInterpolation mode) { mode_ = mode; }

  Result<int> insert(Real time, const Quat& q);
  void setValue(int k, const Quat& q) { keys_[static_cast<size_t>(k)] = glm::normalize(q); }
  void remove(int k);
  Result<int> move(int k, Real time);
  Quat valueAt(Real t) const { return interpolateRotation(times_, keys_, t, mode_); }

 private:
  RotationInterpolation mode_;
  std::vector<Real> times_;
  std::vector<Quat> keys_;
};

}  // namespace pba::animation
