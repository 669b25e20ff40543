#include "physics/cloth/solver.h"

#include <algorithm>
#include <cmath>

#include "physics/cloth/xpbd.h"

namespace pba::cloth {

bool usesSprings(ClothSolverKind kind) {
  return kind == ClothSolverKind::Explicit || kind == ClothSolverKind::Implicit;
}

Status validate(const ClothSolverSettings& s) {
  if (s.substeps < 1 || s.substeps > 1000)
    return Error{"substeps: must be in [1, 1000], got " + std::to_string(s.substeps)};
  if (s.iterations < 1 || s.iterations > 1000)
    return Error{"iterations: must be in [1, 1000], got " + std::to_string(s.iterations)};
  if (!(s.pbdStiffness > 0.0 && s.pbdStiffness <= 1.0)) return Error{"pbdStiffness: must be in (0, 1]"};
  if (!(s.pbdBendStiffness >= 0.0 && s.pbdBendStiffness <= 1.0)) return Error{"pbdBendStiffness: must be in [0, 1]"};
  if (!(s.selfFriction >= 0.0 && s.selfFriction <= 1.0)) return Error{"selfFriction: must be in [0, 1]"};
  if (s.implicit.cg.maxIterations < 1) return Error{"cgMaxIterations: must be ≥ 1"};
  if (!(s.implicit.cg.tolerance > 0.0 && s.implicit.cg.tolerance < 1.0)) return Error{"cgTolerance: must be in (0, 1)"};
  if (s.tearing.enabled && !(s.tearing.threshold > 0.0)) return Error{"tearThreshold: must be > 0"};
  if (!(s.implicit.maxStrainGrowth >= 0.0)) return Error{"maxStrainGrowth: must be ≥ 0 (0 = no step control)"};
  if (s.implicit.maxHalvings < 0 || s.implicit.maxHalvings > 20)
    return Error{"maxHalvings: must be in [0, 20], got " + std::to_string(s.implicit.maxHalvings)};
  if (!(s.divergedSpeed >= 0.0)) return Error{"divergedSpeed: must be ≥ 0 (0 = no check)"};
  if (!(s.explicitLimitFraction >= 0.0 && s.explicitLimitFraction <= 1.0))
    return Error{"explicitLimitFraction: must be in [0, 1] (0 = the substeps asked)"};
  return Status::success();
}

StrainStats edgeStrain(const Cloth& cloth) {
  StrainStats s;
  if (cloth.constraints.empty()) return s;
  for (const Link& l : cloth.constraints) {
    const Real e = (glm::length(cloth.position[l.i] - cloth.position[l.j]) - l.restLength) / l.restLength;
    s.max = std::max(s.max, e);
    s.mean += std::max(0.0, e);
    s.maxCompression = std::max(s.maxCompression, -e);
  }
  s.mean /= static_cast<Real>(cloth.constraints.size());
  return s;
}

Real clothEnergy(const Cloth& cloth, const ClothEnvironment& env, ClothSolverKind kind, BendingModel bending) {
  Real e = kineticEnergy(cloth) + gravityEnergy(cloth, env.gravity);
  if (usesSprings(kind)) return e + springEnergy(cloth.springs, cloth.material, cloth.position);
  e += constraintEnergy(cloth.constraints, cloth.position, cloth.material);
  if (bending == BendingModel::Isometric)
    e += bendingEnergy(cloth.bending, cloth.position, cloth.material.bendCompliance);
  if (bending == BendingModel::Distance) e += constraintEnergy(cloth.bendLinks, cloth.position, cloth.material);
  return e;
}

Real explicitStabilityLimit(const Cloth& cloth) {
  const std::array<Real, kLinkKinds> k = springStiffness(cloth.material);
  std::vector<Real> sum(cloth.size(), 0.0);  // Σ k of the springs at each particle
  for (const Link& s : cloth.springs) {
    sum[s.i] += k[static_cast<std::size_t>(s.kind)];
    sum[s.j] += k[static_cast<std::size_t>(s.kind)];
  }
  Real omega2 = 0.0;
  for (std::size_t i = 0; i < cloth.size(); ++i) omega2 = std::max(omega2, 2.0 * sum[i] * cloth.inverseMass[i]);
  return omega2 > 0.0 ? 2.0 / std::sqrt(omega2) : std::numeric_limits<Real>::infinity();
}

int stableExplicitSubsteps(const Cloth& cloth, Real dt, Real fraction) {
  const Real needed = std::ceil(dt / (fraction * explicitStabilityLimit(cloth)));
  return needed >= kMaxStableSubsteps ? kMaxStableSubsteps : std::max(1, static_cast<int>(needed));
}

void ClothSolver::reset() {
  implicit_ = ImplicitWorkspace{};
  self_ = SelfCollision{};
  lambda_.clear();
  bendLambda_.clear();
  bendLinkLambda_.clear();
}

Vec3 ClothSolver::pinOnItsPath(const Cloth& cloth, std::size_t k, Real fraction) const {
  const Vec3& target = cloth.pins[k].target;
  return fraction >= 1.0 ? target : pinStart_[k] + fraction * (target - pinStart_[k]);
}

void ClothSolver::movePins(Cloth& cloth, Real fraction) {
  for (std::size_t k = 0; k < cloth.pins.size(); ++k)
    cloth.position[cloth.pins[k].particle] = pinOnItsPath(cloth, k, fraction);
}

namespace {
// v is faster than √limit2 or not finite (the comparison is false for NaN).
bool fasterThan(const Vec3& v, Real limit2) { return !(glm::dot(v, v) <= limit2); }
// Some velocity is faster than `limit` or not finite (limit 0: never).
bool diverged(std::span<const Vec3> velocity, Real limit) {
  if (limit <= 0.0) return false;
  bool tooFast = false;
  for (const Vec3& v : velocity) tooFast |= fasterThan(v, limit * limit);
  return tooFast;
}
}  // namespace

ClothStepStats ClothSolver::step(Cloth& cloth, const ClothEnvironment& env, std::span<const Collider> colliders,
                                 const ClothSolverSettings& s, Real dt, Real t) {
  ClothStepStats stats;
  int n = std::max(1, s.substeps);
  if (s.kind == ClothSolverKind::Explicit && s.explicitLimitFraction > 0.0)
    n = std::max(n, stableExplicitSubsteps(cloth, dt, s.explicitLimitFraction));
  stats.substepsPlanned = n;
  const Real h = dt / n;
  if (diverged(cloth.velocity, s.divergedSpeed)) {
    stats.diverged = true;  // nothing to gain from stepping a blown-up state; the lab's guard pauses
    return stats;
  }
  if (s.selfCollision) beginSelfCollision(cloth, s, dt);
  pinStart_.resize(cloth.pins.size());
  for (std::size_t k = 0; k < cloth.pins.size(); ++k) pinStart_[k] = cloth.position[cloth.pins[k].particle];
  for (int k = 0; k < n && !stats.diverged; ++k) {
    ++stats.substepsTaken;
    const Real fraction = static_cast<Real>(k + 1) / n;
    const Real time = t + k * h;
    switch (s.kind) {
      case ClothSolverKind::Explicit:
        explicitSubstep(cloth, env, colliders, s, h, time, fraction, stats);
        break;
      case ClothSolverKind::Implicit:
        implicitSpan(cloth, env, colliders, s, time, h, static_cast<Real>(k) / n, fraction, 0, stats);
        break;
      case ClothSolverKind::Pbd:
      case ClothSolverKind::Xpbd:
        positionBasedSubstep(cloth, env, colliders, s, h, time, fraction, stats);
        break;
    }
  }
  stats.constraintIterations = usesSprings(s.kind) ? 0 : n * s.iterations;
  stats.tears = tearOverstretched(cloth, s.tearing);
  if (stats.tears > 0) implicit_.colouredSprings = ~std::size_t{0};
  return stats;
}

namespace {
/// Largest growth of a stretch or shear spring's strain |l − L| / L from positions x0 to x1 (a spring that
/// relaxes counts 0; bend springs shorten by design when the cloth folds).
Real largestStrainGrowth(std::span<const Link> springs, std::span<const Vec3> x0, std::span<const Vec3> x1) {
  Real largest = 0.0;
  for (const Link& l : springs) {
    if (l.kind == LinkKind::Bend) continue;
    const Real before = std::abs(glm::length(x0[l.j] - x0[l.i]) - l.restLength);
    const Real after = std::abs(glm::length(x1[l.j] - x1[l.i]) - l.restLength);
    largest = std::max(largest, (after - before) / l.restLength);
  }
  return largest;
}
}  // namespace

void ClothSolver::implicitSpan(Cloth& cloth, const ClothEnvironment& env, std::span<const Collider> colliders,
                               const ClothSolverSettings& s, Real t, Real h, Real from, Real to, int halvings,
                               ClothStepStats& stats) {
  // Pins move along their path within the step: each implicit step aims at its share of it.
  std::vector<Pin> finalPins = cloth.pins;
  for (std::size_t p = 0; p < cloth.pins.size(); ++p) cloth.pins[p].target = pinOnItsPath(cloth, p, to);
  const bool control = s.implicit.maxStrainGrowth > 0.0 && halvings < s.implicit.maxHalvings;
  previous_ = cloth.position;
  if (control) {
    savedVelocity_ = cloth.velocity;
    savedReleased_ = implicit_.released;
    savedSticking_ = implicit_.sticking;
  }
  const ImplicitStats is = implicitStep(cloth, env, colliders, s.implicit, h, t, implicit_);
  cloth.pins = std::move(finalPins);
  if (control && largestStrainGrowth(cloth.springs, previous_, cloth.position) > s.implicit.maxStrainGrowth) {
    cloth.position = previous_;
    cloth.velocity = savedVelocity_;
    implicit_.released = savedReleased_;
    implicit_.sticking = savedSticking_;
    ++stats.implicitRetries;
    const Real middle = 0.5 * (from + to);
    implicitSpan(cloth, env, colliders, s, t, 0.5 * h, from, middle, halvings + 1, stats);
    implicitSpan(cloth, env, colliders, s, t + 0.5 * h, 0.5 * h, middle, to, halvings + 1, stats);
    return;
  }
  stats.cgIterations = is.cg.iterations;
  stats.cgResidual = is.cg.relativeResidual;
  endSubstep(cloth, colliders, s, h, true, stats);
}

void ClothSolver::beginSelfCollision(Cloth& cloth, const ClothSolverSettings& s, Real dt) {
  // TMP #15: clamp the speed to the travel limit, then the pairs once for the frame.
  const Real thickness = cloth.material.thickness;
  Real reach = thickness;
  if (s.selfCollisionMaxTravel > 0.0) {
    const Real maxSpeed = s.selfCollisionMaxTravel * thickness * std::max(1, s.substeps) / dt;
    for (Vec3& v : cloth.velocity) {
      const Real speed = glm::length(v);
      if (speed > maxSpeed) v *= maxSpeed / speed;
    }
    reach = thickness + maxSpeed * dt;  // TMP queries maxSpeed·dt; one thickness more for the pair
  } else {
    Real fastest = 0.0;
    for (const Vec3& v : cloth.velocity) fastest = std::max(fastest, glm::length(v));
    reach += 2.0 * (fastest + glm::length(Vec3(0.0, kStandardGravity, 0.0)) * dt) * dt;
  }
  self_.buildPairs(cloth.position, cloth.restPosition, thickness, reach, s.selfCollisionNearList);
}

void ClothSolver::explicitSubstep(Cloth& cloth, const ClothEnvironment& env, std::span<const Collider> colliders,
                                  const ClothSolverSettings& s, Real h, Real t, Real pinFraction,
                                  ClothStepStats& stats) {
  // Symplectic Euler (Lobb notes, "simple loop"): v += h M⁻¹ f(x, v), then x += h v with the new v.
  const std::size_t n = cloth.size();
  force_.assign(n, Vec3(0.0));
  accumulateSpringForces(cloth.springs, cloth.material, cloth.position, cloth.velocity, true, force_);
  accumulateExternalForces(cloth, env, t, cloth.position, cloth.velocity, force_);
  previous_ = cloth.position;
  const Real limit2 = s.divergedSpeed * s.divergedSpeed;
  bool tooFast = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (cloth.inverseMass[i] == 0.0) continue;
    cloth.velocity[i] += h * cloth.inverseMass[i] * force_[i];
    cloth.position[i] += h * cloth.velocity[i];
    tooFast |= fasterThan(cloth.velocity[i], limit2);
  }
  // This substep ends as usual; the step takes no more (the rest would only spend time on a blow-up).
  stats.diverged = tooFast && s.divergedSpeed > 0.0;
  movePins(cloth, pinFraction);
  for (const Pin& p : cloth.pins) cloth.velocity[p.particle] = (cloth.position[p.particle] - previous_[p.particle]) / h;
  endSubstep(cloth, colliders, s, h, true, stats);
}

