#pragma once
// Contact constraints solved by sequential impulses (Catto, "Fast and Simple Physics using Sequential
// Impulses", GDC 2006; "Modeling and Solving Constraints", GDC 2009; Box2D v3 src/contact_solver.c).
//
// Non-penetration at a contact point with normal n (A → B) and arms r_A, r_B:
//   C = separation ≥ 0,   Ċ = n·(v_B + ω_B × r_B − v_A − ω_A × r_A) = J v,
//   J = [−nᵀ, −(r_A × n)ᵀ, nᵀ, (r_B × n)ᵀ],  m_eff the row's effective mass (the exercise RIGID-5).
// Each iteration applies λ = −m_eff (Ċ + bias) and clamps the accumulated impulse to ≥ 0 (the impulse
// may push, never pull). Friction rows along the tangents t₁, t₂ are clamped to the Coulomb cone
// |λ_t| ≤ μ λ_n (or the pyramid |λ_tᵢ| ≤ μ λ_n). The bias: speculative (C > 0: allow the approach
// that closes the gap in this substep, C/h), soft (b2MakeSoft: biasRate·C, with massScale and
// impulseScale) or Baumgarte (β/h·min(0, C + slop)). Restitution runs once after the substeps on points
// that approached faster than the threshold: target n·v_rel' = −e·(n·v_rel before the step).
#include <cstdint>
#include <vector>

#include "physics/collision/manifold.h"
#include "physics/collision/transform.h"
#include "physics/rigid/settings.h"
#include "physics/rigid/softness.h"
#include "physics/rigid/solver_body.h"

namespace pba::rigid {

/// What a contact point carries from step to step (warm starting): its feature id and the impulses it
/// accumulated.
struct ContactPoint {
  Real normalImpulse = 0.0;  ///< [N·s]
  Real tangentImpulse[2] = {0.0, 0.0};
  std::uint32_t id = 0;
};

/// A manifold as the world keeps it between steps (small: it is copied every step).
struct ContactConstraint {
  int bodyA = -1, bodyB = -1;
  std::uint32_t key = 0;  ///< manifold key (mesh triangle)
  Vec3 normal{0.0};
  Vec3 tangent[2]{Vec3(0.0), Vec3(0.0)};
  Real friction = 0.0, restitution = 0.0;
  int count = 0;
  ContactPoint points[4];
  collision::Manifold manifold;  ///< as the narrow phase made it (debug draw)
  // For the contact cache: B's pose relative to A when the manifold was made, the normal in A's frame and
  // each point's two surface points, on A in A's frame and on B in B's frame (Bullet's persistent
  // manifold keeps the same pair to refresh its points).
  collision::Transform relativePose;
  Vec3 localNormal{0.0};
  Vec3 surfaceA[4]{Vec3(0.0), Vec3(0.0), Vec3(0.0), Vec3(0.0)};
  Vec3 surfaceB[4]{Vec3(0.0), Vec3(0.0), Vec3(0.0), Vec3(0.0)};
};

/// A contact point as the solver sees it, rebuilt every step: the arms r_A, r_B from the centres of mass
/// to the point (world axes, fixed for the step). The Jacobian pieces r × d and I⁻¹(r × d) for d = n, t₁,
/// t₂ are recomputed where they are used: storing them made a point 360 bytes, and the passes over the
/// contacts were bound by moving them (Box2D v3 keeps only the anchors too).
struct SolverContactPoint {
  Vec3 rA, rB;
  Real separation;  ///< [m] at the start of the step
  Real normalMass;
  Real tangentMass[2];  ///< 1/K of each tangent row
  Real normalImpulse;   ///< [N·s] accumulated
  Real tangentImpulse[2];
  Real maxNormalImpulse;  ///< largest normal impulse of the step (restitution needs > 0)
  Real relativeVelocity;  ///< [m/s] n·v_rel at the start of the step
};

/// Which sides of a contact the solver works on. A side at rest (a static or sleeping body, or a
/// kinematic one standing still: no inverse mass, no velocity) keeps zero velocity and displacement for
/// the whole step, so its terms in the rows are zero and the impulses it would take are dropped; most
/// manifolds of ragdolls on the ground are of this kind (docs/performance-ragdoll.md).
enum class ContactSides : std::uint8_t { Both, OnlyA, OnlyB };

/// A contact constraint as the solver sees it in one step (every field is written by prepareContact).
struct SolverContact {
  int bodyA, bodyB;
  bool againstStatic;  ///< one side cannot move
  ContactSides sides;  ///< Both unless one side is at rest
  int count;
  Vec3 normal;
  Vec3 tangent[2];
  Real friction, restitution;
  Real invMassA, invMassB;
  Mat3 invIA, invIB;  ///< world inverse inertia of each side (zero for a static one)
  SolverContactPoint points[4];
};

/// Per-substep solver inputs.
struct ContactSolverStep {
  const WorldSettings* settings = nullptr;
  Real h = 0.0;         ///< [s] substep
  Softness soft;        ///< contact softness between two moving bodies at this substep
  Softness staticSoft;  ///< against static bodies: twice the frequency (Box2D v3's staticSoftness)
};

/// Builds the solver data `out` of `c` from its manifold and the bodies at the start of the step; the
/// impulses in c.points (carried over by feature id) start the warm start, or zero without it.
void prepareContact(const ContactConstraint& c, const std::vector<SolverBody>& bodies, bool warmStarting,
                    SolverContact& out);
void warmStartContact(const SolverContact& c, std::vector<SolverBody>& bodies);
void solveContact(SolverContact& c, std::vector<SolverBody>& bodies, const ContactSolverStep& step, bool useBias);
void applyRestitution(SolverContact& c, std::vector<SolverBody>& bodies, const WorldSettings& settings);
/// Writes the step's accumulated impulses back for the next step's warm start.
void storeImpulses(const SolverContact& s, ContactConstraint& c);

/// Tangent basis (t₁, t₂) of unit n: stable under small changes of n, so friction impulses can be warm
/// started (t₁ from the world axis least aligned with n).
void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2);

}  // namespace pba::rigid
