#include "physics/ragdoll/exercises.h"

#include <cmath>

#include "physics/exercises/not_implemented.h"

namespace pba::ragdoll {

// ***** RAG-1: the stick constraint with inverse masses (Ragdoll paper §3.1; Jakobsen 2001, §3) *****
// (1) The vector from a to b, its length, and the error: length minus rest.
// (2) Nothing to do when both ends are pinned (wa + wb = 0) or the ends coincide (no direction).
// (3) Both ends move along the stick's direction and together remove the whole error. Work out how the
//     error is shared from the inverse masses (a pinned end does not move, the heavier end moves less)
//     and which way each end goes when the stick is too long and when it is too short.
// *****
void projectStick(Vec3& a, Vec3& b, Real wa, Real wb, Real rest) {
  // BEGIN SOLUTION
  const Vec3 d = b - a;
  const Real length = glm::length(d);
  const Real w = wa + wb;
  if (!(w > 0.0) || !(length > 1e-12)) return;
  const Vec3 correction = (length - rest) / (length * w) * d;
  a += wa * correction;
  b -= wb * correction;
  // END SOLUTION
  // STUB: static_cast<void>(exercises::notImplemented("RAG-1", 0, a, b, wa, wb, rest));  // nothing moves
}

// ***** RAG-2: the hinge limit by half-planes (Ragdoll paper §3.2.2) *****
// Inputs in world axes: the hinge frame (a point of the axis, the unit axis, the unit direction of angle
// 0, perpendicular to the axis), bone B's reference point p [m], the limits lower ≤ 0 ≤ upper [rad]
// (upper − lower below 2π, so wider than π is allowed). Angles about the axis by the right-hand rule.
// (1) Look at p from the axis: its part across the axis (if (almost) none, there is no angle: Inside,
//     target p) and its part along it.
// (2) Each limit is a half-plane through the axis. Using only signed distances from planes through the
//     axis (no atan2), decide on which side of each limit's plane p lies; work out how "inside" reads
//     when the range is at most π, and when it is wider.
// (3) Outside: a third plane through the axis, through the middle of the forbidden wedge, tells which
//     limit p is nearer: return LimitSide::Lower or LimitSide::Upper accordingly.
// (4) The target: p turned about the axis onto that limit's half-plane, keeping its distance from the
//     axis and its height along it.
// Check: angles inside the range are Inside with target p; the target is at the limit's angle, as far
// from the axis as p, at p's height; with a range of 270° the forbidden quarter is the right one.
// *****
LimitCorrection hingeLimit(const HingeFrame& frame, const Vec3& p, Real lower, Real upper) {
  // BEGIN SOLUTION
  const Vec3 rel = p - frame.origin;
  const Vec3 along = glm::dot(rel, frame.axis) * frame.axis;
  const Vec3 q = rel - along;
  const Real radius = glm::length(q);
  if (!(radius > 1e-12)) return {LimitSide::Inside, p};
  const Vec3 side = glm::cross(frame.axis, frame.zero);
  const auto direction = [&](Real t) { return std::cos(t) * frame.zero + std::sin(t) * side; };
  const Real aboveLower = glm::dot(q, direction(lower + 0.5 * kPi));
  const Real belowUpper = -glm::dot(q, direction(upper + 0.5 * kPi));
  const bool inside =
      upper - lower <= kPi ? (aboveLower >= 0.0 && belowUpper >= 0.0) : (aboveLower >= 0.0 || belowUpper >= 0.0);
  if (inside) return {LimitSide::Inside, p};
  const Real middle = 0.5 * (lower + upper) + kPi;
  const bool nearerLower = glm::dot(q, direction(middle + 0.5 * kPi)) >= 0.0;
  const Real limit = nearerLower ? lower : upper;
  return {nearerLower ? LimitSide::Lower : LimitSide::Upper, frame.origin + along + radius * direction(limit)};
  // END SOLUTION
  // STUB: return exercises::notImplemented("RAG-2", LimitCorrection{LimitSide::Inside, p}, frame, lower, upper);
}

// ***** RAG-3: the ball-joint cone limit (Ragdoll paper §3.2.3) *****
// Inputs in world axes: the apex (the joint) [m], the cone's unit axis, bone B's reference point p [m],
// the half-angle of the cone [rad], between 0 and π.
// (1) Measure p from the apex: its distance from the apex, and its height above the paper's plane (the
//     plane through the apex with the axis as its normal). A point at the apex has no direction: Inside.
// (2) Find the height a point at that same distance would have on the cone's rim. p is inside the cone
//     when it stands at least that high: return LimitSide::Inside with p itself as the target.
// (3) Outside, return LimitSide::Upper (a cone has one limit, the rim) and as the target the point of the
//     rim that is as far from the apex as p and lies in the plane through the axis and p. When p lies on
//     the axis behind the apex that plane is not defined: any plane through the axis will do.
// Check: the target is as far from the apex as p, at exactly the half-angle from the axis, on p's side;
// p already on the rim is Inside.
// *****
LimitCorrection coneLimit(const Vec3& apex, const Vec3& axis, const Vec3& p, Real halfAngle) {
  // BEGIN SOLUTION
  const Vec3 d = p - apex;
  const Real length = glm::length(d);
  if (!(length > 1e-12)) return {LimitSide::Inside, p};
  const Real distance = glm::dot(d, axis);
  if (distance >= length * std::cos(halfAngle)) return {LimitSide::Inside, p};
  Vec3 t = d - distance * axis;
  if (glm::length(t) < 1e-12 * length) t = glm::cross(axis, std::abs(axis.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
  t = glm::normalize(t);
  return {LimitSide::Upper, apex + length * (std::cos(halfAngle) * axis + std::sin(halfAngle) * t)};
  // END SOLUTION
  // STUB: return exercises::notImplemented("RAG-3", LimitCorrection{LimitSide::Inside, p}, apex, axis, halfAngle);
}

// ***** RAG-4: the deepest contact spread over the tetrahedron (Ragdoll paper §3.3) *****
// Inputs: the two sides (each bone's four particles, the contact point's barycentric weights c_i with
// Σ c_i = 1, the bone's mass [kg]; B may be the static ground), the unit normal from B to A and the depth
// [m] ≥ 0 by which they overlap.
// (1) The whole push separates the two by the depth along the normal. Share it between the two bones so
//     that momentum is kept (the heavier bone moves less); against the ground A takes all of it.
// (2) Each side moves its four particles in proportion to their weights, scaled so that the contact
//     point (the weighted sum of the particles) moves by exactly that side's share: work out the scale
//     from the weights.
// Check: the contact point of each side moves by exactly its share; equal masses share equally; the
// ground never moves; a particle with weight 0 stays put.
// *****
void resolveDeepestContact(ContactSide& a, ContactSide& b, const Vec3& normal, Real depth) {
  // BEGIN SOLUTION
  const Vec3 push = depth * normal;
  const bool ground = b.particles == nullptr;
  const Real shareA = ground ? 1.0 : b.mass / (a.mass + b.mass);
  const auto spread = [](ContactSide& s, const Vec3& delta) {
    Real sum = 0.0;
    for (Real c : s.weights) sum += c * c;
    if (!(sum > 0.0)) return;
    const Real lambda = 1.0 / sum;
    for (int i = 0; i < 4; ++i) (*s.particles)[i] += s.weights[i] * lambda * delta;
  };
  if (a.particles) spread(a, shareA * push);
  if (!ground) spread(b, -(1.0 - shareA) * push);
  // END SOLUTION
  // STUB: static_cast<void>(exercises::notImplemented("RAG-4", 0, a, b, normal, depth));  // nothing moves
}

// ***** RAG-6: a joint point embedded in two bones (Müller et al. 2007, §3.3; Ragdoll paper §3.2.1) *****
// Inputs: the two sides (each bone's four particles [m], their inverse masses [1/kg] and the point's
// barycentric weights; a side may be null) and the move delta [m] of B's point relative to A's.
// (1) Nothing to do for a (nearly) zero delta. Otherwise the constraint is the gap along delta's unit
//     direction; write down its gradient with respect to each particle of each side: how does the
//     embedded point move when one particle moves, and with which sign for A and for B?
// (2) Apply the projection of workbook §6.2 (kernels.h) with those gradients. Nothing moves when every
//     particle involved is pinned.
// (3) B's point goes along delta, A's against it, each side by its share of the inverse masses and
//     weights, so that together they close exactly delta.
// Check: the relative move of the two points is exactly delta; momentum Σ m Δx is kept; a pinned side
// stays; a particle of weight 0 stays.
// *****
void moveEmbeddedPoints(EmbeddedSide a, EmbeddedSide b, const Vec3& delta) {
  // BEGIN SOLUTION
  const Real size = glm::length(delta);
  if (!(size > 1e-15)) return;
  Real denominator = 0.0;
  if (b.particles)
    for (int k = 0; k < 4; ++k) denominator += b.inverseMasses[k] * b.weights[k] * b.weights[k];
  if (a.particles)
    for (int k = 0; k < 4; ++k) denominator += a.inverseMasses[k] * a.weights[k] * a.weights[k];
  if (!(denominator > 1e-300)) return;
  const Vec3 n = delta / size;
  const Real s = -size / denominator;
  if (b.particles)
    for (int k = 0; k < 4; ++k) b.particles[k] -= (s * b.inverseMasses[k] * b.weights[k]) * n;
  if (a.particles)
    for (int k = 0; k < 4; ++k) a.particles[k] += (s * a.inverseMasses[k] * a.weights[k]) * n;
  // END SOLUTION
  // STUB: static_cast<void>(exercises::notImplemented("RAG-6", 0, a, b, delta));  // nothing moves
}

namespace {
void probeStick() {
  Vec3 a(0.0), b(2.0, 0.0, 0.0);
  projectStick(a, b, 1.0, 1.0, 1.0);
}
void probeJoint() {
  std::array<Vec3, 4> x{};
  const std::array<Real, 4> w{1.0, 1.0, 1.0, 1.0};
  moveEmbeddedPoints(EmbeddedSide{}, EmbeddedSide{x.data(), w.data()}, kUp);
}
void probeContact() {
  std::array<Vec3, 4> x{};
  ContactSide a{&x}, ground{};
  resolveDeepestContact(a, ground, kUp, 0.1);
}
}  // namespace

// Start-up probes: tell the lab which exercises are still stubs.
PBA_EXERCISE_PROBE(probeStick());
PBA_EXERCISE_PROBE(hingeLimit(HingeFrame{}, Vec3(0.0, 0.0, 1.0), -0.5, 0.5));
PBA_EXERCISE_PROBE(coneLimit(Vec3(0.0), kUp, Vec3(1.0, 0.0, 0.0), 0.5));
PBA_EXERCISE_PROBE(probeContact());
PBA_EXERCISE_PROBE(probeJoint());

}  // namespace pba::ragdoll
