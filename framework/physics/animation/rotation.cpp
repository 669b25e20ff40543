// Quaternion interpolation: slerp and squad (see rotation.h for the sources and formulas).
#include "physics/animation/rotation.h"

#include <algorithm>
#include <cmath>

namespace pba::animation {

Vec3 quatLog(const Quat& qIn) {
  const Quat q = qIn.w < 0.0 ? -qIn : qIn;
  const Vec3 v(q.x, q.y, q.z);
  const Real s = glm::length(v);
  if (s < 1e-12) return v;  // log ≈ v for small angles (sin x ≈ x)
  const Real halfAngle = std::atan2(s, q.w);
  return (halfAngle / s) * v;
}

Quat quatExp(const Vec3& v) {
  const Real a = glm::length(v);
  if (a < 1e-12) return glm::normalize(Quat(1.0, v.x, v.y, v.z));
  const Vec3 n = (std::sin(a) / a) * v;
  return Quat(std::cos(a), n.x, n.y, n.z);
}

Quat slerp(const Quat& q0, const Quat& q1In, Real u) {
  Quat q1 = q1In;
  Real c = glm::dot(q0, q1);
  if (c < 0.0) {
    q1 = -q1;
    c = -c;
  }
  if (c > 1.0 - 1e-12) return glm::normalize(q0 + u * (q1 - q0));  // nearly equal: lerp is exact to 1e-12
  const Real theta = std::acos(std::min(c, 1.0));
  const Real s = std::sin(theta);
  return (std::sin((1.0 - u) * theta) / s) * q0 + (std::sin(u * theta) / s) * q1;
}

Quat squadControl(const Quat& previous, const Quat& current, const Quat& next) {
  const Quat inv = glm::conjugate(current);
  const Vec3 a = quatLog(inv * next);
  const Vec3 b = quatLog(inv * previous);
  return glm::normalize(current * quatExp(-0.25 * (a + b)));
}

Quat squad(const Quat& q0, const Quat& q1, const Quat& s0, const Quat& s1, Real u) {
  return glm::normalize(slerp(slerp(q0, q1, u), slerp(s0, s1, u), 2.0 * u * (1.0 - u)));
}

Quat interpolateRotation(std::span<const Real> times, const std::vector<Quat>& keys, Real t,
                         RotationInterpolation mode) {
  const size_t n = times.size();
  if (n == 0) return Quat(1.0, 0.0, 0.0, 0.0);
  if (n == 1 || t <= times.front()) return keys.front();
  if (t >= times.back()) return keys.back();
  const size_t i = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  if (mode == RotationInterpolation::Step) return keys[i];
  const Real u = (t - times[i]) / (times[i + 1] - times[i]);
  // Keys i−1..i+2 on one hemisphere, each relative to its predecessor.
  auto near = [](const Quat& ref, Quat q) { return glm::dot(ref, q) < 0.0 ? -q : q; };
  const Quat q1 = keys[i];
  const Quat q2 = near(q1, keys[i + 1]);
  if (mode == RotationInterpolation::Slerp) return slerp(q1, q2, u);
  const Quat q0 = i > 0 ? near(q1, keys[i - 1]) : q1;
  const Quat q3 = i + 2 < n ? near(q2, keys[i + 2]) : q2;
  const Quat s1 = i > 0 ? squadControl(q0, q1, q2) : q1;
  const Quat s2 = i + 2 < n ? squadControl(q1, q2, q3) : q2;
  return squad(q1, q2, s1, near(s1, s2), u);
}

Real rotationAngle(const Quat& a, const Quat& b) {
  // 2 atan2(|v|, |w|) of the relative rotation a⁻¹ b: accurate for small angles, where acos is not.
  const Quat r = glm::conjugate(a) * b;
  return 2.0 * std::atan2(glm::length(Vec3(r.x, r.y, r.z)), std::abs(r.w));
}

}  // namespace pba::animation
