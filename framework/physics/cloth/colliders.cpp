#include "physics/cloth/colliders.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "physics/exercises/not_implemented.h"

namespace pba::cloth {
namespace {

using collision::ShapeKind;

/// A collider with what every query needs precomputed: its posed shape (unit rotation, local y axis: the
/// plane's normal, the capsule's axis) and a bounding radius for a quick rejection.
struct Prepared {
  const Collider* c = nullptr;
  collision::PosedShape shape;
  Real bound = std::numeric_limits<Real>::infinity();  ///< [m] no point farther from the centre touches it
};

Prepared prepare(const Collider& c) {
  Prepared p;
  p.c = &c;
  p.shape = collision::posed(c.shape, c.pose);
  if (c.shape.kind != ShapeKind::Plane) p.bound = collision::boundingRadius(c.shape);
  return p;
}

inline const Vec3& centerOf(const Prepared& p) { return p.shape.pose.position; }

/// True when x is farther than margin above the plane through `point` with unit normal `normal` (the
/// distance surfacePoint computes for a plane).
inline bool clearOfPlane(const Vec3& normal, const Vec3& point, const Vec3& x, Real margin) {
  return glm::dot(normal, x - point) >= margin;
}
/// True when x lies outside the ball of radius r about `center`.
inline bool clearOfBall(const Vec3& center, Real r, const Vec3& x) {
  const Vec3 d = x - center;
  return glm::dot(d, d) > r * r;
}
/// True when x is certainly farther than margin from the collider: above a plane (exact), outside the
/// bounding sphere of the others.
bool clearOf(const Prepared& p, const Vec3& x, Real margin) {
  if (p.c->shape.kind == ShapeKind::Plane) return clearOfPlane(p.shape.axis, centerOf(p), x, margin);
  return clearOfBall(centerOf(p), p.bound + margin, x);
}

Vec3 collidePrepared(const Prepared& p, const Vec3& x, const Vec3& xPrev, Real margin, Real h, Real* depth,
                     Real frictionScale);

Collider posedCollider(Result<collision::Shape> shape, const Vec3& center, const Quat& rotation) {
  assert(shape.ok() && "Collider: a sphere's, capsule's or box's sizes must be > 0");
  Collider c;
  c.shape = std::move(shape).value();
  c.pose = {center, rotation};
  return c;
}

}  // namespace

Collider Collider::plane(const Vec3& point, const Quat& rotation) {
  Collider c;
  c.pose = {point, rotation};
  return c;
}
Collider Collider::sphere(const Vec3& center, Real radius) {
  return posedCollider(collision::makeSphere(radius), center, Quat(1.0, 0.0, 0.0, 0.0));
}
Collider Collider::capsule(const Vec3& center, const Quat& rotation, Real halfHeight, Real radius) {
  return posedCollider(collision::makeCapsule(halfHeight, radius), center, rotation);
}
Collider Collider::box(const Vec3& center, const Quat& rotation, const Vec3& halfExtents) {
  return posedCollider(collision::makeBox(halfExtents), center, rotation);
}

Status checkColliders(std::span<const Collider> colliders, const std::string& field) {
  for (std::size_t k = 0; k < colliders.size(); ++k) {
    const Status s = collision::checkPointQueryShape(colliders[k].shape, field + "[" + std::to_string(k) + "].shape");
    if (!s) return s;
  }
  return Status::success();
}

SurfacePoint closestSurface(const Collider& c, const Vec3& x) { return surfacePoint(prepare(c).shape, x); }

Vec3 projectOutOfSphere([[maybe_unused]] const Vec3& x, [[maybe_unused]] const Vec3& xPrev,
                        [[maybe_unused]] const Vec3& center, [[maybe_unused]] Real radius,
                        [[maybe_unused]] Real friction) {
  // BEGIN SOLUTION
  const Vec3 offset = x - center;
  const Real length = glm::length(offset);
  const Real d = length - radius;
  if (d >= 0.0 || length < collision::kNoDirectionDistance) return x;
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

namespace {
Vec3 collidePrepared(const Prepared& p, const Vec3& x, const Vec3& xPrev, Real margin, Real h, Real* depth,
                     Real frictionScale) {
  const Collider& c = *p.c;
  const SurfacePoint s = surfacePoint(p.shape, x);
  if (depth) *depth = std::max(0.0, margin - s.distance);
  if (s.distance >= margin) return x;
  const Vec3 previous = xPrev + h * c.velocity;  // friction sees the motion relative to the collider
  const Real mu = frictionScale * c.friction;
  if (c.shape.kind == ShapeKind::Sphere)
    return projectOutOfSphere(x, previous, centerOf(p), c.shape.radius + margin, mu);
  if (c.shape.kind == ShapeKind::Capsule)
    return projectOutOfSphere(x, previous, collision::capsuleAxisPoint(p.shape, x), c.shape.radius + margin, mu);
  // Plane, box and hull: the tangent sphere of radius R at the closest surface point (see the header).
  const Real R = std::max(1.0, -2.0 * s.distance);
  return projectOutOfSphere(x, previous, x - (s.distance + R) * s.normal, R + margin, mu);
}
}  // namespace

Vec3 collide(const Collider& c, const Vec3& x, const Vec3& xPrev, Real margin, Real h, Real* depth,
             Real frictionScale) {
  return collidePrepared(prepare(c), x, xPrev, margin, h, depth, frictionScale);
}

namespace {
/// Projects particle i out of collider p, which it may touch; counts the contact into stats. Kept out of
/// line: most queries end at clearOf (the falling part, a pile's upper layers), and with the projection
/// inlined into the pass every query paid a call that saved and restored a dozen registers
/// (docs/performance-cloth.md has the figures).
[[gnu::noinline]] void collideTouching(const Prepared& p, std::size_t i, std::span<Vec3> x, std::span<const Vec3> xPrev,
                                       Real margin, Real h, std::span<Vec3> velocities, Real frictionScale,
                                       CollisionPassStats& stats) {
  Real depth = 0.0;
  const Vec3 projected = collidePrepared(p, x[i], xPrev[i], margin, h, &depth, frictionScale);
  if (depth <= 0.0) return;
  ++stats.contacts;
  stats.deepest = std::max(stats.deepest, depth);
  if (!velocities.empty()) velocities[i] += (projected - x[i]) / h;
  x[i] = projected;
}

/// One sweep of collideEach with its clear test; out of line, so that each test's loop has the registers
/// to itself (inlined together, the plane's loop kept its axis and centre on the stack).
template <typename IndexOf, typename Clear>
[[gnu::noinline]] void sweepParticles(const Prepared& p, std::size_t count, IndexOf indexOf, Clear clear,
                                      std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> inverseMass,
                                      Real margin, Real h, std::span<Vec3> velocities, Real frictionScale,
                                      CollisionPassStats& stats) {
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = indexOf(k);
    if (inverseMass[i] != 0.0 && !clear(x[i]))
      collideTouching(p, i, x, xPrev, margin, h, velocities, frictionScale, stats);
  }
}

/// Projects the particles `indexOf` names (those with inverse mass ≠ 0) out of collider p. The clear test
/// runs with the plane's axis and centre, or the bounding ball's centre and radius, held in registers:
/// most queries end there. A particle's colliders are visited one after the other, so a pass that calls
/// this collider by collider gives each particle exactly what visiting its colliders in turn would,
/// provided that no particle is listed twice.
/// `indexOf(k)` names the k-th of `count` particles. (A callable rather than an iota view: clang 14,
/// which builds the fuzz preset, cannot compile libstdc++ 12's <ranges>.)
template <typename IndexOf>
void collideEach(const Prepared& p, std::size_t count, IndexOf indexOf, std::span<Vec3> x, std::span<const Vec3> xPrev,
                 std::span<const Real> inverseMass, Real margin, Real h, std::span<Vec3> velocities, Real frictionScale,
                 CollisionPassStats& stats) {
  if (p.c->shape.kind == ShapeKind::Plane) {
    const Vec3 axis = p.shape.axis, center = centerOf(p);
    sweepParticles(
        p, count, indexOf, [axis, center, margin](const Vec3& xi) { return clearOfPlane(axis, center, xi, margin); }, x,
        xPrev, inverseMass, margin, h, velocities, frictionScale, stats);
  } else {
    const Vec3 center = centerOf(p);
    const Real r = p.bound + margin;
    sweepParticles(
        p, count, indexOf, [center, r](const Vec3& xi) { return clearOfBall(center, r, xi); }, x, xPrev, inverseMass,
        margin, h, velocities, frictionScale, stats);
  }
}

std::vector<Prepared> prepareAll(std::span<const Collider> colliders) {
  std::vector<Prepared> prepared;
  prepared.reserve(colliders.size());
  for (const Collider& c : colliders) prepared.push_back(prepare(c));
  return prepared;
}
}  // namespace

CollisionPassStats collideAll(std::span<const Collider> colliders, std::span<Vec3> x, std::span<const Vec3> xPrev,
                              std::span<const Real> inverseMass, Real margin, Real h, std::span<Vec3> velocities,
                              Real frictionScale) {
  CollisionPassStats stats;
  if (colliders.empty()) return stats;
  // Collider by collider: every particle once, so the same results as particle by particle.
  for (const Prepared& p : prepareAll(colliders)) {
    collideEach(
        p, x.size(), [](std::size_t k) { return k; }, x, xPrev, inverseMass, margin, h, velocities, frictionScale,
        stats);
  }
  return stats;
}

void collideListed(std::span<const Collider> colliders, std::span<const std::uint32_t> particles, std::span<Vec3> x,
                   std::span<const Vec3> xPrev, std::span<const Real> inverseMass, Real margin, Real h) {
  if (colliders.empty()) return;
  const std::vector<Prepared> prepared = prepareAll(colliders);
  CollisionPassStats unused;
  if (prepared.size() == 1) {  // the order per particle cannot differ
    collideEach(
        prepared.front(), particles.size(), [particles](std::size_t k) { return std::size_t{particles[k]}; }, x, xPrev,
        inverseMass, margin, h, {}, 0.0, unused);
    return;
  }
  // A particle may be listed more than once: each listing visits all its colliders in turn.
  for (const std::uint32_t i : particles) {
    if (inverseMass[i] == 0.0) continue;
    for (const Prepared& p : prepared) {
      if (!clearOf(p, x[i], margin)) collideTouching(p, i, x, xPrev, margin, h, {}, 0.0, unused);
    }
  }
}

Real minColliderDistance(std::span<const Collider> colliders, std::span<const Vec3> x, Real margin) {
  Real best = std::numeric_limits<Real>::infinity();
  for (const Collider& c : colliders) {
    const Prepared p = prepare(c);
    for (const Vec3& v : x) best = std::min(best, surfacePoint(p.shape, v).distance - margin);
  }
  return best;
}

// Start-up probe: tells the lab whether CLOTH-4 is still a stub.
PBA_EXERCISE_PROBE(projectOutOfSphere(Vec3(0.0, 0.5, 0.0), Vec3(0.0, 1.0, 0.0), Vec3(0.0), 1.0, 0.5));

}  // namespace pba::cloth
