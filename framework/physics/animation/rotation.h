#pragma once
// Interpolation of rotations (Shoemake 1985, "Animating rotation with quaternion curves", SIGGRAPH;
// Dam, Koch & Lillholm 1998, "Quaternions, Interpolation and Animation", §6.2–6.4).
//
//   slerp(q0, q1, u) = q0 (q0⁻¹ q1)^u : the great arc, at constant angular speed, of angle θ with
//                      cos θ = q0·q1 (after flipping q1 to the same hemisphere: the shorter way round).
//   log(q) = (θ/2) n for q = (cos θ/2, sin θ/2 n);  exp is its inverse.
//   squad(q_i, q_i+1, s_i, s_i+1, u) = slerp(slerp(q_i, q_i+1, u), slerp(s_i, s_i+1, u), 2u(1 − u)),
//   s_i = q_i exp(−(log(q_i⁻¹ q_i+1) + log(q_i⁻¹ q_i−1))/4): a C¹ curve through the keys (Shoemake's
//   spherical analogue of a cubic Bézier; the end keys use s = q).
#include <span>
#include <vector>

#include "physics/core/types.h"

namespace pba::animation {

/// log of a unit quaternion: (θ/2) n, with |result| ∈ [0, π/2] after choosing the hemisphere w ≥ 0.
Vec3 quatLog(const Quat& q);
/// exp of a pure quaternion (0, v): (cos|v|, sin|v| v/|v|).
Quat quatExp(const Vec3& v);
/// Shortest-arc spherical linear interpolation; unit length; exact at u = 0 and u = 1 (up to sign).
Quat slerp(const Quat& q0, const Quat& q1, Real u);
/// Shoemake's inner control point s_i of key i between its neighbours.
Quat squadControl(const Quat& previous, const Quat& current, const Quat& next);
/// Spherical quadrangle interpolation between q0 and q1 with controls s0, s1.
Quat squad(const Quat& q0, const Quat& q1, const Quat& s0, const Quat& s1, Real u);

enum class RotationInterpolation {
  Step,   ///< the key at or before t
  Slerp,  ///< great arcs between keys (C⁰: the angular velocity jumps at the keys)
  Squad,  ///< Shoemake's squad (C¹)
};

/// Rotation at t through keys at strictly increasing times (neighbouring keys are brought to the same
/// hemisphere first). No key → identity; outside the keys → the nearest end key.
Quat interpolateRotation(std::span<const Real> times, const std::vector<Quat>& keys, Real t,
                         RotationInterpolation mode);

/// Angle [rad] of the rotation between two unit quaternions (0 to π).
Real rotationAngle(const Quat& a, const Quat& b);

}  // namespace pba::animation
