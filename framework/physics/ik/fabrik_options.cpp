// FABRIK's two departures of ours (SolveOptions::fabrikHingeTwist, fabrikLimitFit; off by default,
// the published passes being fabrik.cpp and IK-5's fabrik_passes.cpp), and the IK-6 clamp of
// candidate values both passes use.
//
// Why (docs/performance-ik.md, "Trees and analytic IK"): on the hand (ball knuckles within ±60° per
// Euler angle, two one-way hinges per finger), FABRIK as published reaches few goals from rest.
// Two things trap it. (1) The plane a hinge bends in is the one the shortest-arc rule carries along
// from the previous pose: a straight finger whose one-way hinges face away from the goal clamps to
// straight and stays so. (2) IK-6's clamp of a ball joint's Euler angles can land far from the best
// rotation the limits allow, so the forward pass undoes what the backward pass built, and the pose
// jumps from limit to limit between iterations.
#include <algorithm>
#include <cmath>
#include <span>

#include "physics/ik/exercises.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik::detail {

// ---- fabrikLimitFit ------------------------------------------------------------------------------
// Minimise Σ wᵢ |R fromᵢ − goalᵢ|², R = R_pre · Rx(θ₀) Ry(θ₁) Rz(θ₂), over the box of the Euler limits,
// by coordinate sweeps from IK-6's clamp of `wanted`. Angle θₖ turns the points about the world axis
// R_pre · Rx(θ₀)…(θₖ₋₁) · êₖ, so along it the objective is c − ρ cos(θ − ψ) with ψ from alignJoint's
// hinge formula (bestAngle): the best allowed value is the clamp of the representative of ψ nearest
// in angle (bestHingeValue, then IK-6). Each update lowers the objective, so the result is never
// worse than the clamp. Four sweeps: the angles of the hand's knuckles settle within them.
namespace {
constexpr int kLimitFitSweeps = 4;
Vec3 unitAxis(int k) {
  Vec3 a(0.0);
  a[k] = 1.0;
  return a;
}
}  // namespace

bool fitBallWithinLimits(Context& c, int j, const Frame& f, const Quat& wanted, const std::vector<Vec3>& from,
                         const std::vector<Vec3>& goals, const std::vector<Real>& w, std::vector<Vec3>& scratch) {
  const Joint& joint = c.skeleton.joint(j);
  if (joint.type != JointType::Ball || rotationUnlimited(joint) || c.surelyWithinLimits(j, wanted)) return false;
  bool inside = false;
  const Vec3 e = eulerWithinLimits(joint, wanted, &inside);
  if (inside) return false;
  Vec3 x = clampedByLimits(c, j, &e[0], 3);
  scratch.resize(from.size());
  for (int sweep = 0; sweep < kLimitFitSweeps; ++sweep) {
    for (int k = 0; k < 3; ++k) {
      Quat before(1, 0, 0, 0);
      for (int m = 0; m < k; ++m) before = before * glm::angleAxis(x[m], unitAxis(m));
      const Quat R = f.pre * quatFromEulerXYZ(x);
      for (size_t i = 0; i < from.size(); ++i) scratch[i] = R * from[i];
      const Real theta = bestAngle(f.pre * (before * unitAxis(k)), Vec3(0.0), scratch, goals, w);
      Vec3 trial = x;
      trial[k] = bestHingeValue(x[k] + theta, joint.lo[k], joint.hi[k], true);
      x = clampedByLimits(c, j, &trial[0], 3);
    }
  }
  Real* dofs = c.pose.dofs.data() + joint.firstDof;
  for (int k = 0; k < 3; ++k) dofs[k] = x[k];
  c.local[static_cast<size_t>(j)] = jointRotation(joint, c.pose, j);
  c.staleEuler[static_cast<size_t>(j)] = 0;
  return true;
}

