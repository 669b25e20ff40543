#pragma once
// The one header of numeric aliases for the physics library (docs/architecture.md §2).
// Physics runs in double precision; rendering converts to float at upload.
// SI units throughout: m, kg, s, N, rad. Right-handed, y up.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace pba {

using Real = double;
using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Vec4 = glm::dvec4;
using Mat3 = glm::dmat3;
using Mat4 = glm::dmat4;
using Quat = glm::dquat;

/// World up axis (y up) and the default gravitational acceleration [m/s²], standard gravity.
inline constexpr Vec3 kUp{0.0, 1.0, 0.0};
inline constexpr Real kStandardGravity = 9.80665;  // [m/s²]
inline constexpr Real kPi = 3.14159265358979323846;

/// Degrees appear only at the user interface; this is the one conversion helper (docs/architecture.md §2).
constexpr Real degToRad(Real degrees) { return degrees * (kPi / 180.0); }
constexpr Real radToDeg(Real radians) { return radians * (180.0 / kPi); }

/// True when every component is finite (no NaN, no Inf).
bool isFinite(Real value);
bool isFinite(const Vec3& v);

}  // namespace pba
