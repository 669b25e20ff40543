#include "physics/ragdoll/tetrahedron.h"

#include <algorithm>
#include <cmath>

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

collision::Transform fitFrame(const std::array<Vec3, 4>& x, const Mat3& restInverse) {
  Mat3 r = Mat3(x[1] - x[0], x[2] - x[0], x[3] - x[0]) * restInverse;
  // Higham's iteration converges quadratically to the polar factor; a bone is nearly rigid, so a few
  // passes reach rounding (at most 6; it stops when a pass moves no entry by more than 10⁻¹⁴, where the
  // next would move them by ~10⁻²⁸). A reflected (inverted) tetrahedron keeps det < 0: flip one axis then.
  for (int k = 0; k < 6; ++k) {
    const Mat3 next = 0.5 * (r + glm::transpose(glm::inverse(r)));
    // The largest entry change, column by column as glm::compMax(glm::abs(·)) takes it; std::abs is one
    // mask where glm's abs branches (they differ only in the sign of a zero, which the test ignores).
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

}  // namespace pba::ragdoll
