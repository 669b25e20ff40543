#pragma once
// Damped springs between particles (Lobb notes, "Spring force" and "Damped spring").
//
// Glossary: r = x_j − x_i, l = |r|, r̂ = r/l, ṙ = v_j − v_i, L rest length, k stiffness, k_d damping.
//   F_i = [k (l − L) + k_d (r̂·ṙ)] r̂,   F_j = −F_i                                  (Lobb, damped spring)
// The damping acts only along the spring (it resists the rate of change of length, not rotation), so
// a freely spinning spring keeps its angular momentum; F_i + F_j = 0 keeps linear momentum.
// Jacobian (for implicit Euler; Baraff & Witkin 1998 §5.2 for the structure):
//   ∂F_i/∂x_j = k [ r̂r̂ᵀ + (1 − L/l)(I − r̂r̂ᵀ) ] =: K_s,   ∂F_i/∂x_i = −K_s,
//   ∂F_i/∂v_j = k_d r̂r̂ᵀ =: K_d,                           ∂F_i/∂v_i = −K_d,
// dropping the damping term's dependence on x (small; B&W drop it too). Departure: under compression
// (l < L) the factor (1 − L/l) is negative and makes K_s indefinite, which can break conjugate gradients;
// we clamp it to 0 (Choi & Ko 2002, "Stable but responsive cloth", §4) — the system matrix stays SPD.
#include <cstdint>
#include <span>
#include <vector>

#include "physics/core/types.h"

namespace pba::springs {

struct Spring {
  std::uint32_t i = 0, j = 0;  ///< particle indices
  Real restLength = 1.0;       ///< L [m] > 0
  Real stiffness = 100.0;      ///< k [N/m] ≥ 0; typical 10–10⁵
  Real damping = 0.5;          ///< k_d [N·s/m] ≥ 0, along the spring
};

// ***** PART-4: the damped spring force (Lobb notes, "Damped spring") *****
// Returns the force [N] on particle i from the spring to particle j: positions [m], velocities [m/s],
// stiffness k [N/m], rest length L [m], damping k_d [N·s/m] acting along the spring only.
// (1) The spring's direction and length. When the two ends (nearly) coincide there is no direction:
//     return a zero force.
// (2) The size of the force has two parts: one from how far the spring is stretched beyond its rest
//     length, one from how fast its length is changing (the relative velocity's part along the spring,
//     not its sideways part).
// (3) The force on i acts along the spring; decide its sign so that a stretched or lengthening spring
//     pulls i towards j. (The force on j is its negative: the caller applies both.)
// Check: no force at rest length and rest; momentum conserved (f_i + f_j = 0); a sideways relative
// velocity adds no damping; the elastic part is minus the gradient of the spring's stored energy.
// *****
Vec3 dampedSpringForce(const Vec3& xi, const Vec3& xj, const Vec3& vi, const Vec3& vj, Real stiffness, Real restLength,
                       Real damping);

/// Adds every spring's force to f (both ends).
void accumulateSpringForces(std::span<const Spring> springs, std::span<const Vec3> x, std::span<const Vec3> v,
                            std::span<Vec3> f);
/// Adds the springs' force differential K dx + D dv (Jacobian above) to df.
void accumulateSpringDifferential(std::span<const Spring> springs, std::span<const Vec3> x, std::span<const Vec3> dx,
                                  std::span<const Vec3> dv, std::span<Vec3> df);
/// Adds every spring's part of the Jacobian's diagonal blocks, ∂F_i/∂x_i = −K_s and ∂F_i/∂v_i = −K_d at
/// both ends, to dfdx and dfdv (one 3×3 block per particle): implicit Euler's preconditioner.
void accumulateSpringJacobianDiagonal(std::span<const Spring> springs, std::span<const Vec3> x, std::span<Mat3> dfdx,
                                      std::span<Mat3> dfdv);
/// Σ k (l − L)² / 2 [J].
Real springPotentialEnergy(std::span<const Spring> springs, std::span<const Vec3> x);
/// Largest |l − L| / L over the springs (a measure of how far a stiff network is from rest).
Real maxRelativeStretch(std::span<const Spring> springs, std::span<const Vec3> x);

}  // namespace pba::springs
