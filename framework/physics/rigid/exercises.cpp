#include "physics/rigid/exercises.h"

#include <algorithm>
#include <cmath>

#include "physics/exercises/not_implemented.h"

namespace pba::rigid {

// ***** RIGID-1: Box inertia tensor and its world transform (Baraff & Witkin 2001, "Rigid Body
// Dynamics I", §2.9–2.10) *****
// Inputs: the mass [kg] and the half extents h [m] (the full sides are twice as long). Output: the
// inertia tensor [kg·m²] about the centre of mass, in the box's own axes.
// (1) Work out from the integral of Baraff & Witkin §2.9 (or its table of solids) which entries a box
//     centred on its own axes has, and which of the three sides each one depends on.
// (2) Return it as a Mat3 (glm is column-major).
// Check: a cube's tensor is a multiple of the identity; stretching the box along x leaves I_xx alone
// and raises the other two; the tensor scales with the mass and with the square of the size.
// *****
Mat3 boxInertiaTensor(Real mass, const Vec3& halfExtents) {
  // BEGIN SOLUTION
  const Vec3 side = 2.0 * halfExtents;
  const Vec3 s2 = side * side;
  Mat3 inertia(0.0);
  inertia[0][0] = mass / 12.0 * (s2.y + s2.z);
  inertia[1][1] = mass / 12.0 * (s2.z + s2.x);
  inertia[2][2] = mass / 12.0 * (s2.x + s2.y);
  return inertia;
  // END SOLUTION
  // STUB: return exercises::notImplemented("RIGID-1", Mat3(mass), halfExtents);
}

// ***** RIGID-1 (continued): the world-space tensor *****
// Inputs: the tensor in body axes and the orientation q (body axes → world axes). Output: the tensor that
// maps an angular velocity in WORLD axes to the angular momentum in world axes.
// (1) Think of what the body tensor expects: an ω expressed in body axes. Chain the changes of frame
//     that take a world ω into the body frame, apply the body tensor, and bring the result back.
// Check: the world tensor is symmetric with the body tensor's eigenvalues; for q the identity it is the
// body tensor; L computed either way (in world axes, or in body axes and rotated) agrees.
// *****
Mat3 worldInertiaTensor(const Mat3& bodyInertia, const Quat& q) {
  // BEGIN SOLUTION
  const Mat3 r = glm::mat3_cast(q);
  return r * bodyInertia * glm::transpose(r);
  // END SOLUTION
  // STUB: return exercises::notImplemented("RIGID-1", bodyInertia, q);
}

// ***** RIGID-2: Quaternion integration of the orientation (Baraff & Witkin 2001, §4.2) *****
// Inputs: the orientation q (unit, body → world), the angular velocity ω [rad/s] in WORLD axes, the step
// h [s]. Output: the orientation after one explicit Euler step, of unit length.
// (1) Find in B&W §4.2 the time derivative of q for a world-axes ω: what ω becomes as a quaternion, the
//     factor in front, and on which side of q it multiplies (the side is fixed by the frame of ω).
// (2) Take one explicit Euler step of the four components, then bring q back to unit length: the step
//     leaves the unit sphere.
// Check: ω = 0 leaves q unchanged; a small step about z turns a body's x axis towards +y by ω h to
// first order; the result has unit length.
// *****
Quat integrateOrientation(const Quat& q, const Vec3& omega, Real h) {
  // BEGIN SOLUTION
  const Quat w(0.0, omega.x, omega.y, omega.z);
  const Quat dq = 0.5 * h * (w * q);
  return glm::normalize(q + dq);
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

// Start-up probes: tell the lab which exercises are still stubs.
PBA_EXERCISE_PROBE(boxInertiaTensor(1.0, Vec3(0.5)));
PBA_EXERCISE_PROBE(worldInertiaTensor(Mat3(1.0), Quat(1, 0, 0, 0)));
PBA_EXERCISE_PROBE(integrateOrientation(Quat(1, 0, 0, 0), Vec3(0.0, 1.0, 0.0), 0.01));
PBA_EXERCISE_PROBE(collisionImpulse(ImpulseBody{1.0, Mat3(1.0), Vec3(0.0), Vec3(0.0, -1.0, 0.0), Vec3(0.0)},
                                    ImpulseBody{}, Vec3(0.0), kUp, 0.5));
PBA_EXERCISE_PROBE(frictionImpulse(ImpulseBody{1.0, Mat3(1.0), Vec3(0.0), Vec3(1.0, -1.0, 0.0), Vec3(0.0)},
                                   ImpulseBody{}, Vec3(0.0), kUp, 1.0, 0.5));

}  // namespace pba::rigid
