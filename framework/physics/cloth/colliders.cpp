#include "physics/cloth/colliders.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/exercises/not_implemented.h"

namespace pba::cloth {
namespace {

constexpr Real kMinDistance = 1e-12;  // [m] a particle this close to a sphere's centre has no normal

SurfacePoint boxSurface(const Collider& c, const Vec3& x) {
  const Quat q = glm::normalize(c.orientation);
  const Vec3 p = glm::conjugate(q) * (x - c.center);  // box frame
  const Vec3 a = glm::abs(p) - c.halfExtents;         // per-axis distance outside the slab
  SurfacePoint s;
  if (a.x > 0.0 || a.y > 0.0 || a.z > 0.0) {  // outside: distance to the closest point of the box
    const Vec3 outside = glm::max(a, Vec3(0.0));
    s.distance = glm::length(outside);
    Vec3 n = outside * glm::sign(p);
    s.normal = q * (n / s.distance);
    return s;
  }
  int axis = 0;  // inside: leave through the nearest face
  if (a.y > a[axis]) axis = 1;
  if (a.z > a[axis]) axis = 2;
  Vec3 n(0.0);
  n[axis] = p[axis] >= 0.0 ? 1.0 : -1.0;
  s.distance = a[axis];
  s.normal = q * n;
  return s;
}

}  // namespace

SurfacePoint closestSurface(const Collider& c, const Vec3& x) {
  switch (c.shape) {
    case ColliderShape::Plane: {
      const Vec3 n = glm::normalize(c.orientation) * Vec3(0.0, 1.0, 0.0);
      return {glm::dot(n, x - c.center), n};
    }
    case ColliderShape::Sphere:
    case ColliderShape::Capsule: {
      Vec3 core = c.center;
      if (c.shape == ColliderShape::Capsule) {
        const Vec3 axis = glm::normalize(c.orientation) * Vec3(0.0, 1.0, 0.0);
        core += std::clamp(glm::dot(x - c.center, axis), -c.halfLength, c.halfLength) * axis;
      }
      const Vec3 r = x - core;
      const Real l = glm::length(r);
      return {l - c.radius, l > kMinDistance ? r / l : Vec3(0.0, 1.0, 0.0)};
    }
    case ColliderShape::Box: return boxSurface(c, x);
  }
  return {};
}

Vec3 projectOutOfSphere([[maybe_unused]] const Vec3& x, [[maybe_unused]] const Vec3& xPrev,
                        [[maybe_unused]] const Vec3& center, [[maybe_unused]] Real radius,
                        [[maybe_unused]] Real friction) {
  // BEGIN SOLUTION
  const Vec3 offset = x - center;
  const Real length = glm::length(offset);
  const Real d = length - radius;
  if (d >= 0.0 || length < kMinDistance) return x;
  const Vec3 n = offset / length;
  Vec3 projected = center + radius * n;
  const Vec3 motion = projected - xPrev;
  const Vec3 tangential = motion - glm::dot(motion, n) * n;
  const Real slip = glm::length(tangential);
  const Real bound = friction * (-d);
  projected -= slip <= bound ? tangential : tangential * (bound / slip);
  return projected;
  // END SOLUTION
  // STUB: return exercises::notImplemented("CLOTH-4", x, xPrev, center, radius, friction);
}

Vec3 collide(const Collider& c, const Vec3& x, const Vec3& xPrev, Real margin, Real h, Real* depth) {
  const SurfacePoint s = closestSurface(c, x);
  if (depth) *depth = std::max(0.0, margin - s.distance);
  if (s.distance >= margin) return x;
  const Vec3 previous = xPrev + h * c.velocity;  // friction sees the motion relative to the collider
  if (c.shape == ColliderShape::Sphere) return projectOutOfSphere(x, previous, c.center, c.radius + margin, c.friction);
  if (c.shape == ColliderShape::Capsule) {
    const Vec3 axis = glm::normalize(c.orientation) * Vec3(0.0, 1.0, 0.0);
    const Vec3 core = c.center + std::clamp(glm::dot(x - c.center, axis), -c.halfLength, c.halfLength) * axis;
    return projectOutOfSphere(x, previous, core, c.radius + margin, c.friction);
  }
  // Plane and box: the tangent sphere of radius R at the closest surface point (see the header).
  const Real R = std::max(1.0, -2.0 * s.distance);
  return projectOutOfSphere(x, previous, x - (s.distance + R) * s.normal, R + margin, c.friction);
}

CollisionPassStats collideAll(std::span<const Collider> colliders, std::span<Vec3> x, std::span<const Vec3> xPrev,
                              std::span<const Real> inverseMass, Real margin, Real h, std::span<Vec3> velocities) {
  CollisionPassStats stats;
  if (colliders.empty()) return stats;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (inverseMass[i] == 0.0) continue;
    for (const Collider& c : colliders) {
      Real depth = 0.0;
      const Vec3 projected = collide(c, x[i], xPrev[i], margin, h, &depth);
      if (depth <= 0.0) continue;
      ++stats.contacts;
      stats.deepest = std::max(stats.deepest, depth);
      if (!velocities.empty()) velocities[i] += (projected - x[i]) / h;
      x[i] = projected;
    }
  }
  return stats;
}

Real minColliderDistance(std::span<const Collider> colliders, std::span<const Vec3> x, Real margin) {
  Real best = std::numeric_limits<Real>::infinity();
  for (const Collider& c : colliders) {
    for (const Vec3& p : x) best = std::min(best, closestSurface(c, p).distance - margin);
  }
  return best;
}

// Start-up probe: tells the lab whether CLOTH-4 is still a stub.
PBA_EXERCISE_PROBE(projectOutOfSphere(Vec3(0.0, 0.5, 0.0), Vec3(0.0, 1.0, 0.0), Vec3(0.0), 1.0, 0.5));

}  // namespace pba::cloth
