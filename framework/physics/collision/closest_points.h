#pragma once
// Closest-point queries (Ericson, Real-Time Collision Detection §5.1), all in one frame.
#include "physics/core/types.h"

namespace pba::collision {

/// Closest point to p on segment [a, b]; t ∈ [0, 1] its parameter (a + t(b − a)). §5.1.2.
Vec3 closestPointOnSegment(const Vec3& p, const Vec3& a, const Vec3& b, Real* t = nullptr);

/// Closest points c1 = p1 + s(q1 − p1) and c2 = p2 + t(q2 − p2) of two segments. §5.1.9: minimise
/// |c1 − c2|² over the unit square; clamp s, recompute t, clamp t and recompute s. Degenerate segments
/// (points) are handled. For parallel segments an arbitrary pair of the closest set is returned.
struct SegmentPair {
  Vec3 onFirst{0.0}, onSecond{0.0};
  Real s = 0.0, t = 0.0;
};
SegmentPair closestPointsSegments(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2);

/// Closest point to p on triangle abc, by the Voronoi regions of its vertices, edges and face. §5.1.5.
/// region: 0–2 vertex a, b, c; 3–5 edges ab, bc, ca; 6 the face.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int* region = nullptr);

/// Closest point to p (box frame) on or in the box |x_i| ≤ h_i: clamp each coordinate. §5.1.3.
Vec3 closestPointOnBox(const Vec3& p, const Vec3& halfExtents);

}  // namespace pba::collision
