// alignJoint: the one joint update shared by CCD (Workbook §2.4) and FABRIK's return from positions to
// joint angles. Derivation for a rotation R(θ) about a unit world axis a through the pivot p, points
// uᵢ = fromᵢ − p, vᵢ = toᵢ − p, weights wᵢ:
//   Σ wᵢ |R uᵢ − vᵢ|² = const − 2 Σ wᵢ vᵢ·R uᵢ,   vᵢ·R uᵢ = vᵢ∥·uᵢ∥ + cos θ (u⊥ᵢ·v⊥ᵢ) + sin θ a·(u⊥ᵢ × v⊥ᵢ)
// so the exact minimiser is θ = atan2(Σ wᵢ a·(uᵢ × vᵢ), Σ wᵢ u⊥ᵢ·v⊥ᵢ) (⊥: component normal to a).
// For a translation d along a: d = Σ wᵢ a·(vᵢ − uᵢ) / Σ wᵢ. A single point on a ball or free joint is
// turned exactly by the shortest arc; the Euler DOFs are then read back from the new local rotation.
// Limiting cases: uᵢ ∥ a or vᵢ = 0 contribute nothing (atan2(0, 0) = 0: no motion, no NaN).
#include <algorithm>
#include <cmath>

#include "physics/ik/exercises.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik::detail {

const Quat& setJointRotation(Context& c, int j, const Quat& wanted, bool clampLimits) {
  const Joint& joint = c.skeleton.joint(j);
  const bool clampNow =
      clampLimits && !(joint.type == JointType::Ball && c.surelyWithinLimits(j, wanted)) && !rotationUnlimited(joint);
  // Written in place and returned from there: a local copy or a returned one would be stored and read
  // back at once in pieces of other sizes (a store-forwarding stall on every call).
  Quat& local = c.local[static_cast<size_t>(j)];
  if (joint.type == JointType::Ball) {
    if (clampNow) {
      Real* dofs = c.pose.dofs.data() + joint.firstDof;
      const Vec3 e = eulerWithinLimits(joint, wanted);
      for (int k = 0; k < 3; ++k) dofs[k] = e[k];
      clampJointToLimits(c.skeleton, c.pose, j);
      const bool clamped = dofs[0] != e[0] || dofs[1] != e[1] || dofs[2] != e[2];
      local = clamped ? jointRotation(joint, c.pose, j) : wanted;
    } else {
      local = wanted;
    }
    c.staleEuler[static_cast<size_t>(j)] = !clampNow;  // unclamped: flushPose() writes the Euler angles
  } else {
    c.pose.rotations[static_cast<size_t>(j)] = wanted;
    if (clampNow) clampJointToLimits(c.skeleton, c.pose, j);
    local = c.pose.rotations[static_cast<size_t>(j)];
  }
  return local;
}

namespace {

// Turns joint j by the world rotation `world` about its pivot: its local rotation becomes
// R_pre⁻¹ · world · R_pre · oldLocal (ball: stored as XYZ Euler angles; free: directly), clamped to the
// limits; `oldWorld` = R_pre · oldLocal is the joint's current world rotation (Frame::rotation).
// Keeps c.local[j] current and returns the world rotation actually applied (`world` itself unless
// clamping changed it). An unclamped ball update needs no sincos (the Euler round trip is the
// same rotation), and when no limit can act the Euler angles are written later (flushPose).
Quat turnJoint(Context& c, int j, const Frame& f, const Quat oldLocal, const Quat& oldWorld, const Quat& world,
               bool clampLimits) {
  const Quat preInverse = glm::conjugate(f.pre);
  const Quat wanted = glm::normalize(preInverse * (world * oldWorld));
  const Quat newLocal = setJointRotation(c, j, wanted, clampLimits);
  if (newLocal == wanted) return world;
  return f.pre * newLocal * glm::conjugate(oldLocal) * preInverse;
}

// `q` turned by at most `maxTurn` [rad] about its own axis (SolveOptions::ccdMaxTurn, ours); q itself
// when maxTurn is 0 or q turns less. q = ±(cos ½θ, sin ½θ n̂): the turn exceeds the cap when |w| < cos ½cap.
Quat capTurn(const Quat& q, Real maxTurn) {
  if (!(maxTurn > 0.0) || std::abs(q.w) >= std::cos(0.5 * maxTurn)) return q;
  const Vec3 v(q.x, q.y, q.z);
  const Real length = glm::length(v);
  if (!(length > 0.0)) return q;
  const Vec3 n = (q.w < 0.0 ? -1.0 : 1.0) * v / length;
  return glm::angleAxis(std::min(maxTurn, kPi), n);
}

}  // namespace

