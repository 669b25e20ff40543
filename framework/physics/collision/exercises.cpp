#include "physics/collision/exercises.h"

#include <cmath>

#include "physics/exercises/not_implemented.h"

namespace pba::collision {

// ***** COLL-1: Sphere–sphere and sphere–plane contact (Ericson, Real-Time Collision Detection §4.3.1,
// §5.2.2) *****
// (1) The spheres overlap when the distance between the centres is less than the sum of the radii.
// (2) The normal points from the first centre to the second; the depth is how much the radii exceed the
//     distance.
// (3) The contact point lies on the line of centres, halfway between the two surfaces.
// (4) Coincident centres: any unit normal will do (use +y), the depth is the sum of the radii.
// *****
std::optional<SphereContact> sphereSphereContact(const Vec3& ca, Real ra, const Vec3& cb, Real rb) {
  // BEGIN SOLUTION
  const Vec3 d = cb - ca;
  const Real distance = glm::length(d);
  if (distance >= ra + rb) return std::nullopt;
  const Vec3 n = distance > 1e-12 ? d / distance : kUp;
  const Real depth = ra + rb - distance;
  const Vec3 surfaceA = ca + ra * n, surfaceB = cb - rb * n;
  return SphereContact{n, depth, 0.5 * (surfaceA + surfaceB)};
  // END SOLUTION
  // STUB: return exercises::notImplemented("COLL-1", std::optional<SphereContact>{}, ca, ra, cb, rb);
}

// ***** COLL-1 (continued): sphere against a plane *****
// (1) The signed distance of the centre from the plane is the normal's dot product with the offset from
//     a point of the plane.
// (2) The sphere touches when that distance is less than the radius; the depth is the difference.
// (3) The contact point is halfway between the sphere's lowest point and the plane.
// *****
std::optional<SphereContact> spherePlaneContact(const Vec3& center, Real radius, const Vec3& planePoint,
                                                const Vec3& planeNormal) {
  // BEGIN SOLUTION
  const Real height = glm::dot(planeNormal, center - planePoint);
  if (height >= radius) return std::nullopt;
  const Real depth = radius - height;
  const Vec3 lowest = center - radius * planeNormal;
  return SphereContact{planeNormal, depth, lowest + 0.5 * depth * planeNormal};
  // END SOLUTION
  // STUB: return exercises::notImplemented("COLL-1", std::optional<SphereContact>{}, center, radius, planePoint, planeNormal);
}

// ***** COLL-2: One separating-axis test for two boxes (Ericson §4.4.1; Gottschalk, Lin & Manocha 1996) *****
// Inputs: two oriented boxes (centre [m], rotation whose columns are the box's axes in world axes, half
// extents [m]) and one unit axis L in world axes. Output: the gap [m] between the boxes' projections on
// L: positive when L separates them, negative (minus the overlap) when not.
// (1) Project the centres on L: how far apart are they along L, whatever their order?
// (2) Each box projects onto an interval about its centre's projection. Work out its half-length: how
//     much does each of the box's three axes, with its half extent, stretch along L?
// (3) The gap follows from the distance between the centres and the two half-lengths.
// Check: two unit cubes side by side along x with a 1 m gap give 1 on L = x and a negative gap on y; the
// result does not change when L is negated; turning a cube by 45° about z lengthens its half-length on x
// to √2/2 times its side.
// *****
Real obbSeparationOnAxis(const Obb& a, const Obb& b, const Vec3& axis) {
  // BEGIN SOLUTION
  const Mat3 ra = glm::mat3_cast(a.rotation), rb = glm::mat3_cast(b.rotation);
  Real radiusA = 0.0, radiusB = 0.0;
  for (int k = 0; k < 3; ++k) {
    radiusA += a.halfExtents[k] * std::abs(glm::dot(ra[k], axis));
    radiusB += b.halfExtents[k] * std::abs(glm::dot(rb[k], axis));
  }
  return std::abs(glm::dot(b.center - a.center, axis)) - radiusA - radiusB;
  // END SOLUTION
  // STUB: return exercises::notImplemented("COLL-2", 0.0, a, b, axis);
}

// Start-up probes: tell the lab which exercises are still stubs.
PBA_EXERCISE_PROBE(sphereSphereContact(Vec3(0.0), 1.0, Vec3(1.0, 0.0, 0.0), 1.0));
PBA_EXERCISE_PROBE(spherePlaneContact(Vec3(0.0, 0.5, 0.0), 1.0, Vec3(0.0), kUp));
PBA_EXERCISE_PROBE(obbSeparationOnAxis(Obb{}, Obb{}, Vec3(1.0, 0.0, 0.0)));

}  // namespace pba::collision
