#pragma once
// How small a step an explicit integrator needs on a spring network: the highest angular frequency of its
// small vibrations about the current configuration. Linearised, M ẍ = −K x with K the springs' stiffness
// matrix (the Jacobian of spring_network.h, without damping) and M the particle masses; the modes solve
// K φ = ω² M φ. Pinned particles (inverse mass 0) do not move. On one undamped mode ẍ = −ω²x, symplectic
// Euler (v += −hω²x, then x += hv) has the step matrix [[1 − h²ω², h], [−hω², 1]] of determinant 1 and
// trace 2 − h²ω²: bounded iff |2 − h²ω²| < 2, i.e. h < 2/ω. Classical RK4 is bounded on the imaginary axis
// up to hω = 2√2, and forward Euler grows for every h (Lobb notes, "ODE view": stiff springs force small
// steps). So the stiffest mode sets an explicit method's step, not the stiffest spring alone: a lattice's
// shear and bending springs push it above the chain estimate 2√(k/m).
#include <span>

#include "physics/core/types.h"
#include "physics/springs/spring_network.h"

namespace pba::springs {

/// ω_max [rad/s] of the network about configuration x (same indices as inverseMass), by power iteration on
/// the symmetric M^{-1/2} K M^{-1/2}; its Rayleigh quotient approaches ω_max² from below. Stops when
/// the quotient changes by less than `relativeTolerance` between iterations, or after `maxIterations`.
/// 0 when nothing can move.
Real highestAngularFrequency(std::span<const Spring> springs, std::span<const Vec3> x,
                             std::span<const Real> inverseMass, int maxIterations = 2000,
                             Real relativeTolerance = 1e-12);

}  // namespace pba::springs
