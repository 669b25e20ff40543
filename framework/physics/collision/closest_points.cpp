#include "physics/collision/closest_points.h"

#include <algorithm>

namespace pba::collision {

Vec3 closestPointOnSegment(const Vec3& p, const Vec3& a, const Vec3& b, Real* tOut) {
  const Vec3 ab = b - a;
  const Real denom = glm::dot(ab, ab);
  Real t = denom > 0.0 ? std::clamp(glm::dot(p - a, ab) / denom, 0.0, 1.0) : 0.0;
  if (tOut) *tOut = t;
  return a + t * ab;
}

SegmentPair closestPointsSegments(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const Real a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  constexpr Real kTiny = 1e-300;
  Real s = 0.0, t = 0.0;
  if (a <= kTiny && e <= kTiny) {
    // both points
  } else if (a <= kTiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const Real c = glm::dot(d1, r);
    if (e <= kTiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const Real b = glm::dot(d1, d2);
      const Real denom = a * e - b * b;  // ≥ 0; 0 when parallel
      s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return {p1 + s * d1, p2 + t * d2, s, t};
}

Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int* region) {
  auto set = [&](int r) {
    if (region) *region = r;
  };
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const Real d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return set(0), a;
  const Vec3 bp = p - b;
  const Real d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return set(1), b;
  const Real vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return set(3), a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const Real d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return set(2), c;
  const Real vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return set(5), a + (d2 / (d2 - d6)) * ac;
  const Real va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return set(4), b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const Real sum = va + vb + vc;
  if (!(sum > 0.0)) return set(0), a;  // degenerate triangle
  const Real denom = 1.0 / sum;
  set(6);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

Vec3 closestPointOnBox(const Vec3& p, const Vec3& h) { return glm::clamp(p, -h, h); }

}  // namespace pba::collision
