#pragma once
// The collision-detection exercises (docs/architecture.md §5; workbook chapter 4). The narrow
// phase (narrow_phase.h) calls COLL-1 for every round pair (spheres and capsules, through the closest
// points of their cores); its tests feed the exercises fixed inputs, so each is graded alone.
#include <optional>
#include <utility>
#include <vector>

#include "physics/collision/aabb.h"
#include "physics/core/types.h"

namespace pba::collision {

/// A single contact: unit normal, penetration depth (> 0 when overlapping) and the point midway between
/// the two surfaces.
struct SphereContact {
  Vec3 normal{0.0};  ///< from the first shape toward the second (plane: the plane's normal)
  Real depth = 0.0;  ///< [m]
  Vec3 point{0.0};   ///< [m]
};

// COLL-1
/// Two spheres (centres c, radii r): the contact when they overlap, else nothing.
std::optional<SphereContact> sphereSphereContact(const Vec3& ca, Real ra, const Vec3& cb, Real rb);
/// A sphere against the plane through `planePoint` with unit normal `planeNormal` (solid below): the
/// contact when the sphere dips below the plane, else nothing. The normal is the plane's.
std::optional<SphereContact> spherePlaneContact(const Vec3& center, Real radius, const Vec3& planePoint,
                                                const Vec3& planeNormal);

/// An oriented box: centre, rotation (columns of R are its axes in world coordinates), half extents.
struct Obb {
  Vec3 center{0.0};  ///< [m]
  Quat rotation{1, 0, 0, 0};
  Vec3 halfExtents{0.5};  ///< [m]
};

// COLL-2
/// The separating-axis test of two boxes on one unit axis L: the gap between their projections,
/// positive when L separates them, negative (the overlap) when not.
Real obbSeparationOnAxis(const Obb& a, const Obb& b, const Vec3& axis);

// COLL-3
/// Sort and sweep on one axis (0 = x, 1 = y, 2 = z): `order` lists the indices of `boxes` taking part and
/// comes back sorted by their lower bound along the axis (kept from call to call, so it is nearly sorted
/// already); every pair (i, j) of overlapping boxes that are not both static is appended to `pairs` once.
/// BroadPhase's sweep-and-prune method calls it.
void sortAndSweep(const std::vector<Aabb>& boxes, const std::vector<char>& isStatic, int axis, std::vector<int>& order,
                  std::vector<std::pair<int, int>>& pairs);

}  // namespace pba::collision
