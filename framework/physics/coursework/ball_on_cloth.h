#pragma once
// Coursework 2, cloth meeting a rigid object (docs/course/coursework-2-cloth-meets-rigid.md): a heavy
// ball falls onto a trampoline of cloth pinned at its four corners. Unlike the cloth lab's colliders,
// which move on a script and never feel the cloth, the ball is dynamic: every contact pushes the ball
// as much as it pushes the cloth (two-way coupling), so the trampoline can catch it, sag and throw it
// back. Position-based dynamics (Müller et al. 2007 §3; Macklin et al. 2016 for XPBD's stretch
// constraints, CLOTH-2): predict, project the constraints and contacts, derive the velocities.
#include <vector>
#include "physics/cloth/cloth.h"
#include "physics/core/result.h"

namespace pba::coursework {

/// A solid ball [SI]: the rigid object of the coursework (no rotation: contacts are frictionless).
struct Ball {
  Vec3 position{0.0};      ///< [m] centre
  Vec3 velocity{0.0};      ///< [m/s]
  Real radius = 0.2;       ///< [m]
  Real inverseMass = 2.0;  ///< [1/kg]; 0 holds the ball where it is (a kinematic obstacle)
};

/// The two corrections of one ball–particle contact [m].
struct BallContact {
  Vec3 particle{0.0};  ///< Δx of the particle
  Vec3 ball{0.0};      ///< Δx of the ball's centre
};

// ***** CW2-1: one ball–particle contact, both ways (Müller et al. 2007 §3.3, eq. 8–9) *****
// Inputs: the particle's position x_p [m] and inverse mass w_p [1/kg], the ball's centre x_b [m] and
// inverse mass w_b, and the contact radius r [m] (the ball's radius plus the cloth's margin).
// Return how far each of the two moves so that the particle ends exactly on the sphere of radius r
// about the ball's new centre.
// (1) Write the contact as a constraint C ≥ 0 on the two positions; act only when it is violated.
//     Nothing can be done when the particle sits at the very centre or when both are immovable.
// (2) Its gradient with respect to each position: two opposite unit vectors.
// (3) Share the correction in proportion to the inverse masses, as for any PBD constraint between two
//     points: an immovable one (w = 0) never moves, a heavy one moves little.
// Check: afterwards |x_p − x_b| = r; the momentum of the pair is unchanged (Δx_p / w_p + Δx_b / w_b = 0);
// a point outside the sphere is left alone; with w_b = 0 only the particle moves.
// *****
BallContact ballParticleContact(const Vec3& particle, Real particleInverseMass, const Vec3& ball, Real ballInverseMass,
                                Real radius);

/// The trampoline and the ball, with their defaults.
struct BallOnClothDesc {
  int resolution = 24;            ///< particles along each side of the square cloth, ≥ 2
  Real size = 1.6;                ///< [m] side of the square, centred on (0, clothHeight, 0), horizontal
  Real clothHeight = 1.0;         ///< [m]
  Real massPerArea = 0.3;         ///< [kg/m²]
  Real stretchCompliance = 1e-6;  ///< α [m/N] of every distance constraint (0: inextensible)
  Real ballRadius = 0.2;          ///< [m]
  Real ballMass = 1.0;            ///< [kg] > 0
  Vec3 ballStart{0.0, 1.8, 0.0};  ///< [m]
  Vec3 ballVelocity{0.0};         ///< [m/s] initial
  Real margin = 0.01;             ///< [m] added to the ball's radius for contacts
  int iterations = 8;             ///< constraint sweeps per substep, ≥ 1
  Real damping = 1.5;             ///< [1/s] linear damping rate of every velocity (air drag), ≥ 0
  Vec3 gravity{0.0, -9.81, 0.0};  ///< [m/s²]
};

/// The scene: the cloth (lib cloth, corners pinned), the ball, and the solver's own scratch.
struct BallOnCloth {
  cloth::Cloth cloth;
  Ball ball;
  Vec3 gravity{0.0, -9.81, 0.0};  ///< [m/s²]
  Real margin = 0.01;             ///< [m]
  int iterations = 8;
  Real damping = 1.5;          ///< [1/s]
  Real time = 0.0;             ///< [s]
  std::vector<Vec3> previous;  ///< scratch: positions at the start of a step
  std::vector<Real> lambda;    ///< scratch: one XPBD multiplier per distance constraint
};

/// Builds the scene; errors name the field ("resolution: must be at least 2").
Result<BallOnCloth> buildBallOnCloth(const BallOnClothDesc& desc);

// ***** CW2-2: the coupled position-based step (Müller et al. 2007 §3.1, Algorithm 1; Macklin et al. 2016) *****
// Advance the scene by one step h [s]: cloth and ball together, so that each feels the other.
// (1) Remember where everything starts. Predict: every free particle and the ball (when it is free)
//     gain g h of velocity and move by their new velocity times h. Pinned particles stay.
// (2) Start the step's XPBD multipliers at zero. Then, `iterations` times: one sweep of the cloth's
//     distance constraints (the library's sweep, which uses CLOTH-2, with the cloth's compliances),
//     then every particle's contact with the ball (CW2-1, radius = ball radius + margin), applying
//     both corrections at once so the next contact sees the moved ball.
// (3) Velocities are what the positions did: the displacement over the step divided by h, for the
//     particles and the ball alike. Then every velocity loses the fraction damping·h of itself (never
//     more than all of it). Advance the clock.
// Check: without damping the ball alone falls exactly as symplectic Euler does, and without gravity or
// pins a collision leaves the total momentum of cloth and ball unchanged; nothing ends inside the ball;
// with damping the trampoline catches the ball and comes to rest.
// *****
void stepBallOnCloth(BallOnCloth& scene, Real h);

/// Total linear momentum of the cloth's free particles and the free ball [kg·m/s].
Vec3 totalMomentum(const BallOnCloth& scene);
/// Smallest distance of any particle to the ball's surface minus the margin [m] (negative: inside).
Real deepestBallPenetration(const BallOnCloth& scene);

}  // namespace pba::coursework
