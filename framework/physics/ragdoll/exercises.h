#pragma once
// The ragdoll exercises RAG-1..4 and RAG-6 (docs/workbook/06-ragdolls.md; RAG-5 is in tetrahedron.h): the particle ragdoll's kernels in the
// paper's own form (Ragdoll paper §3; Jakobsen 2001). The particle ragdoll (particle_ragdoll.h) calls them
// for its sticks, limits and contacts; their tests feed them fixed inputs, so each is graded alone.
#include <array>

#include "physics/ragdoll/kernels.h"
#include "physics/ragdoll/tetrahedron.h"

namespace pba::ragdoll {

// RAG-1
/// Jakobsen's stick: moves a and b along their line so that |a − b| = rest, each by its share of the
/// inverse masses wa, wb [1/kg] (0: pinned). Nothing moves when both are pinned or they coincide.
void projectStick(Vec3& a, Vec3& b, Real wa, Real wb, Real rest);

enum class LimitSide { Inside, Lower, Upper };
struct LimitCorrection {
  LimitSide side = LimitSide::Inside;
  Vec3 target{0.0};  ///< [m] where the reference point must go (its position when inside)
};

// RAG-2
/// The paper's hinge limit by half-planes (§3.2.2): is the reference point `p` of bone B inside the
/// wedge lower ≤ angle ≤ upper (lower ≤ 0 ≤ upper, range below 2π, so beyond π works)? Outside, the
/// limit it breached (the nearer one, told apart by the third plane) and the target: p turned about
/// the axis onto that limit's half-plane, same distance from the axis, same height along it.
LimitCorrection hingeLimit(const HingeFrame& frame, const Vec3& p, Real lower, Real upper);

// RAG-3
/// The paper's ball-joint cone limit (§3.2.3): the reference point `p` of bone B, at distance
/// |p − apex| from the joint, must stay within `halfAngle` [rad] of the cone axis (unit). Outside, the
/// target is p turned towards the axis onto the cone, at the same distance from the apex (when p lies
/// on the axis behind the apex, any direction ⟂ axis will do).
LimitCorrection coneLimit(const Vec3& apex, const Vec3& axis, const Vec3& p, Real halfAngle);

/// One side of a contact between two bones (or a bone and the ground): the tetrahedron's particles,
/// the contact point's weights c_i (Σ c_i = 1) and the bone's mass.
struct ContactSide {
  std::array<Vec3, 4>* particles = nullptr;  ///< null: the static ground (it does not move)
  std::array<Real, 4> weights{0.25, 0.25, 0.25, 0.25};
  Real mass = 1.0;  ///< [kg]
};

// RAG-4
/// The paper's deepest-contact response (§3.3): A and B overlap by `depth` [m] ≥ 0 along the unit
/// `normal` (pointing from B to A). The push is split between the bones by mass (against the ground A
/// takes all of it), and each side hands its share to its particles in proportion to their weights so
/// that the contact point itself moves by exactly that share (workbook §6.7, RAG-4).
void resolveDeepestContact(ContactSide& a, ContactSide& b, const Vec3& normal, Real depth);

/// One bone's side of a correction at a point embedded in it: the bone's four particles, their inverse
/// masses and the point's barycentric weights c_i (Σ c_i = 1).
struct EmbeddedSide {
  Vec3* particles = nullptr;            ///< the four particles; null: a side that does not take part
  const Real* inverseMasses = nullptr;  ///< [1/kg] of the four particles (0: pinned)
  Weights weights{0.25, 0.25, 0.25, 0.25};
};

// RAG-6
/// Moves the point embedded in B by `delta` [m] relative to the point embedded in A, as one projection
/// along delta's direction shared by inverse masses and weights (a joint: B's copy of the joint point
/// onto A's; a limit: B's reference point onto its target, A pushed back). A null side does not move.
void moveEmbeddedPoints(EmbeddedSide a, EmbeddedSide b, const Vec3& delta);

}  // namespace pba::ragdoll