void ClothSolver::endSubstep(Cloth& cloth, std::span<const Collider> colliders, const ClothSolverSettings& s, Real h,
                             bool velocityLevel, ClothStepStats& stats) {
  const std::span<Vec3> velocities = velocityLevel ? std::span<Vec3>(cloth.velocity) : std::span<Vec3>();
  if (s.selfCollision) {
    if (velocityLevel) beforeSelf_ = cloth.position;
    for (int sweep = 0; sweep < std::max(1, s.selfCollisionSweeps); ++sweep) {
      // Between sweeps, the colliders without friction for the particles in contact: the next sweep
      // starts from them outside the colliders and makes again the pushes the colliders undid (further
      // sweeps so keep a pile on the floor from pressing its lowest layers together). Friction acts once,
      // in the last pass.
      if (sweep > 0) {
        collideListed(colliders, self_.contactParticles(), cloth.position, previous_, cloth.inverseMass,
                      0.5 * cloth.material.thickness, h);
      }
      const std::size_t contacts =
          self_.solve(cloth.position, previous_, cloth.inverseMass, cloth.material.thickness, s.selfFriction, sweep > 0)
              .contacts;
      if (sweep == 0) stats.selfContacts = contacts;
    }
    if (velocityLevel) {
      for (std::size_t i = 0; i < cloth.size(); ++i) cloth.velocity[i] += (cloth.position[i] - beforeSelf_[i]) / h;
    }
  }
  stats.contacts =
      collideAll(colliders, cloth.position, previous_, cloth.inverseMass, 0.5 * cloth.material.thickness, h, velocities)
          .contacts;
}

}  // namespace pba::cloth