void bestAngleTerms(const Vec3& a, const Vec3& p, const std::vector<Vec3>& from, const std::vector<Vec3>& to,
                    const std::vector<Real>& w, Real* S, Real* C) {
  *S = 0.0;
  *C = 0.0;
  for (size_t i = 0; i < from.size(); ++i) {
    const Vec3 u = perpendicularPart(from[i] - p, a), v = perpendicularPart(to[i] - p, a);
    *S += w[i] * glm::dot(a, glm::cross(u, v));
    *C += w[i] * glm::dot(u, v);
  }
}

Real bestAngle(const Vec3& a, const Vec3& p, const std::vector<Vec3>& from, const std::vector<Vec3>& to,
               const std::vector<Real>& w) {
  Real S = 0.0, C = 0.0;
  bestAngleTerms(a, p, from, to, w, &S, &C);
  return std::atan2(S, C);
}

void hingeRanges(const Skeleton& s, std::vector<HingeRange>& out) {
  out.assign(static_cast<size_t>(s.jointCount()), {});
  for (int j = 0, last = -1; j < s.jointCount(); ++j) {
    const Joint& joint = s.joint(j);
    if (joint.type != JointType::Hinge || !(joint.lo[0] > -kPi && joint.hi[0] < kPi)) continue;
    if (last >= 0 && s.joint(last).lo[0] == joint.lo[0] && s.joint(last).hi[0] == joint.hi[0]) {
      out[static_cast<size_t>(j)] = out[static_cast<size_t>(last)];
    } else {
      const Real mid = 0.5 * (joint.lo[0] + joint.hi[0]), half = 0.5 * (joint.hi[0] - joint.lo[0]);
      out[static_cast<size_t>(j)] = {std::cos(mid), std::sin(mid), std::cos(half), true};
    }
    last = j;
  }
}

bool turnHingeWithinLimits(Context& c, int j, const Frame& f, const HingeRange& range, const std::vector<Vec3>& from,
                           const std::vector<Vec3>& to, const std::vector<Real>& w) {
  const Joint& joint = c.skeleton.joint(j);
  Real S = 0.0, C = 0.0;
  bestAngleTerms(f.pre * joint.axis, f.position, from, to, w, &S, &C);
  const Quat& q = c.local[static_cast<size_t>(j)];
  const Real s = glm::dot(Vec3(q.x, q.y, q.z), joint.axis), cosD = q.w * q.w - s * s, sinD = 2.0 * q.w * s;
  const Real cx = cosD * C - sinD * S, sx = sinD * C + cosD * S, r = std::sqrt(cx * cx + sx * sx);
  if (!range.holds(cx, sx, r)) return false;
  c.local[static_cast<size_t>(j)] =
      glm::normalize(Quat(r + cx, sx * joint.axis.x, sx * joint.axis.y, sx * joint.axis.z));
  c.staleEuler[static_cast<size_t>(j)] = 1;
  return true;
}

