// PBD and XPBD substeps of ClothSolver (solver.h).
//
// One substep (Macklin et al. 2019, "Small steps in physics simulation", Algorithm 1, with the XPBD
// multipliers of Macklin et al. 2016 Algorithm 1):
//   predict   v ← v + h a_ext,  x_prev ← x,  x ← x + h v      (pins follow their path)
//   collide   collider projection without friction (TMP #15 projects its ground before the constraints,
//             so that they start from a valid configuration)
//   solve     λ ← 0; `iterations` Gauss–Seidel sweeps over the distance constraints and bending
//   collide   self-collision, then the collider projection with friction on the substep's whole motion
//             (Macklin et al. 2014 §6.1): no particle ends the substep inside a collider
//   update    v ← (x − x_prev)/h, then velocity damping v ← v e^(−c h)
// Small Steps' point: with the budget substeps × iterations fixed, one iteration per substep gives the
// lowest constraint error and the least artificial damping, because each substep restarts from a good
// prediction and the error of a sweep shrinks with h².
#include <array>
#include <cmath>
#include <limits>

#include "physics/cloth/solver.h"
#include "physics/cloth/xpbd.h"

namespace pba::cloth {

void ClothSolver::positionBasedSubstep(Cloth& cloth, const ClothEnvironment& env, std::span<const Collider> colliders,
                                       const ClothSolverSettings& s, Real h, Real t, Real pinFraction,
                                       ClothStepStats& stats) {
  const std::size_t n = cloth.size();
  force_.assign(n, Vec3(0.0));
  ClothEnvironment external = env;
  external.massDamping = 0.0;  // velocity damping below, after the update
  accumulateExternalForces(cloth, external, t, cloth.position, cloth.velocity, force_);
  previous_ = cloth.position;
  // TMP #15 clamps the speed in every substep, so that the frame's pair list stays complete.
  const Real maxSpeed = s.selfCollision && s.selfCollisionMaxTravel > 0.0
                            ? s.selfCollisionMaxTravel * cloth.material.thickness / h
                            : std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    if (cloth.inverseMass[i] == 0.0) continue;
    cloth.velocity[i] += h * cloth.inverseMass[i] * force_[i];
    const Real speed = glm::length(cloth.velocity[i]);
    if (speed > maxSpeed) cloth.velocity[i] *= maxSpeed / speed;
    cloth.position[i] += h * cloth.velocity[i];
  }
  movePins(cloth, pinFraction);
  collideAll(colliders, cloth.position, previous_, cloth.inverseMass, 0.5 * cloth.material.thickness, h, {}, 0.0);
  solveConstraints(cloth, s, h);
  if (s.longRangeAttachments && !s.tearing.enabled) attachToPins(cloth);
  endSubstep(cloth, colliders, s, h, false, stats);
  const Real damping = std::exp(-env.massDamping * h);
  for (std::size_t i = 0; i < n; ++i) {
    cloth.velocity[i] = (cloth.position[i] - previous_[i]) / h;
    if (cloth.inverseMass[i] != 0.0) cloth.velocity[i] *= damping;
  }
}

void ClothSolver::attachToPins(Cloth& cloth) const {
  // Kim et al. 2012 §4: C(x) = |x − p| − d ≤ 0 with the pin p fixed, so only x moves, straight to the sphere.
  for (const Pin& pin : cloth.pins) {
    const Vec3 p = cloth.position[pin.particle];
    const Vec3 pRest = cloth.restPosition[pin.particle];
    for (std::size_t i = 0; i < cloth.size(); ++i) {
      if (cloth.inverseMass[i] == 0.0) continue;
      const Vec3 r = cloth.position[i] - p;
      const Real d = glm::length(cloth.restPosition[i] - pRest);
      const Real l2 = glm::dot(r, r);
      if (l2 > d * d) cloth.position[i] = p + (d / std::sqrt(l2)) * r;
    }
  }
}

void ClothSolver::solveConstraints(Cloth& cloth, const ClothSolverSettings& s, Real h) {
  const SweepMode mode{s.kind == ClothSolverKind::Xpbd, s.pbdStiffness};
  const SweepMode bendMode{mode.xpbd, s.pbdBendStiffness};
  const std::array<Real, kLinkKinds> alpha = constraintCompliance(cloth.material);
  lambda_.assign(cloth.constraints.size(), 0.0);
  bendLambda_.assign(s.bending == BendingModel::Isometric ? cloth.bending.size() : 0, Vec3(0.0));
  bendLinkLambda_.assign(s.bending == BendingModel::Distance ? cloth.bendLinks.size() : 0, 0.0);
  for (int it = 0; it < s.iterations; ++it) {
    sweepDistanceConstraints(cloth.constraints, alpha, mode, h, cloth.position, cloth.inverseMass, lambda_);
    if (s.bending == BendingModel::Isometric) {
      sweepIsometricBending(cloth.bending, cloth.material.bendCompliance, bendMode, h, cloth.position,
                            cloth.inverseMass, bendLambda_);
    } else if (s.bending == BendingModel::Distance) {
      sweepDistanceConstraints(cloth.bendLinks, alpha, bendMode, h, cloth.position, cloth.inverseMass, bendLinkLambda_);
    }
  }
}

}  // namespace pba::cloth
