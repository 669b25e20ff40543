#pragma once
// Collisions of cloth particles with planes, spheres, capsules, boxes and hulls (collision shapes at
// poses, their distances from collision/point_query.h), with Coulomb friction and the cloth's thickness,
// for every solver alike: positions are projected out at the end of a (sub)step and friction removes
// tangential motion in proportion to the penetration depth (Müller et al. 2007 §3.5; Macklin et al. 2014
// "Unified particle physics" §6.1). The force solvers then add Δx/h to the velocity, which is an
// inelastic contact: a resting particle loses exactly the g h it gained in the step.
//
// Every shape reduces to the sphere of CLOTH-4: a capsule is the sphere of its radius about the closest
// point of its axis (exact); a plane, box or hull is the sphere tangent at the particle's closest surface
// point (centre x − (d + R) n for signed distance d and normal n, any R > 0), which projects to the same
// point and gives friction the same normal, so the result is exact too.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "physics/collision/point_query.h"
#include "physics/collision/shapes.h"
#include "physics/collision/transform.h"
#include "physics/core/result.h"
#include "physics/core/types.h"

namespace pba::cloth {

using collision::SurfacePoint;

/// A collider: a collision shape at a pose (collision/shapes.h: a plane is local y = 0 with normal +y, a
/// capsule runs along local y), which may move, with the cloth's friction against it. A rigid body's
/// shape and pose serve as they are. Any shape but a mesh (checkColliders).
struct Collider {
  collision::Shape shape = collision::makePlane();
  /// The shape's frame in the world: its centre [m] (a point of a plane), e.g. (0, 0.6, 0), and rotation.
  collision::Transform pose;
  Vec3 velocity{0.0};   ///< [m/s] world, of a moving collider (friction acts on relative motion); e.g. (0, −0.4, 0)
  Real friction = 0.5;  ///< μ, Coulomb: static and kinetic alike; typical 0.3–0.5

  // The sizes below must be > 0 (an assert: scenes pass constants or range-checked parameters).
  /// The plane through `point` whose normal is the rotation's local y: the floor y = 0 by default.
  static Collider plane(const Vec3& point = Vec3(0.0), const Quat& rotation = Quat(1.0, 0.0, 0.0, 0.0));
  /// A sphere of radius [m] about `center`.
  static Collider sphere(const Vec3& center, Real radius);
  /// A capsule about `center` whose axis is the rotation's local y: end-sphere centres ±halfHeight [m]
  /// along it, radius [m].
  static Collider capsule(const Vec3& center, const Quat& rotation, Real halfHeight, Real radius);
  /// A box about `center`, its axes the rotation's, half extents [m].
  static Collider box(const Vec3& center, const Quat& rotation, const Vec3& halfExtents);
};

/// Success when every collider's shape has a point query (no mesh); else an error naming
/// `field`[k].shape.
Status checkColliders(std::span<const Collider> colliders, const std::string& field = "colliders");

/// Signed distance of x to the collider's surface [m] (negative inside) and the outward unit normal there.
SurfacePoint closestSurface(const Collider& c, const Vec3& x);

// ***** CLOTH-4: sphere collision projection with friction (Müller et al. 2007 §3.5; Macklin et al. 2014 §6.1) *****
// A particle ended a step at x [m], coming from xPrev (where it was at the start of the step, already
// moved with the collider). The sphere has centre c and radius r (the collider's radius plus the cloth's
// collision margin). Return where the particle ends after the contact:
// (1) Act only on a particle inside the sphere (leave it alone at the very centre: no direction).
// (2) Project it out onto the surface along the sphere's normal there; remember how deep it was.
// (3) Friction acts on the tangential part of the particle's motion over the step (from xPrev to its
//     projected position). Coulomb: it can undo at most μ times the depth of that motion. Within the
//     budget the particle sticks (all tangential motion undone); beyond it, it slides and loses exactly
//     the budget, never more, never reversing.
// Check: outside points are untouched; inside points end on the surface (|x' − c| = r) when there is no
// friction; μ = 0 leaves the tangential motion alone; friction never moves a point back past xPrev.
// *****
Vec3 projectOutOfSphere(const Vec3& x, const Vec3& xPrev, const Vec3& center, Real radius, Real friction);

/// Projects x (which started the step at xPrev; h [s] the step) out of the collider with margin [m] and
/// friction μ × frictionScale. Returns the new position; `depth` receives the penetration before it (≥ 0).
Vec3 collide(const Collider& c, const Vec3& x, const Vec3& xPrev, Real margin, Real h, Real* depth = nullptr,
             Real frictionScale = 1.0);

struct CollisionPassStats {
  std::size_t contacts = 0;  ///< particle–collider contacts
  Real deepest = 0.0;        ///< [m] deepest penetration before projection
};
/// Projects every free particle (w > 0) out of every collider. When `velocities` is not empty, adds the
/// projection's Δx/h to each velocity (the force-based solvers; XPBD derives v from x afterwards).
/// frictionScale 0 projects without friction (XPBD's first pass, before the constraints).
CollisionPassStats collideAll(std::span<const Collider> colliders, std::span<Vec3> x, std::span<const Vec3> xPrev,
                              std::span<const Real> inverseMass, Real margin, Real h, std::span<Vec3> velocities,
                              Real frictionScale = 1.0);

/// The frictionless projection of collideAll (positions only) for the listed particles (repeats allowed).
void collideListed(std::span<const Collider> colliders, std::span<const std::uint32_t> particles, std::span<Vec3> x,
                   std::span<const Vec3> xPrev, std::span<const Real> inverseMass, Real margin, Real h);

/// Smallest signed distance of any particle to any collider minus `margin` [m] (negative = penetration);
/// +∞ without colliders.
Real minColliderDistance(std::span<const Collider> colliders, std::span<const Vec3> x, Real margin);

}  // namespace pba::cloth