// ---- fabrikHingeTwist ----------------------------------------------------------------------------
// In the backward pass the part of the tree below hinge k (body k and its descendants) is placed and
// carries one position effector, which the point rule has put on its goal g. The part may turn as one
// rigid piece about the line from k's pivot P to g: the effector stays on g and the part keeps its
// shape, so everything the pass has built still holds. A turn by φ about d = (g − P)/|g − P| carries
// the hinge's world axis w₀ to
//   w(φ) = w∥ + cos φ w⊥ + sin φ (d × w⊥)        (w∥ = (w₀·d) d, w⊥ = w₀ − w∥),
// and the hinge's plane (normal w) holds the parent's previous pivot oldP when w(φ)·v = 0, v = oldP − P:
//   A cos φ + B sin φ = −C,  A = w⊥·v, B = (d × w⊥)·v, C = w∥·v,
//   φ = β ± acos(−C/r),  β = atan2(B, A),  r = √(A² + B²)   (|C| > r: acos(±1), the nearest plane).
// The two roots lay the plane through oldP with the hinge's axis pointing either way, so a one-way
// hinge bends toward oldP in one of them. Limiting cases: g at P, or r = 0 (w₀ or v along d): no turn
// changes the plane.
int hingePlaneTurns(const Vec3& axis, const Vec3& pivot, const Vec3& goal, const Vec3& oldP, Vec3* d, Real* phi) {
  const Vec3 toGoal = goal - pivot, v = oldP - pivot;
  const Real length = glm::length(toGoal), lever = glm::length(v);
  if (!(length > 1e-12) || !(lever > 1e-12)) return 0;
  *d = toGoal / length;
  const Vec3 wPar = glm::dot(axis, *d) * *d, wPerp = axis - wPar;
  const Real A = glm::dot(wPerp, v), B = glm::dot(glm::cross(*d, wPerp), v), C = glm::dot(wPar, v);
  const Real r = std::sqrt(A * A + B * B);
  if (!(r > 1e-12 * lever)) return 0;
  const Real beta = std::atan2(B, A), alpha = std::acos(std::clamp(-C / r, -1.0, 1.0));
  phi[0] = std::remainder(beta + alpha, 2.0 * kPi);
  phi[1] = std::remainder(beta - alpha, 2.0 * kPi);
  return 2;
}

void DeferredTurns::build(const Context& c) {
  const int J = c.skeleton.jointCount();
  effector_.assign(static_cast<size_t>(J), -1);
  for (int j = 0; j < J; ++j) {
    const std::span<const int> below = c.effectorsBelow(j);
    if (below.size() == 1 && c.effectors[static_cast<size_t>(below[0])].kind == EffectorKind::Position)
      effector_[static_cast<size_t>(j)] = below[0];
  }
  turns_.assign(c.effectors.size(), Motion{});
  placed_.assign(static_cast<size_t>(J), Motion{});
}

void DeferredTurns::reset() { std::fill(turns_.begin(), turns_.end(), Motion{}); }

// The part's motion so far, M: x ↦ q_M x + t_M, followed by the turn T: x ↦ q (x − p) + p, is
// T ∘ M: x ↦ q q_M x + q (t_M − p) + p.
Quat DeferredTurns::turn(int k, Real phi, const Vec3& d, const Vec3& pivot, const Quat& R) {
  const Quat q = glm::angleAxis(phi, d);
  Motion& m = turns_[static_cast<size_t>(effectorOf(k))];
  m = Motion{glm::normalize(q * m.q), q * (m.t - pivot) + pivot};
  placed_[static_cast<size_t>(k)] = m;
  return glm::normalize(q * R);
}

// A joint placed when the part's motion was N and now is M moves by M ∘ N⁻¹: x ↦ q_M q_N⁻¹ (x − t_N) + t_M.
void DeferredTurns::apply(const Context& c, std::vector<Vec3>& P, std::vector<Quat>& R) const {
  for (size_t j = 0; j < effector_.size(); ++j) {
    if (effector_[j] < 0 || !c.active[j]) continue;
    const Motion& now = turns_[static_cast<size_t>(effector_[j])];
    const Motion& then = placed_[j];
    if (now.q == then.q && now.t == then.t) continue;
    const Quat q = glm::normalize(now.q * glm::conjugate(then.q));
    P[j] = q * (P[j] - then.t) + now.t;
    R[j] = glm::normalize(q * R[j]);
  }
}

}  // namespace pba::ik::detail
