#pragma once
// Collisions of cloth particles with planes, spheres, capsules and boxes, with Coulomb friction and the
// cloth's thickness, for every solver alike: positions are projected out at the end of a (sub)step and
// friction removes tangential motion in proportion to the penetration depth (Müller et al. 2007 §3.5;
// Macklin et al. 2014 "Unified particle physics" §6.1). The force solvers then add Δx/h to the velocity,
// which is an inelastic contact: a resting particle loses exactly the g h it gained in the step.
//
// Every shape reduces to the sphere of CLOTH-4: a capsule is the sphere of its radius about the closest
// point of its axis (exact); a plane or a box is the sphere tangent at the particle's closest surface point
// (centre x − (d + R) n for signed distance d and normal n, any R > 0), which projects to the same point
// and gives friction the same normal, so the result is exact too.
#include <cstdint>
#include <span>
#include <vector>

#include "physics/core/types.h"

namespace pba::cloth {

enum class ColliderShape { Plane, Sphere, Capsule, Box };

struct Collider {
  ColliderShape shape = ColliderShape::Plane;
  Vec3 center{0.0};                      ///< [m] sphere, capsule and box centre; a point of a plane
  Quat orientation{1.0, 0.0, 0.0, 0.0};  ///< capsule axis = local y; box axes; plane normal = local y
  Real radius = 0.5;                     ///< [m] sphere and capsule
  Real halfLength = 0.5;                 ///< [m] capsule: half the distance between its end-sphere centres
  Vec3 halfExtents{0.5};                 ///< [m] box
  Vec3 velocity{0.0};                    ///< [m/s] of a moving collider (friction acts on relative motion)
  Real friction = 0.5;                   ///< μ, Coulomb: static and kinetic alike
};

/// Signed distance of x to the surface [m] (negative inside) and the outward unit normal there.
struct SurfacePoint {
  Real distance = 0.0;
  Vec3 normal{0.0, 1.0, 0.0};
};
SurfacePoint closestSurface(const Collider& c, const Vec3& x);

// ***** CLOTH-7: signed distance and normal of a box (Müller et al. 2007 §3.5: collision constraints) *****
// The box is centred at the origin of its own frame, its faces perpendicular to the axes, halfExtents
// [m] from the centre (all > 0). p [m] is the particle in that frame (the caller rotates in and out).
// Return the signed distance of p to the box's surface [m] (negative inside) and the outward unit normal
// at the closest surface point, both in the box frame.
// (1) Per axis, work out how far p lies outside the slab between the two faces of that axis (negative
//     when it lies between them).
// (2) Outside the box (outside at least one slab): the closest point clamps p into the box; the distance
//     and the normal come from the part of p that clamping removes (a face, an edge or a corner is the
//     closest feature depending on how many slabs p is outside), with the normal's signs those of p.
// (3) Inside: the particle leaves through the nearest face; the distance is the least negative of the
//     three slab values and the normal is that face's axis, pointing to the side p is on (+ at 0).
// Check: a point above the top face by d has distance d and normal +y; one beyond an edge or corner lies
// at the Euclidean distance to it, with a unit normal along the offset; the centre is at minus the
// smallest half extent; |normal| = 1 everywhere.
// *****
SurfacePoint boxSurface(const Vec3& halfExtents, const Vec3& p);

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
