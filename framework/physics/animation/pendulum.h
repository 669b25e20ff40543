#pragma once
// Secondary motion: pendulum and spring joints hanging from a keyframed character (CMU asst4,
// "Pendulum joints", in 3-D).
//
// asst4's planar joint: θ̈ = −(⟨a, y⊥⟩/L² + m g L sin(θ − ψ)/I), with y = C − c the pivot-to-centre-of-
// mass vector (L = |y|), ψ its angle with the link, a the pivot's acceleration, I the moment of inertia
// about the pivot. In 3-D the state is the unit direction d of y (so the offset ψ is already in d; the
// link is drawn from d) and the angular velocity ω ⊥ d. In the pivot's accelerating frame the body
// feels gravity g and the inertial force −m a, so the torque about the pivot is τ = L d × m (g − a) and
//   ω̇ = (m L / I) d × (g − a)  −  (k / I) φ   (spring joints: φ the rotation vector from the rest
//                                              direction to d, k the angular stiffness [N m/rad])
// The first term with a = 0 is asst4's gravity term (planar: d × g = −g sin θ), the a-part is its
// reaction term (⟨a, y⊥⟩/L² for a point mass, I = m L²). Integration: symplectic Euler (ω first, then
// d turned by the new ω·dt), damping ω ← ω exp(−c dt) as in asst4.
// Limiting cases: small swings have the period 2π √(I/(m g L)); undamped, the energy
// ½ I |ω|² − m L d·g oscillates without drift; a pivot accelerating uniformly by a (horizontal) holds
// the bob at atan(|a|/g) from the vertical, trailing behind.
#include <vector>

#include "physics/core/types.h"

namespace pba::animation {

struct PendulumDesc {
  Real mass = 0.3;       ///< [kg] m > 0
  Real length = 0.25;    ///< [m] L > 0: pivot to centre of mass
  Real inertia = 0.0;    ///< [kg m²] I about the pivot; 0: a point mass, m L²
  Real damping = 0.5;    ///< [1/s] c ≥ 0 in ω ← ω exp(−c dt)
  Real stiffness = 0.0;  ///< [N m/rad] k ≥ 0: 0 is a pendulum joint, > 0 a spring joint
  Real momentOfInertia() const { return inertia > 0.0 ? inertia : mass * length * length; }
};

struct PendulumState {
  Vec3 direction{0.0, -1.0, 0.0};  ///< unit d, world: pivot → centre of mass
  Vec3 omega{0.0};                 ///< [rad/s] world, ⊥ d
};

/// What the character imposes on the joint this step.
struct PendulumDrive {
  Vec3 gravity{0.0, -kStandardGravity, 0.0};  ///< [m/s²] world
  Vec3 pivotAcceleration{0.0};                ///< [m/s²] world: a of the pivot
  Vec3 restDirection{0.0, -1.0, 0.0};         ///< unit, world: where a spring joint pulls d
  bool reaction = true;                       ///< false drops the −a term (to see what it adds)
};

/// One symplectic Euler step of length dt [s]. Exercise ANIM-4.
PendulumState stepPendulum(const PendulumDesc& desc, const PendulumState& state, const PendulumDrive& drive, Real dt);

/// ½ I |ω|² − m L d·g + ½ k |φ|² [J], zero potential at the pivot's height.
Real pendulumEnergy(const PendulumDesc& desc, const PendulumState& state, const PendulumDrive& drive);

/// Rotates unit d by the rotation vector φ (Rodrigues).
Vec3 rotateByVector(const Vec3& d, const Vec3& phi);

/// An n-link chain (tail, ponytail): link k hangs from the tip of link k−1, the first from the pivot.
/// Each link is one pendulum joint driven by its own pivot's acceleration (the previous link's tip,
/// a = a_pivot + ω̇ × r + ω × (ω × r)): asst4's "n-pendulum" extension with one-way coupling (a link
/// does not push back on the one above it), which keeps the step explicit and cheap.
struct PendulumChain {
  std::vector<PendulumDesc> links;
  std::vector<PendulumState> states;
  std::vector<Vec3>
      tips;  ///< [m] world tip of each link after the last step (tip = centre of mass · 2 for a rod; here L)

  /// Steps every link; `pivot` [m] and its acceleration [m/s²] come from the character.
  void step(const Vec3& pivot, const PendulumDrive& drive, Real dt);
  /// Puts every link along the rest direction at rest.
  void rest(const Vec3& pivot, const Vec3& restDirection);
  /// [J] sum of pendulumEnergy over the links, each with its own rest direction and pivot frame.
  Real energy(const Vec3& pivot, const PendulumDrive& drive) const;
};

}  // namespace pba::animation
