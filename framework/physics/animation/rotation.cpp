// Quaternion interpolation: slerp and squad (see rotation.h for the sources; squad is exercise ANIM-5).
#include "physics/animation/rotation.h"

#include <algorithm>
#include <cmath>

#include "physics/exercises/not_implemented.h"

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

// ***** ANIM-5: Shoemake's squad between two keys (Shoemake 1985; Dam, Koch & Lillholm 1998, §6.2–6.4) *****
// Inputs: four unit keys on one hemisphere (q1 and q2 bound the segment, q0 and q3 are their neighbours
// when hasPrevious / hasNext), and u ∈ [0, 1] (the segment's own parameter, not seconds).
// (1) The inner control point of a key with both neighbours: in that key's own frame, take the logarithms
//     (quatLog) of the rotations to its two neighbours. Work out from workbook §7.2 which multiple of
//     their sum, mapped back with quatExp and applied to the key, gives a curve that leaves the key in the
//     direction it arrived (the condition the section derives it from). A key at an end of the channel is
//     its own control point.
// (2) Bring the second control point to the hemisphere of the first.
// (3) Interpolate twice along great arcs (slerp): once between the keys, once between the control points,
//     both at u; then between those two results with the weight of workbook §7.2, which vanishes at both
//     ends of the segment.
// (4) Return a unit quaternion.
// Check: u = 0 and u = 1 give the keys; keys about one axis give a rotation about that axis whose angle is
// the scalar formula of §7.2; the angular velocity is continuous across an interior key on uniform knots.
// *****
Quat squadSegment(const Quat& q0, const Quat& q1, const Quat& q2, const Quat& q3, bool hasPrevious, bool hasNext,
                  Real u) {
  // BEGIN SOLUTION
  const auto control = [](const Quat& previous, const Quat& current, const Quat& next) {
    const Quat inverse = glm::conjugate(current);
    return glm::normalize(current * quatExp(-0.25 * (quatLog(inverse * next) + quatLog(inverse * previous))));
  };
  const Quat s1 = hasPrevious ? control(q0, q1, q2) : q1;
  Quat s2 = hasNext ? control(q1, q2, q3) : q2;
  if (glm::dot(s1, s2) < 0.0) s2 = -s2;
  return glm::normalize(slerp(slerp(q1, q2, u), slerp(s1, s2, u), 2.0 * u * (1.0 - u)));
  // END SOLUTION
  // STUB: return exercises::notImplemented("ANIM-5", q1, q0, q2, q3, hasPrevious, hasNext, u);  // holds the key
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
  return squadSegment(q0, q1, q2, q3, i > 0, i + 2 < n, u);  // ANIM-5
}

Real rotationAngle(const Quat& a, const Quat& b) {
  // 2 atan2(|v|, |w|) of the relative rotation a⁻¹ b: accurate for small angles, where acos is not.
  const Quat r = glm::conjugate(a) * b;
  return 2.0 * std::atan2(glm::length(Vec3(r.x, r.y, r.z)), std::abs(r.w));
}

// Start-up probe: tells the lab whether ANIM-5 is still a stub.
PBA_EXERCISE_PROBE(squadSegment(Quat(1, 0, 0, 0), Quat(1, 0, 0, 0), glm::angleAxis(0.5, kUp), glm::angleAxis(1.0, kUp),
                                true, true, 0.5));

}  // namespace pba::animation
