#pragma once
// The rigid-body exercises (docs/architecture.md §5) and the course's single-impulse collision response built from
// them (the `tumble` scene). The world's solver (world.h) moves every orientation with RIGID-2 and
// finds box contacts through COLL-2 (collision/exercises.h); for inertia and impulses it has its own
// general routes (Mirtich's integrals of any hull, sequential impulses with accumulated clamping), so
// RIGID-1, -3 and -4 run in the `tumble` scene. The world's contact solver takes the effective mass of
// every contact row from RIGID-5.
//
// Conventions of this file (Baraff & Witkin 2001, "Rigid Body Dynamics II", §8): a contact between
// bodies A and B at world point p with unit normal n pointing from B toward A; arms r = p − x; the
// relative normal velocity v_rel = n·(v_A(p) − v_B(p)) is negative while they approach. An impulse
// j n is applied to A and −j n to B.
#include "physics/core/types.h"

namespace pba::rigid {

// RIGID-1
/// Inertia tensor [kg·m²] of a solid box of mass m [kg] and half extents h [m] about its centre, in
/// world axes for the orientation q (body axes → world axes).
Mat3 boxInertiaTensor(Real mass, const Vec3& halfExtents, const Quat& q);

// RIGID-2
/// The orientation after a step h [s] under a constant angular velocity ω in world axes [rad/s]: the
/// exact turn over the step, renormalised. The rigid world's integrator calls it for every body.
Quat integrateOrientation(const Quat& q, const Vec3& omega, Real h);

/// What the impulse formulas need of a body.
struct ImpulseBody {
  Real inverseMass = 0.0;     ///< [1/kg], 0 for static
  Mat3 inverseInertia{0.0};   ///< [1/(kg·m²)] world axes
  Vec3 position{0.0};         ///< [m] centre of mass
  Vec3 velocity{0.0};         ///< [m/s]
  Vec3 angularVelocity{0.0};  ///< [rad/s]
  Vec3 velocityAt(const Vec3& p) const { return velocity + glm::cross(angularVelocity, p - position); }
};

// RIGID-3
/// Magnitude j ≥ 0 of the collision impulse with restitution e (0 when not approaching): after +j n on A
/// and −j n on B the normal relative velocity at the point is −e times what it was.
Real collisionImpulse(const ImpulseBody& a, const ImpulseBody& b, const Vec3& point, const Vec3& normal,
                      Real restitution);

// RIGID-4
/// The Coulomb friction impulse on A (−it on B) that accompanies a normal impulse j: it opposes the
/// tangential relative velocity, stops it if that takes at most μ j, and is clamped to μ j otherwise.
Vec3 frictionImpulse(const ImpulseBody& a, const ImpulseBody& b, const Vec3& point, const Vec3& normal,
                     Real normalImpulse, Real friction);

// RIGID-5
/// The effective mass [kg] of one contact row along the unit direction d (the normal or a tangent) at a
/// point with arms r_A, r_B from the two centres of mass (world axes): the impulse along d that changes
/// the relative velocity of the two points along d by 1 m/s. 0 when neither side can respond (K = 0).
/// A side that cannot move passes 0 for its inverse mass and inverse inertia. The world's contact
/// solver (contact_solver.cpp, prepareContact) calls it for each point's normal and two tangent rows.
Real contactEffectiveMass(Real inverseMassA, const Mat3& inverseInertiaA, const Vec3& armA, Real inverseMassB,
                          const Mat3& inverseInertiaB, const Vec3& armB, const Vec3& direction);

}  // namespace pba::rigid