// The hinge optimum is an angle modulo 2π. Of the representatives ψ − 2π, ψ, ψ + 2π, pick the one
// whose clamped value is closest to the optimum in angle (the objective is proportional to
// cos(value − ψ)): a joint at 100° with limits ±120° that should turn +170° goes to −90°, not to 120°.
// The common case at a limit is told without cosines: ψ beyond one limit by x₀ ≤ π/2, and the clamped
// values of ψ ± 2π either that limit (the same score less the tie-break) or at least 0.01 rad farther
// from ψ in angle (e ≤ π). Then ψ's score exceeds the latter's by
// cos x₀ − cos e = 2 sin ½(x₀ + e) sin ½(e − x₀) ≥ 2 sin² 0.005 ≈ 5·10⁻⁵, which neither rounding nor the
// 10⁻⁹ tie-break can overturn: the loop would return ψ itself, and so does the shortcut (same bits; a
// CCD pass on a chain bent to its limits made three cosines per joint here).
Real bestHingeValue(Real psi, Real lo, Real hi, bool clampLimits) {
  if (!clampLimits || (psi >= lo && psi <= hi)) return psi;
  const Real x0 = psi > hi ? psi - hi : lo - psi;
  if (x0 <= 0.5 * kPi) {
    bool clear = true;
    const Real limit = psi > hi ? hi : lo;
    for (Real candidate : {psi - 2.0 * kPi, psi + 2.0 * kPi}) {
      const Real clamped = std::clamp(candidate, lo, hi);
      if (clamped == limit) continue;  // the same score as ψ's less the tie-break: ψ wins
      Real e = std::abs(clamped - psi);
      if (e > kPi) e = std::abs(e - 2.0 * kPi);
      clear = clear && e <= kPi && e >= x0 + 0.01;
    }
    if (clear) return psi;
  }
  Real best = psi, bestScore = -2.0;
  for (Real candidate : {psi - 2.0 * kPi, psi, psi + 2.0 * kPi}) {
    const Real clamped = std::clamp(candidate, lo, hi);
    const Real score = std::cos(clamped - psi) - 1e-9 * std::abs(candidate - psi);
    if (score > bestScore) {
      bestScore = score;
      best = candidate;
    }
  }
  return best;
}

namespace {
// x, or x ± 2π, inside [lo, hi]; else the one of them nearest the interval. *violation: its distance.
Real shiftInto(Real x, Real lo, Real hi, Real* violation) {
  Real best = x, bestViolation = 1e300;
  for (Real candidate : {x, x - 2.0 * kPi, x + 2.0 * kPi}) {
    const Real v = std::max(0.0, lo - candidate) + std::max(0.0, candidate - hi);
    if (v < bestViolation) bestViolation = v, best = candidate;
  }
  *violation += bestViolation;
  return best;
}
// std::remainder(x, 2π), without the call when |x| ≤ π: the remainder is exact and its quotient then 0,
// so it is x itself.
Real remainderTwoPi(Real x) { return std::abs(x) <= kPi ? x : std::remainder(x, 2.0 * kPi); }
}  // namespace

Vec3 eulerWithinLimits(const Joint& joint, const Quat& q, bool* inside) {
  const Vec3 principal = eulerXYZFromQuat(q);
  if (principal.x >= joint.lo[0] && principal.x <= joint.hi[0] && principal.y >= joint.lo[1] &&
      principal.y <= joint.hi[1] && principal.z >= joint.lo[2] && principal.z <= joint.hi[2]) {  // the common case
    if (inside) *inside = true;
    return principal;
  }
  Vec3 out[2] = {principal, Vec3(principal.x + kPi, kPi - principal.y, principal.z + kPi)};
  Real violation[2] = {0.0, 0.0};
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < 3; ++k)
      out[r][k] = shiftInto(remainderTwoPi(out[r][k]), joint.lo[k], joint.hi[k], &violation[r]);
  const int pick = violation[1] < violation[0] ? 1 : 0;
  if (inside) *inside = violation[pick] == 0.0;
  return out[pick];
}

bool rotationUnlimited(const Joint& joint) {
  if (joint.type == JointType::Free) return joint.maxRotation >= kPi;
  if (joint.type != JointType::Ball) return false;
  return joint.lo[0] <= -kPi && joint.hi[0] >= kPi && joint.lo[1] <= -0.5 * kPi && joint.hi[1] >= 0.5 * kPi &&
         joint.lo[2] <= -kPi && joint.hi[2] >= kPi;
}

