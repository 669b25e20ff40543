#include "physics/collision/exercises.h"

#include <cmath>

#include "physics/exercises/not_implemented.h"

namespace pba::collision {

// ***** COLL-1: Sphere–sphere and sphere–plane contact (Ericson, Real-Time Collision Detection §4.3.1,
// §5.2.2) *****
// Inputs: the centres [m] (world) and radii [m] of two spheres. Output: nothing when they do not overlap;
// otherwise the unit normal from the first sphere toward the second, the depth [m] (> 0) and the contact
// point [m] midway between the two surfaces.
// (1) Decide from the centres and the radii whether the spheres overlap (touching is not overlapping).
// (2) The normal, and how deep the two surfaces interpenetrate along it.
// (3) Each sphere's deepest surface point along the normal; the contact point lies between them.
// (4) Coincident centres leave the direction undefined: choose +y; the depth is then as large as it gets.
// Check: the normal has unit length and points from a to b; the depth shrinks to 0 as the spheres separate;
// swapping the spheres flips the normal and keeps the depth and the point.
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
// Inputs: the sphere's centre and radius [m], a point of the plane and its unit normal (the solid lies
// below). Output: nothing when the sphere is above the plane; otherwise the plane's normal, the depth [m]
// and the point midway between the sphere's lowest point and the plane.
// (1) How high is the centre above the plane, measured along its normal (negative below)?
// (2) Compare that height with the radius: touching or not, and how deep.
// (3) The sphere's lowest point toward the plane; the contact point is halfway to the plane.
// Check: a sphere resting exactly on the plane gives nothing; a centre below the plane gives a depth larger
// than the radius; tilting the plane tilts the normal and moves the point with it.
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

// ***** COLL-3: Sort and sweep, a broad phase (Baraff 1992 §4, "sweep and prune"; Ericson §7.5.2) *****
// Inputs: axis-aligned boxes [m] (world), which of them are static, the axis to sweep along (0, 1, 2), and
// `order`, the indices of the boxes taking part, sorted by the last call (the bodies moved a little since).
// Output: `order` sorted by each box's lower bound along the axis; appended to `pairs`: each pair of
// indices whose boxes overlap, once, unless both are static (static bodies never collide).
// (1) Sort `order` by the lower bound along the axis. It is nearly sorted already: which simple sort is
//     close to linear then, and which of the standard sorts would throw that away?
// (2) Sweep: walk the sorted boxes; for each, look only at the boxes after it whose lower bound does not
//     lie beyond its upper bound along the axis. Why can you stop at the first one that does?
// (3) Along the axis those candidates overlap; a pair is reported only when the boxes overlap on all
//     three axes (aabb.h) and are not both static.
// Check: the pairs are exactly those of testing every pair with overlaps() (brute force); boxes that
// only touch count as overlapping; a second call with the same boxes leaves `order` as it is and finds
// the same pairs.
// *****
void sortAndSweep([[maybe_unused]] const std::vector<Aabb>& boxes, [[maybe_unused]] const std::vector<char>& isStatic,
                  [[maybe_unused]] int axis, [[maybe_unused]] std::vector<int>& order,
                  [[maybe_unused]] std::vector<std::pair<int, int>>& pairs) {
  // BEGIN SOLUTION
  for (std::size_t i = 1; i < order.size(); ++i) {  // insertion sort: nearly linear on a nearly sorted list
    const int id = order[i];
    const Real key = boxes[id].min[axis];
    std::size_t j = i;
    while (j > 0 && boxes[order[j - 1]].min[axis] > key) {
      order[j] = order[j - 1];
      --j;
    }
    order[j] = id;
  }
  for (std::size_t i = 0; i < order.size(); ++i) {
    const int first = order[i];
    for (std::size_t j = i + 1; j < order.size() && boxes[order[j]].min[axis] <= boxes[first].max[axis]; ++j) {
      const int second = order[j];
      if (!(isStatic[first] && isStatic[second]) && overlaps(boxes[first], boxes[second]))
        pairs.emplace_back(first, second);
    }
  }
  // END SOLUTION
  // STUB: exercises::markNotImplemented("COLL-3");
}

// Start-up probes: tell the lab which exercises are still stubs.
PBA_EXERCISE_PROBE(sphereSphereContact(Vec3(0.0), 1.0, Vec3(1.0, 0.0, 0.0), 1.0));
PBA_EXERCISE_PROBE(spherePlaneContact(Vec3(0.0, 0.5, 0.0), 1.0, Vec3(0.0), kUp));
PBA_EXERCISE_PROBE(obbSeparationOnAxis(Obb{}, Obb{}, Vec3(1.0, 0.0, 0.0)));
static void probeSortAndSweep() {
  std::vector<int> order;
  std::vector<std::pair<int, int>> pairs;
  sortAndSweep({}, {}, 0, order, pairs);
}
PBA_EXERCISE_PROBE(probeSortAndSweep());

}  // namespace pba::collision
