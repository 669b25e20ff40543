#pragma once
// Rays, and the ray-sphere and ray-plane intersections that picking and the shape ray casts
// (raycast.h) share.
#include <optional>

#include "physics/core/types.h"

namespace pba {

/// A half-line origin + t·direction, t ≥ 0, in world space [m].
struct Ray {
  Vec3 origin{0.0};
  Vec3 direction{0.0, 0.0, -1.0};  ///< unit length
};

/// Distance t ≥ 0 to the first intersection of `ray` with a sphere, or nothing.
/// |o + t d − c|² = r² with |d| = 1 gives t² + 2bt + c₀ = 0, b = d·(o − c), c₀ = |o − c|² − r²;
/// the smaller root −b − √(b² − c₀) is the entry point (the larger one when the origin is inside).
std::optional<Real> intersectRaySphere(const Ray& ray, const Vec3& center, Real radius);

/// Point of `ray` at parameter t.
inline Vec3 pointAt(const Ray& ray, Real t) { return ray.origin + t * ray.direction; }

/// Intersection with the plane through `point` with normal `normal`; nothing when parallel or behind.
std::optional<Real> intersectRayPlane(const Ray& ray, const Vec3& point, const Vec3& normal);

}  // namespace pba
