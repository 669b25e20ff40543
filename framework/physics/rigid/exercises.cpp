#include "physics/rigid/exercises.h"

#include <algorithm>
#include <cmath>

#include "physics/exercises/not_implemented.h"

namespace pba::rigid {

// ***** RIGID-1: The inertia tensor of a box in world axes (Baraff & Witkin 2001, "Rigid Body
// Dynamics I", §2.9–2.10) *****
// Inputs: the mass [kg], the half extents h [m] (the full sides are twice as long) and the orientation q
// (body axes → world axes). Output: the inertia tensor [kg·m²] about the centre of mass that maps an
// angular velocity in WORLD axes to the angular momentum in world axes.
// (1) In the box's own axes: work out from the integral of B&W §2.9 (or its table of solids) which
//     entries the tensor of a box centred on its axes has, and which of the three sides each depends on.
// (2) Into world axes: the body tensor expects an ω written in body axes. Chain the changes of frame
//     that take a world ω into the body frame, apply the body tensor, and bring the result back; write
//     the chain as one matrix (glm is column-major).
// Check: a cube's tensor is a multiple of the identity in any orientation; stretching the box along its
// x axis leaves I_xx alone and raises the other two (q the identity); the tensor is symmetric and keeps
// its trace when q turns; L computed in world axes equals L computed in body axes and rotated.
// *****
Mat3 boxInertiaTensor(Real mass, const Vec3& halfExtents, const Quat& q) {
  // BEGIN SOLUTION
  const Vec3 side = 2.0 * halfExtents;
  const Vec3 s2 = side * side;
  Mat3 inertia(0.0);
  inertia[0][0] = mass / 12.0 * (s2.y + s2.z);
  inertia[1][1] = mass / 12.0 * (s2.z + s2.x);
  inertia[2][2] = mass / 12.0 * (s2.x + s2.y);
  const Mat3 r = glm::mat3_cast(q);
  return r * inertia * glm::transpose(r);
  // END SOLUTION
  // STUB: return exercises::notImplemented("RIGID-1", Mat3(mass), halfExtents, q);
}

// ***** RIGID-2: Updating the orientation over one step (Baraff & Witkin 2001, §4.2; Catto, "Numerical
// Methods", GDC 2015) *****
// Inputs: the orientation q (unit, body → world), the angular velocity ω [rad/s] in WORLD axes, held
// constant over the step, and the step h [s]. Output: the orientation after the step, of unit length.
// The rigid world and the `tumble` scene move every body's orientation with this function.
// (1) Over the step the body turns about one fixed world axis. Work out that axis (a unit vector) and
//     the angle [rad] it turns through.
// (2) Build the unit quaternion of that turn from the half angle (B&W's appendix on quaternions).
// (3) Apply it to q: ω is in world axes, so decide on which side of q it multiplies. Bring the product
//     back to unit length (rounding drifts it over many steps).
// (4) A body that does not turn (ω = 0, or an angle too small to define an axis) must keep q exactly;
//     for tiny angles find a form of the vector part that needs no division by |ω|.
// Check: ω = 0 leaves q unchanged; N steps of h turn a body by exactly N h |ω| about ω's axis; a small
// step about z turns the body's x axis towards +y; B&W's derivative ½ ω q is the first-order term.
// *****
Quat integrateOrientation(const Quat& q, const Vec3& omega, Real h) {
  // BEGIN SOLUTION
  const Real speed = glm::length(omega);
  const Real angle = speed * h;
  if (angle < 1e-300) return q;
  // Half-angle form; for tiny angles sin(x/2)/x → 1/2 keeps the axis well defined.
  const Real half = 0.5 * angle;
  const Real s = angle > 1e-8 ? std::sin(half) / speed : 0.5 * h;
  const Quat dq(std::cos(half), s * omega.x, s * omega.y, s * omega.z);
  return glm::normalize(dq * q);
  // END SOLUTION
  // STUB: return exercises::notImplemented("RIGID-2", q, omega, h);
}

// ***** RIGID-3: The collision impulse with restitution (Baraff & Witkin 2001, "Rigid Body Dynamics
// II", §8.3) *****
// Inputs in world axes: the two bodies (ImpulseBody: inverse mass, inverse inertia, centre, velocities),
// the contact point [m], the unit normal n from B toward A, the restitution e. Output: the impulse's
// size j [N·s] ≥ 0, applied as +j n to A and −j n to B.
// (1) The relative velocity of the two material points at the contact, and its part along n [m/s]:
//     what sign does it have while the bodies approach? A contact that is not approaching gets nothing.
// (2) Work out from B&W §8.3 how much that normal relative velocity changes per unit impulse: each
//     body's translation contributes through its inverse mass, its rotation through the arm from its
//     centre to the point and its inverse inertia (world axes).
// (3) Choose j so that the normal relative velocity after the impulse is −e times the one before.
// Check: two equal spheres meeting head on with e = 1 exchange velocities; e = 0 leaves no normal
// relative velocity; a static body (inverse mass and inertia 0) receives nothing but still acts.
// *****
Real collisionImpulse(const ImpulseBody& a, const ImpulseBody& b, const Vec3& point, const Vec3& normal,
                      Real restitution) {
  // BEGIN SOLUTION
  const Vec3 ra = point - a.position, rb = point - b.position;
  const Real vrel = glm::dot(normal, a.velocityAt(point) - b.velocityAt(point));
  if (vrel >= 0.0) return 0.0;
  const Real denominator = a.inverseMass + b.inverseMass +
                           glm::dot(normal, glm::cross(a.inverseInertia * glm::cross(ra, normal), ra)) +
                           glm::dot(normal, glm::cross(b.inverseInertia * glm::cross(rb, normal), rb));
  if (!(denominator > 0.0)) return 0.0;
  return -(1.0 + restitution) * vrel / denominator;
  // END SOLUTION
  // STUB: return exercises::notImplemented("RIGID-3", 0.0, a, b, point, normal, restitution);
}

// ***** RIGID-4: The friction impulse clamped to μ·j (Coulomb's law for impulses; Mirtich 1996, §3.3) *****
// Inputs as RIGID-3 plus the normal impulse j [N·s] already decided and the friction coefficient μ.
// Output: the friction impulse on A [N·s] (B receives its negative), in the contact's tangent plane.
// (1) The sliding: the relative velocity at the contact without its normal part. No sliding, no friction.
// (2) The impulse that would stop the sliding: how much does the sliding speed change per unit impulse
//     along the sliding direction (the same reasoning as RIGID-3's, along another direction)?
// (3) Coulomb: friction can never exceed μ times the normal impulse. Return the stopping impulse when
//     it is within that bound, otherwise the largest one allowed, against the sliding.
// Check: μ = 0 gives nothing; the result is perpendicular to n and opposes the sliding; a large μ stops
// the sliding exactly; the size never exceeds μ j.
// *****
Vec3 frictionImpulse(const ImpulseBody& a, const ImpulseBody& b, const Vec3& point, const Vec3& normal,
                     Real normalImpulse, Real friction) {
  // BEGIN SOLUTION
  const Vec3 ra = point - a.position, rb = point - b.position;
  const Vec3 vr = a.velocityAt(point) - b.velocityAt(point);
  const Vec3 vt = vr - glm::dot(vr, normal) * normal;
  const Real speed = glm::length(vt);
  if (speed <= 1e-12) return Vec3(0.0);
  const Vec3 t = vt / speed;
  const Real kt = a.inverseMass + b.inverseMass + glm::dot(t, glm::cross(a.inverseInertia * glm::cross(ra, t), ra)) +
                  glm::dot(t, glm::cross(b.inverseInertia * glm::cross(rb, t), rb));
  if (!(kt > 0.0)) return Vec3(0.0);
  const Real stop = speed / kt;
  return -std::min(stop, friction * normalImpulse) * t;
  // END SOLUTION
  // STUB: return exercises::notImplemented("RIGID-4", Vec3(0.0), a, b, point, normal, normalImpulse, friction);
}

// ***** RIGID-5: The effective mass of a contact row (Catto, "Fast and Simple Physics using Sequential
// Impulses", GDC 2006; Baraff & Witkin 2001, "Rigid Body Dynamics II", §8.3) *****
// Inputs in world axes: each side's inverse mass [1/kg] and inverse inertia [1/(kg·m²)] (zeros for a
// side that cannot move), the arms r_A, r_B [m] from each centre of mass to the contact point, and the
// unit direction d of the row. Output: the effective mass [kg] ≥ 0 of the row, the factor the
// sequential-impulse solver multiplies a velocity error along d [m/s] by to get the impulse [N·s].
// (1) Translation: an impulse of 1 N·s along d (+ on B, − on A) changes each side's velocity by its
//     inverse mass; add up how much that changes the two points' relative velocity along d.
// (2) Rotation: the same impulse applied at the end of an arm gives each side an angular impulse (the
//     moment of d about the centre); its inverse inertia turns that into a change of ω, which moves
//     the point; keep only the part of that motion along d. Each side adds a term of its own, ≥ 0.
// (3) The sum K [1/kg] is the inverse of the effective mass. Return its reciprocal, or 0 when K is not
//     positive (two sides that cannot move: the row must apply nothing).
// Check: a point on the line of d through a centre adds only that side's inverse mass; an arm
// perpendicular to d adds (|r|²/I) for an isotropic inertia I; swapping A and B, or reversing d,
// changes nothing; 1/K equals the impulse that stops a relative velocity of 1 m/s along d.
// *****
Real contactEffectiveMass(Real inverseMassA, const Mat3& inverseInertiaA, const Vec3& armA, Real inverseMassB,
                          const Mat3& inverseInertiaB, const Vec3& armB, const Vec3& direction) {
  // BEGIN SOLUTION
  // K = m_A⁻¹ + m_B⁻¹ + (r_A × d)·I_A⁻¹(r_A × d) + (r_B × d)·I_B⁻¹(r_B × d), summed in this order.
  Real k = inverseMassA + inverseMassB;
  const Vec3 momentA = glm::cross(armA, direction);
  k += glm::dot(momentA, inverseInertiaA * momentA);
  const Vec3 momentB = glm::cross(armB, direction);
  k += glm::dot(momentB, inverseInertiaB * momentB);
  return k > 0.0 ? 1.0 / k : 0.0;
  // END SOLUTION
  // STUB: return exercises::notImplemented("RIGID-5", 0.0, inverseMassA, inverseInertiaA, armA, inverseMassB, inverseInertiaB, armB, direction);
}

// Start-up probes: tell the lab which exercises are still stubs.
PBA_EXERCISE_PROBE(boxInertiaTensor(1.0, Vec3(0.5), Quat(1, 0, 0, 0)));
PBA_EXERCISE_PROBE(integrateOrientation(Quat(1, 0, 0, 0), Vec3(0.0, 1.0, 0.0), 0.01));
PBA_EXERCISE_PROBE(collisionImpulse(ImpulseBody{1.0, Mat3(1.0), Vec3(0.0), Vec3(0.0, -1.0, 0.0), Vec3(0.0)},
                                    ImpulseBody{}, Vec3(0.0), kUp, 0.5));
PBA_EXERCISE_PROBE(frictionImpulse(ImpulseBody{1.0, Mat3(1.0), Vec3(0.0), Vec3(1.0, -1.0, 0.0), Vec3(0.0)},
                                   ImpulseBody{}, Vec3(0.0), kUp, 1.0, 0.5));
PBA_EXERCISE_PROBE(contactEffectiveMass(1.0, Mat3(1.0), Vec3(1.0, 0.0, 0.0), 0.0, Mat3(0.0), Vec3(0.0), kUp));

}  // namespace pba::rigid
