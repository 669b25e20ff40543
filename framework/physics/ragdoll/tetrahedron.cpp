#include "physics/ragdoll/tetrahedron.h"

#include <algorithm>
#include <cmath>

#include "physics/exercises/not_implemented.h"

namespace pba::ragdoll {

std::array<Vec3, 4> tetrahedronOffsets(const Vec3& h) {
  const Vec3 s = h / std::sqrt(3.0);
  return {Vec3(s.x, s.y, s.z), Vec3(s.x, -s.y, -s.z), Vec3(-s.x, s.y, -s.z), Vec3(-s.x, -s.y, s.z)};
}

Weights barycentric(const std::array<Vec3, 4>& x, const Vec3& point) {
  const Mat3 edges(x[1] - x[0], x[2] - x[0], x[3] - x[0]);
  const Vec3 c = glm::inverse(edges) * (point - x[0]);
  return {1.0 - c.x - c.y - c.z, c.x, c.y, c.z};
}

Mat3 restEdgesInverse(const std::array<Vec3, 4>& r) {
  return glm::inverse(Mat3(r[1] - r[0], r[2] - r[0], r[3] - r[0]));
}

// ***** RAG-5: the box's frame from its four particles (Ragdoll paper §3.1, "Display") *****
// Inputs: the particles x0..x3 [m] in world axes, and the inverse of the rest edge matrix (columns
// r1 − r0, r2 − r0, r3 − r0 of the rest offsets in the box's frame). Output: the box's centre (the mean
// of the particles, as given) and the rotation of the box's frame into world axes.
// (1) Build the deformation that carries the rest edges onto the current edges (world edges times the
//     given inverse). It is a rotation only while the bone is perfectly rigid; after relaxation it is a
//     rotation times a small stretch.
// (2) Keep only its rotation part, the polar factor (the rotation nearest to it): find it with Higham's
//     Newton iteration (workbook §6.7, RAG-5). Stop when a pass changes no entry by more than about 1e-14,
//     and after six passes at most (it converges quadratically from a nearly rigid bone).
// (3) An inverted tetrahedron has a polar factor with determinant −1, which no rotation is: turn it into a
//     proper rotation by flipping one of its axes.
// (4) Return the centre with the rotation as a unit quaternion.
// Check: a rigidly moved tetrahedron gives back its rotation exactly; a rotation times a symmetric
// positive stretch gives back the rotation alone; the result is always unit length.
// *****
collision::Transform fitFrame(const std::array<Vec3, 4>& x, const Mat3& restInverse) {
  // BEGIN SOLUTION
  Mat3 r = Mat3(x[1] - x[0], x[2] - x[0], x[3] - x[0]) * restInverse;
  for (int k = 0; k < 6; ++k) {
    const Mat3 next = 0.5 * (r + glm::transpose(glm::inverse(r)));
    Real change = 0.0;
    for (int c = 0; c < 3; ++c) {
      const Vec3 d = next[c] - r[c];
      change = std::max(change, std::max(std::max(std::abs(d.x), std::abs(d.y)), std::abs(d.z)));
    }
    r = next;
    if (change < 1e-14) break;
  }
  if (glm::determinant(r) < 0.0) r[0] = -r[0];
  return {centroid(x), glm::normalize(glm::quat_cast(r))};
  // END SOLUTION
  // STUB: return exercises::notImplemented("RAG-5", collision::Transform{centroid(x)}, restInverse);  // unrotated
}

Mat3 pointMassInertia(const std::array<Vec3, 4>& x, const Weights& m) {
  Vec3 c(0.0);
  Real total = 0.0;
  for (int i = 0; i < 4; ++i) c += m[i] * x[i], total += m[i];
  c /= total;
  Mat3 inertia(0.0);
  for (int i = 0; i < 4; ++i) {
    const Vec3 r = x[i] - c;
    inertia += m[i] * (glm::dot(r, r) * Mat3(1.0) - glm::outerProduct(r, r));
  }
  return inertia;
}

// Start-up probe: tells the lab whether RAG-5 is still a stub.
PBA_EXERCISE_PROBE(fitFrame(tetrahedronOffsets(Vec3(0.1, 0.2, 0.3)),
                            restEdgesInverse(tetrahedronOffsets(Vec3(0.1, 0.2, 0.3)))));

}  // namespace pba::ragdoll
