#pragma once
// Interpolation of rotations (Shoemake 1985, "Animating rotation with quaternion curves", SIGGRAPH;
// Dam, Koch & Lillholm 1998, "Quaternions, Interpolation and Animation", §6.2–6.4).
//
//   slerp(q0, q1, u) = q0 (q0⁻¹ q1)^u : the great arc, at constant angular speed, of angle θ with
//                      cos θ = q0·q1 (after flipping q1 to the same hemisphere: the shorter way round).
//   log(q) = (θ/2) n for q = (cos θ/2, sin θ/2 n);  exp is its inverse.
//   squad: Shoemake's spherical analogue of a cubic Bézier between two keys, a C¹ curve through the keys
//   (exercise ANIM-5, squadSegment; its theory is workbook §7.2).
#include <span>
#include <vector>

#include "physics/core/enum_names.h"
#include "physics/core/types.h"

namespace pba::animation {

/// log of a unit quaternion: (θ/2) n, with |result| ∈ [0, π/2] after choosing the hemisphere w ≥ 0.
Vec3 quatLog(const Quat& q);
/// exp of a pure quaternion (0, v): (cos|v|, sin|v| v/|v|).
Quat quatExp(const Vec3& v);
/// Shortest-arc spherical linear interpolation; unit length; exact at u = 0 and u = 1 (up to sign).
Quat slerp(const Quat& q0, const Quat& q1, Real u);
// ANIM-5
/// Shoemake's squad on one segment: the rotation at u ∈ [0, 1] between the keys q1 (u = 0) and q2
/// (u = 1), whose neighbouring keys are q0 (before q1) and q3 (after q2). All four are unit and already
/// on one hemisphere, each relative to its predecessor. At an end of the channel a key has no neighbour
/// (hasPrevious or hasNext false: q0 or q3 is then ignored) and is its own inner control point.
Quat squadSegment(const Quat& q0, const Quat& q1, const Quat& q2, const Quat& q3, bool hasPrevious, bool hasNext,
                  Real u);

enum class RotationInterpolation {
  Step,   ///< the key at or before t
  Slerp,  ///< great arcs between keys (C⁰: the angular velocity jumps at the keys)
  Squad,  ///< Shoemake's squad (C¹)
};
inline constexpr auto kRotationInterpolationNames =
    enumNames<RotationInterpolation>({{RotationInterpolation::Step, "step"},
                                      {RotationInterpolation::Slerp, "slerp"},
                                      {RotationInterpolation::Squad, "squad"}});

/// Rotation at t through keys at strictly increasing times (neighbouring keys are brought to the same
/// hemisphere first). No key → identity; outside the keys → the nearest end key.
Quat interpolateRotation(std::span<const Real> times, const std::vector<Quat>& keys, Real t,
                         RotationInterpolation mode);

/// Angle [rad] of the rotation between two unit quaternions (0 to π).
Real rotationAngle(const Quat& a, const Quat& b);

}  // namespace pba::animation