Quat alignJoint(Context& c, int j, const Frame& f, const std::vector<Vec3>& from, const std::vector<Vec3>& to,
                const std::vector<Real>& w, bool clampLimits, bool useExercise, Vec3* translation, Real maxTurn) {
  const Skeleton& s = c.skeleton;
  Pose& pose = c.pose;
  const Joint& joint = s.joint(j);
  if (translation) *translation = Vec3(0.0);
  if (from.empty()) return Quat(1, 0, 0, 0);
  const Vec3 p = f.position;
  switch (joint.type) {
    case JointType::Fixed:
      return Quat(1, 0, 0, 0);
    case JointType::Prismatic: {
      const Vec3 a = f.pre * joint.axis;
      Real num = 0.0, den = 0.0;
      for (size_t i = 0; i < from.size(); ++i) {
        num += w[i] * glm::dot(a, to[i] - from[i]);
        den += w[i];
      }
      Real& d = pose.dofs[static_cast<size_t>(joint.firstDof)];
      const Real old = d;
      if (den > 0.0) d += num / den;
      if (clampLimits) clampJointToLimits(s, pose, j);
      if (translation) *translation = a * (d - old);
      return Quat(1, 0, 0, 0);
    }
    case JointType::Hinge: {
      const Vec3 a = f.pre * joint.axis;
      Real theta = 0.0;
      if (from.size() == 1 && useExercise) {
        // Workbook Algorithm 1 on the projections onto the hinge plane: the update's axis is ±a.
        const Quat q = ccdJointUpdate(p, p + perpendicularPart(from[0] - p, a), p + perpendicularPart(to[0] - p, a));
        theta = glm::dot(rotationVector(q), a);
      } else {
        theta = bestAngle(a, p, from, to, w);
      }
      if (maxTurn > 0.0) theta = std::clamp(theta, -maxTurn, maxTurn);  // SolveOptions::ccdMaxTurn (ours)
      Real& d = pose.dofs[static_cast<size_t>(joint.firstDof)];
      const Real old = d;
      d = bestHingeValue(old + theta, joint.lo[0], joint.hi[0], clampLimits);
      if (clampLimits) clampJointToLimits(s, pose, j);
      // CCD's hinge held at a limit it is pushed against keeps its angle: its cached rotation is already
      // jointRotation's of that angle (CCD sets a hinge's `local` only here and in refresh(); with ccdMaxTurn
      // also turnHingeCapped, the same rotation to rounding), and
      // angleAxis(0, a) is exactly (1, 0 a). Two sincos fewer per such joint and pass, same bits.
      if (useExercise && d == old) return Quat(1.0, a * 0.0);
      c.local[static_cast<size_t>(j)] = jointRotation(joint, pose, j);
      return glm::angleAxis(d - old, a);
    }
    case JointType::Ball:
    case JointType::Free: {
      const Quat oldLocal = c.local[static_cast<size_t>(j)];
      if (from.size() == 1) {
        const Quat world = useExercise ? ccdJointUpdate(p, from[0], to[0]) : shortestArc(from[0] - p, to[0] - p);
        return turnJoint(c, j, f, oldLocal, f.rotation, capTurn(world, maxTurn), clampLimits);
      }
      // Several points: a few sweeps of exact single-axis updates about the axis Σ wᵢ uᵢ × vᵢ (the
      // direction of steepest descent of the rotation), each the closed form above.
      std::vector<Vec3> moved = from;
      Quat total(1, 0, 0, 0);
      for (int sweep = 0; sweep < 3; ++sweep) {
        Vec3 axis(0.0);
        for (size_t i = 0; i < moved.size(); ++i) axis += w[i] * glm::cross(moved[i] - p, to[i] - p);
        const Real length = glm::length(axis);
        if (length < 1e-15) break;
        axis /= length;
        Real theta = bestAngle(axis, p, moved, to, w);
        if (maxTurn > 0.0) theta = std::clamp(theta, -maxTurn, maxTurn);
        const Quat current = c.local[static_cast<size_t>(j)];
        const Quat applied = turnJoint(c, j, f, current, f.pre * current, glm::angleAxis(theta, axis), clampLimits);
        for (Vec3& m : moved) m = p + applied * (m - p);
        total = applied * total;
      }
      return total;
    }
  }
  return Quat(1, 0, 0, 0);
}

}  // namespace pba::ik::detail
