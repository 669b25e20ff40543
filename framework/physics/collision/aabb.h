#pragma once
// Axis-aligned bounding boxes in world space (Ericson, Real-Time Collision Detection §4.2).
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/core/types.h"

namespace pba::collision {

struct Aabb {
  Vec3 min{std::numeric_limits<Real>::max()};   ///< [m]
  Vec3 max{-std::numeric_limits<Real>::max()};  ///< [m]

  bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
  Vec3 center() const { return 0.5 * (min + max); }
  Vec3 extents() const { return 0.5 * (max - min); }
  /// Surface area [m²]: the cost measure of the surface area heuristic.
  Real area() const {
    const Vec3 d = max - min;
    return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
  void grow(const Vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  Aabb fattened(Real margin) const { return {min - Vec3(margin), max + Vec3(margin)}; }
  bool contains(const Aabb& o) const {
    return min.x <= o.min.x && min.y <= o.min.y && min.z <= o.min.z && o.max.x <= max.x && o.max.y <= max.y &&
           o.max.z <= max.z;
  }
};

inline Aabb merge(const Aabb& a, const Aabb& b) { return {glm::min(a.min, b.min), glm::max(a.max, b.max)}; }

inline bool overlaps(const Aabb& a, const Aabb& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y && a.min.z <= b.max.z &&
         b.min.z <= a.max.z;
}

/// 1/d per component, with ±1e100 in place of ±inf for (nearly) zero components, so that the slab
/// test below never computes 0·inf (the tests run with floating-point traps on).
inline Vec3 safeInverse(const Vec3& d) {
  Vec3 r;
  for (int k = 0; k < 3; ++k) r[k] = std::abs(d[k]) < 1e-100 ? (d[k] < 0.0 ? -1e100 : 1e100) : 1.0 / d[k];
  return r;
}

/// Slab test (Ericson §5.3.3): does the segment origin + t·direction, t ∈ [0, maxT], meet the box?
/// invDirection = safeInverse(direction).
inline bool raySegmentHitsAabb(const Vec3& origin, const Vec3& invDirection, Real maxT, const Aabb& box) {
  Real t0 = 0.0, t1 = maxT;
  for (int k = 0; k < 3; ++k) {
    Real a = (box.min[k] - origin[k]) * invDirection[k];
    Real b = (box.max[k] - origin[k]) * invDirection[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace pba::collision
