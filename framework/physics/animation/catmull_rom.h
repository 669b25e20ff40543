#pragma once
// Catmull-Rom splines through keyframes at non-uniform times (CMU asst4, "Splines"), evaluated as
// Hermite segments (hermite.h).
//
// Between knots k1 = (t1, p1) and k2 = (t2, p2), with neighbours k0 and k3:
//   tangent at k1: (p2 − p0)/(t2 − t0),   tangent at k2: (p3 − p1)/(t3 − t1)   [value per second]
// Normalising time into u = (t − t1)/h, h = t2 − t1, multiplies each tangent by h (hermite.h).
// Boundary rules of asst4: no knot → the default value T(); one knot → that value everywhere;
// t ≤ first knot → first value; t ≥ last knot → last value; a missing outer knot is mirrored,
// k0 = k1 − (k2 − k1) and k3 = k2 + (k2 − k1) (times and values alike).
//
// The segment search and the tangents depend only on the knot times: catmullRomSegment returns each
// tangent as weights on the values of the four knots around the interval, so one non-template function
// serves every value type.
#include <array>
#include <span>
#include <vector>

#include "physics/animation/hermite.h"
#include "physics/core/types.h"

namespace pba::animation {

enum class SegmentRegion {
  Empty,     ///< no knots: the default value
  Constant,  ///< one knot, or t outside the knots: the value of knot `key`
  Interior,  ///< t inside [t_key, t_key+1): a Hermite segment
};

/// Where t falls among the knots and the segment's tangents as weights on knot values.
struct CatmullRomSegment {
  SegmentRegion region = SegmentRegion::Empty;
  int key = 0;        ///< Constant: the knot that holds; Interior: the first knot k1 of the interval
  Real u = 0.0;       ///< [1] normalised time in [0, 1) (Interior only)
  Real length = 1.0;  ///< [s] interval length h = t2 − t1 (Interior only)
  /// Tangent at k1 times h (d/du): Σ_s startTangent[s] · value(key − 1 + s), s = 0..3; weights of
  /// knots that do not exist are 0 (a mirrored knot is folded into the weights of the real ones).
  std::array<Real, 4> startTangent{};
  std::array<Real, 4> endTangent{};  ///< the same for the tangent at k2
};

/// The segment of t among strictly increasing knot times. Exercise ANIM-2.
CatmullRomSegment catmullRomSegment(std::span<const Real> times, Real t);

/// Σ_s weights[s] · values[key − 1 + s] over the knots that exist.
template <typename T>
T weightedKnots(const std::vector<T>& values, int key, const std::array<Real, 4>& weights) {
  T sum = T(0.0) * 0.0;
  for (int s = 0; s < 4; ++s) {
    const int k = key - 1 + s;
    if (weights[static_cast<size_t>(s)] != 0.0 && k >= 0 && k < static_cast<int>(values.size()))
      sum = sum + weights[static_cast<size_t>(s)] * values[static_cast<size_t>(k)];
  }
  return sum;
}

/// Value (derivative 0), velocity (1, per second) or acceleration (2, per second²) of the Catmull-Rom
/// spline through (times, values) at t. Outside the knots and on constant parts the derivatives are 0.
template <typename T>
T catmullRom(std::span<const Real> times, const std::vector<T>& values, Real t, int derivative = 0,
             const T& defaultValue = T(0.0)) {
  const CatmullRomSegment s = catmullRomSegment(times, t);
  const T zero = defaultValue * 0.0;
  if (s.region == SegmentRegion::Empty) return derivative == 0 ? defaultValue : zero;
  if (s.region == SegmentRegion::Constant) return derivative == 0 ? values[static_cast<size_t>(s.key)] : zero;
  const T m1 = weightedKnots(values, s.key, s.startTangent);
  const T m2 = weightedKnots(values, s.key, s.endTangent);
  const T d =
      hermite(values[static_cast<size_t>(s.key)], m1, values[static_cast<size_t>(s.key + 1)], m2, s.u, derivative);
  Real scale = 1.0;
  for (int k = 0; k < derivative; ++k) scale /= s.length;
  return scale * d;
}

}  // namespace pba::animation
