// PBD and XPBD substeps of ClothSolver (solver.h).
//
// One substep (Macklin et al. 2019, "Small steps in physics simulation", Algorithm 1, with the XPBD
// multipliers of Macklin et al. 2016 Algorithm 1):
//   predict   v ← v + h a_ext,  x_prev ← x,  x ← x + h v      (pins follow their path)
//   solve     λ ← 0; `iterations` Gauss–Seidel sweeps over the distance constraints and bending
//   collide   self-collision, then collider projection with friction (colliders.h)
//   update    v ← (x − x_prev)/h, then velocity damping v ← v e^(−c h)
// Small Steps' point: with the budget substeps × iterations fixed, one iteration per substep gives the
// lowest constraint error and the least artificial damping, because each substep restarts from a good
// prediction and the error of a sweep shrinks with h².
#include <cmath>

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
  for (std::size_t i = 0; i < n; ++i) {
    if (cloth.inverseMass[i] == 0.0) continue;
    cloth.velocity[i] += h * cloth.inverseMass[i] * force_[i];
    cloth.position[i] += h * cloth.velocity[i];
  }
  movePins(cloth, pinFraction);
  solveConstraints(cloth, s, h);
  endSubstep(cloth, colliders, s, h, false, stats);
  const Real damping = std::exp(-env.massDamping * h);
  for (std::size_t i = 0; i < n; ++i) {
    cloth.velocity[i] = (cloth.position[i] - previous_[i]) / h;
    if (cloth.inverseMass[i] != 0.0) cloth.velocity[i] *= damping;
  }
}

void ClothSolver::solveConstraints(Cloth& cloth, const ClothSolverSettings& s, Real h) {
  const bool xpbd = s.kind == ClothSolverKind::Xpbd;
  const std::array<Real, kLinkKinds> alpha = constraintCompliance(cloth.material);
  lambda_.assign(cloth.constraints.size(), 0.0);
  bendLambda_.assign(cloth.bending.size(), Vec3(0.0));
  std::vector<Vec3>& x = cloth.position;
  const std::vector<Real>& w = cloth.inverseMass;
  for (int it = 0; it < s.iterations; ++it) {
    for (std::size_t k = 0; k < cloth.constraints.size(); ++k) {
      const Link& l = cloth.constraints[k];
      const Real compliance = xpbd ? alpha[static_cast<std::size_t>(l.kind)] : 0.0;
      const DistanceCorrection c = xpbdDistanceCorrection(x[l.i], x[l.j], w[l.i], w[l.j], l.restLength, compliance, h,
                                                          xpbd ? lambda_[k] : 0.0);
      const Real scale = xpbd ? 1.0 : s.pbdStiffness;  // PBD: Müller et al. 2006 §3.3, stiffness per projection
      x[l.i] += scale * c.deltaI;
      x[l.j] += scale * c.deltaJ;
      lambda_[k] += c.deltaLambda;
    }
    if (!s.bending) continue;
    for (std::size_t k = 0; k < cloth.bending.size(); ++k) {
      if (xpbd) {
        projectIsometricBending(cloth.bending[k], x, w, cloth.material.bendCompliance, h, bendLambda_[k]);
      } else {
        // PBD: the exact projection (compliance 0) scaled by the bending stiffness, as for stretch.
        const BendingStencil& b = cloth.bending[k];
        std::array<Vec3, 4> before;
        for (int v = 0; v < 4; ++v) before[v] = x[b.vertex[v]];
        Vec3 unused(0.0);
        projectIsometricBending(b, x, w, 0.0, h, unused);
        for (int v = 0; v < 4; ++v) x[b.vertex[v]] = before[v] + s.pbdBendStiffness * (x[b.vertex[v]] - before[v]);
      }
    }
  }
}

}  // namespace pba::cloth
