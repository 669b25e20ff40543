#pragma once
// Interpolating splines for comparison with Catmull-Rom (catmull_rom.h): step, linear, and the C²
// cubic spline with natural (zero second derivative) or clamped (given end slopes) ends. Templated
// over the value type like the others; the same boundary rules (no knot → default, one knot or t
// outside the knots → the nearest end value).
//
// Cubic spline (de Boor, "A Practical Guide to Splines", ch. IV; Burden & Faires §3.5). With
// h_i = t_i+1 − t_i and unknown second derivatives M_i at the knots, on [t_i, t_i+1]:
//   S(t) = M_i (t_i+1 − t)³/(6h_i) + M_i+1 (t − t_i)³/(6h_i)
//        + (p_i/h_i − M_i h_i/6)(t_i+1 − t) + (p_i+1/h_i − M_i+1 h_i/6)(t − t_i).
// C¹ at the interior knots gives the tridiagonal system
//   h_i−1 M_i−1 + 2(h_i−1 + h_i) M_i + h_i M_i+1 = 6[(p_i+1 − p_i)/h_i − (p_i − p_i−1)/h_i−1],
// closed by M_0 = M_n−1 = 0 (natural), or by the end slopes s0, s1 (clamped):
//   2h_0 M_0 + h_0 M_1 = 6[(p_1 − p_0)/h_0 − s0],  h_n−2 M_n−2 + 2h_n−2 M_n−1 = 6[s1 − (p_n−1 − p_n−2)/h_n−2].
// Solved by the Thomas algorithm (the matrix is diagonally dominant, so no pivoting is needed).
#include <algorithm>
#include <optional>
#include <span>
#include <vector>

#include "physics/core/types.h"

namespace pba::animation {

enum class CubicEnds {
  Natural,  ///< zero second derivative at both ends
  Clamped,  ///< given first derivatives at both ends
};

namespace detail {
/// Index i of the interval [t_i, t_i+1) holding t, for t strictly inside the knots.
inline int intervalOf(std::span<const Real> times, Real t) {
  return static_cast<int>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
}

/// The boundary rules of the derivative-taking splines: with no knot, the default value; with one knot or
/// t at or outside the ends, the nearest end value; every derivative there is zero. Empty when t lies
/// strictly inside the knots, where the spline itself is evaluated.
template <typename T>
std::optional<T> outsideKnots(std::span<const Real> times, const std::vector<T>& values, Real t, int derivative,
                              const T& defaultValue) {
  const T zero = defaultValue * 0.0;
  if (times.empty()) return derivative == 0 ? defaultValue : zero;
  if (times.size() == 1 || t <= times.front()) return derivative == 0 ? values.front() : zero;
  if (t >= times.back()) return derivative == 0 ? values.back() : zero;
  return std::nullopt;
}
}  // namespace detail

/// Step (derivative 0 only; the others are 0): the value of the last knot at or before t.
template <typename T>
T stepInterpolate(std::span<const Real> times, const std::vector<T>& values, Real t, const T& defaultValue = T(0.0)) {
  if (times.empty()) return defaultValue;
  if (t <= times.front()) return values.front();
  if (t >= times.back()) return values.back();
  return values[static_cast<size_t>(detail::intervalOf(times, t))];
}

/// Piecewise linear: value (0) or velocity (1); the acceleration (2) is 0 inside the intervals.
template <typename T>
T linearInterpolate(std::span<const Real> times, const std::vector<T>& values, Real t, int derivative = 0,
                    const T& defaultValue = T(0.0)) {
  if (std::optional<T> end = detail::outsideKnots(times, values, t, derivative, defaultValue)) return *end;
  const T zero = defaultValue * 0.0;
  const size_t i = static_cast<size_t>(detail::intervalOf(times, t));
  const Real h = times[i + 1] - times[i];
  const T slope = (1.0 / h) * (values[i + 1] - values[i]);
  if (derivative == 1) return slope;
  if (derivative >= 2) return zero;
  return values[i] + (t - times[i]) * slope;
}

/// The knots' second derivatives M_i of the cubic spline (see the header comment).
template <typename T>
std::vector<T> cubicSplineMoments(std::span<const Real> times, const std::vector<T>& values, CubicEnds ends,
                                  const T& startSlope, const T& endSlope) {
  const size_t n = times.size();
  const T zero = startSlope * 0.0;
  std::vector<T> moments(n, zero);
  if (n < 2 || (n == 2 && ends == CubicEnds::Natural)) return moments;
  std::vector<Real> diag(n, 1.0), upper(n, 0.0), lower(n, 0.0);
  std::vector<T> rhs(n, zero);
  auto h = [&](size_t i) { return times[i + 1] - times[i]; };
  auto slope = [&](size_t i) { return (1.0 / h(i)) * (values[i + 1] - values[i]); };
  for (size_t i = 1; i + 1 < n; ++i) {
    lower[i] = h(i - 1);
    diag[i] = 2.0 * (h(i - 1) + h(i));
    upper[i] = h(i);
    rhs[i] = 6.0 * (slope(i) - slope(i - 1));
  }
  if (ends == CubicEnds::Clamped) {
    diag[0] = 2.0 * h(0);
    upper[0] = h(0);
    rhs[0] = 6.0 * (slope(0) - startSlope);
    lower[n - 1] = h(n - 2);
    diag[n - 1] = 2.0 * h(n - 2);
    rhs[n - 1] = 6.0 * (endSlope - slope(n - 2));
  }
  // Thomas algorithm: forward elimination, back substitution.
  for (size_t i = 1; i < n; ++i) {
    const Real f = lower[i] / diag[i - 1];
    diag[i] -= f * upper[i - 1];
    rhs[i] = rhs[i] - f * rhs[i - 1];
  }
  moments[n - 1] = (1.0 / diag[n - 1]) * rhs[n - 1];
  for (size_t i = n - 1; i-- > 0;) moments[i] = (1.0 / diag[i]) * (rhs[i] - upper[i] * moments[i + 1]);
  return moments;
}

/// Value (0), velocity (1) or acceleration (2) of the cubic spline with precomputed moments.
template <typename T>
T cubicSplineEvaluate(std::span<const Real> times, const std::vector<T>& values, const std::vector<T>& moments, Real t,
                      int derivative = 0, const T& defaultValue = T(0.0)) {
  if (std::optional<T> end = detail::outsideKnots(times, values, t, derivative, defaultValue)) return *end;
  const T zero = defaultValue * 0.0;
  const size_t i = static_cast<size_t>(detail::intervalOf(times, t));
  const Real h = times[i + 1] - times[i];
  const Real a = times[i + 1] - t, b = t - times[i];
  const T& m0 = moments[i];
  const T& m1 = moments[i + 1];
  const T c0 = (1.0 / h) * values[i] - (h / 6.0) * m0;
  const T c1 = (1.0 / h) * values[i + 1] - (h / 6.0) * m1;
  switch (derivative) {
    case 0:
      return (a * a * a / (6.0 * h)) * m0 + (b * b * b / (6.0 * h)) * m1 + a * c0 + b * c1;
    case 1:
      return (-a * a / (2.0 * h)) * m0 + (b * b / (2.0 * h)) * m1 - c0 + c1;
    case 2:
      return (a / h) * m0 + (b / h) * m1;
    default:
      return zero;
  }
}

}  // namespace pba::animation
