#include "physics/collision/toi.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/collision/gjk.h"

namespace pba::collision {

Transform Sweep::at(Real t) const {
  Quat q1s = q1;
  if (glm::dot(q0, q1s) < 0.0) q1s = -q1s;  // the short way round
  return {c0 + t * (c1 - c0), glm::normalize(q0 * (1.0 - t) + q1s * t)};
}

namespace {
// Angle [rad] of the rotation from q0 to q1.
Real rotationAngle(const Quat& q0, const Quat& q1) {
  const Real d = std::min(1.0, std::abs(glm::dot(q0, q1)));
  return 2.0 * std::acos(d);
}
}  // namespace

namespace {
// Signed distance of convex `a` to the plane shape at `plane` (normal from a toward the plane).
SignedDistance toPlane(const Shape& a, const Transform& xa, const Transform& plane) {
  const CoreVertices vertices(a);
  const Vec3 n = plane.rotate(kUp);
  SignedDistance d;
  d.separation = std::numeric_limits<Real>::max();
  for (const Vec3& v : vertices)
    d.separation = std::min(d.separation, glm::dot(n, xa.apply(v) - plane.position) - a.radius);
  d.normal = -n;
  return d;
}
}  // namespace

ToiResult timeOfImpact(const Shape& a, const Sweep& sa, const Shape& b, const Sweep& sb, Real target, Real tolerance) {
  const bool plane = b.kind == ShapeKind::Plane;
  const ConvexProxy pa = makeProxy(a), pb = plane ? ConvexProxy{} : makeProxy(b);
  // Over the whole step, no point of A moves more than |Δc_A| + θ_A r_A (nlerp sweeps the angle
  // monotonically), so along the normal n the gap closes by at most
  //   μ = n·(Δc_A − Δc_B) + θ_A r_A + θ_B r_B   per unit of t.
  const Real angularBound =
      rotationAngle(sa.q0, sa.q1) * boundingRadius(a) + rotationAngle(sb.q0, sb.q1) * boundingRadius(b);
  const Vec3 relative = (sa.c1 - sa.c0) - (sb.c1 - sb.c0);
  ToiResult out;
  Real t = 0.0;
  constexpr int kMaxIterations = 64;
  for (out.iterations = 0; out.iterations < kMaxIterations; ++out.iterations) {
    const Transform xa = sa.at(t), xb = sb.at(t);
    const SignedDistance d = plane ? toPlane(a, xa, xb) : signedDistance(pa, xa, pb, xb);
    if (!d.valid) {
      out.state = ToiResult::State::Failed;
      out.t = t;
      return out;
    }
    if (d.separation <= target + tolerance) {
      out.state = t == 0.0 && d.separation < target - tolerance ? ToiResult::State::Overlapping : ToiResult::State::Hit;
      out.t = t;
      return out;
    }
    const Real approach = glm::dot(relative, d.normal) + angularBound;
    if (approach <= 0.0) break;  // moving apart along the normal faster than anything can rotate in
    t += (d.separation - target) / approach;
    if (t >= 1.0) break;
  }
  out.state = ToiResult::State::Separated;
  out.t = 1.0;
  return out;
}

}  // namespace pba::collision
