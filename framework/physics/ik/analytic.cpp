// Analytic IK: IK-1 (one joint from the dot and cross products), the two-bone law-of-cosines solution
// with a pole direction, and the "analytic" solver that applies them to a skeleton whose effector
// hangs below one or two moving joints.
#include "physics/ik/analytic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "physics/exercises/not_implemented.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik {

// ***** IK-1: single-joint analytic IK (Workbook §2.1 task 2) *****
// Inputs in world axes: the bone's direction and the direction from the joint to the target (any
// lengths). Output: the unit axis and the angle θ in [0, π] [rad] of the smallest rotation that turns the
// first direction onto the second.
// (1) Only directions matter. If either is (almost) zero there is nothing to do: angle 0, any axis.
// (2) Which two products of the directions give the axis and the cosine and sine of the angle? Get θ
//     from them with an inverse trigonometric function that stays exact near 0 and π and never returns
//     NaN for a cosine rounded slightly above 1.
// (3) Parallel directions: θ = 0 (keep any axis). Opposite ones: a half turn about any axis
//     perpendicular to the bone (anyPerpendicular).
// Check: the returned rotation applied to the bone direction gives the target direction; θ = π/2 for
// perpendicular directions; the axis has unit length.
// *****
AxisAngle analyticSingleJoint([[maybe_unused]] const Vec3& boneDirection, [[maybe_unused]] const Vec3& toTarget) {
  // BEGIN SOLUTION
  const Real lb = glm::length(boneDirection), lt = glm::length(toTarget);
  if (lb < 1e-12 || lt < 1e-12) return {};
  const Vec3 b = boneDirection / lb, t = toTarget / lt;
  const Vec3 axis = glm::cross(b, t);
  const Real s = glm::length(axis), c = glm::dot(b, t);
  if (s < 1e-12) return c > 0.0 ? AxisAngle{} : AxisAngle{anyPerpendicular(b), kPi};
  return {axis / s, std::atan2(s, c)};
  // END SOLUTION
  // STUB: return exercises::notImplemented("IK-1", AxisAngle{});
}

TwoBonePose twoBoneGeometry(const Vec3& s, Real a, Real b, const Vec3& t, const Vec3& pole) {
  TwoBonePose out;
  const Vec3 st = t - s;
  const Real dRaw = glm::length(st);
  const Real dMin = std::abs(a - b), dMax = a + b;
  const Real d = std::clamp(dRaw, dMin, dMax);
  out.reachable = dRaw >= dMin - 1e-12 && dRaw <= dMax + 1e-12;
  // Directions: n̂ toward the target (any axis when the target sits on the shoulder), m̂ toward the pole.
  Vec3 n = dRaw > 1e-12 ? st / dRaw : Vec3(1, 0, 0);
  Vec3 m = detail::perpendicularPart(pole - s, n);
  m = glm::length(m) < 1e-12 ? anyPerpendicular(n) : m / glm::length(m);
  const Real cosAlpha = d > 1e-12 ? std::clamp((a * a + d * d - b * b) / (2.0 * a * d), -1.0, 1.0) : 0.0;
  const Real sinAlpha = std::sqrt(std::max(0.0, 1.0 - cosAlpha * cosAlpha));
  out.elbow = s + a * (cosAlpha * n + sinAlpha * m);
  out.wrist = s + d * n;
  return out;
}

// Start-up probe: tells the lab whether IK-1 is still a stub.
PBA_EXERCISE_PROBE(analyticSingleJoint(Vec3(1.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0)));

namespace detail {
namespace {

Real wrapAngle(Real x) { return std::remainder(x, 2.0 * kPi); }

// Writes a ball or free joint's local rotation (ball: the Euler representation its limits admit),
// clamps it when limits are enforced (IK-6), and refreshes the frames.
void setLocal(Context& c, int j, const Quat& local) {
  const Joint& joint = c.skeleton.joint(j);
  if (joint.type == JointType::Ball) {
    const Vec3 e = c.options.enforceLimits ? eulerWithinLimits(joint, local) : eulerXYZFromQuat(local);
    for (int k = 0; k < 3; ++k) c.pose.dofs[static_cast<size_t>(joint.firstDof + k)] = e[k];
  } else if (joint.type == JointType::Free) {
    c.pose.rotations[static_cast<size_t>(j)] = glm::normalize(local);
  }
  if (c.options.enforceLimits) clampJointToLimits(c.skeleton, c.pose, j);
  c.refresh();
}

// True when a ball or free joint's local rotation lies within its limits (always, when they are
// not enforced).
bool withinLimits(const Context& c, const Joint& joint, const Quat& local) {
  if (!c.options.enforceLimits) return true;
  if (joint.type == JointType::Free) return glm::length(rotationVector(local)) <= joint.maxRotation + 1e-12;
  bool inside = true;
  if (joint.type == JointType::Ball) eulerWithinLimits(joint, local, &inside);
  return inside;
}

// A ball joint's rotations that take the unit lever u (in its own frame) onto the unit direction d
// (in its pre-rotation frame) form a one-parameter family. With R = Rx(a) Ry(b) Rz(c) and a given,
// Ry(b) Rz(c) u = w := Rx(−a) d has the closed form
//   y:  r sin(c + ψ) = w_y, r = |(u_x, u_y)|, ψ = atan2(u_y, u_x)  →  c = asin(w_y / r) − ψ or π − asin(w_y / r) − ψ
//   xz: b = atan2(u_z, r cos(c + ψ)) − atan2(w_z, w_x)             (Ry(b) turns the xz-plane by −b)
// so a sweep of a over its range lists the members inside the limits, exactly (10° steps, refined to
// 1° about the best). Returns the one of least cost(q), or false when no sampled member lies within
// the limits.
template <typename Cost>
bool ballDirectionWithinLimits(const Joint& joint, const Vec3& u, const Vec3& d, Cost cost, Quat* best) {
  const Real r = std::hypot(u.x, u.y), psi = std::atan2(u.y, u.x);
  Real bestCost = std::numeric_limits<Real>::infinity(), bestA = 0.0;
  auto scan = [&](Real lo, Real hi, Real step) {
    const int samples = std::max(1, static_cast<int>(std::ceil((hi - lo) / step)));
    for (int i = 0; i <= samples; ++i) {
      const Real a = lo + (hi - lo) * Real(i) / Real(samples);
      const Vec3 w = glm::angleAxis(-a, Vec3(1, 0, 0)) * d;
      if (std::abs(w.y) > r + 1e-12) continue;
      const Real s = r > 1e-15 ? std::asin(std::clamp(w.y / r, -1.0, 1.0)) : 0.0;
      for (Real c : {s - psi, kPi - s - psi}) {
        const Real b = std::atan2(u.z, r * std::cos(c + psi)) - std::atan2(w.z, w.x);
        Vec3 e(a, wrapAngle(b), wrapAngle(c));
        bool inside = true;
        for (int k = 1; k < 3; ++k) {
          Real shifted = e[k];
          for (Real candidate : {e[k], e[k] - 2.0 * kPi, e[k] + 2.0 * kPi})
            if (candidate >= joint.lo[k] && candidate <= joint.hi[k]) shifted = candidate;
          inside = inside && shifted >= joint.lo[k] && shifted <= joint.hi[k];
          e[k] = shifted;
        }
        if (!inside) continue;
        const Quat q = quatFromEulerXYZ(e);
        const Real value = cost(q);
        if (value < bestCost) bestCost = value, *best = q, bestA = a;
      }
    }
  };
  // 10° steps, then 1° steps around the best of them (or over the whole range when none fits).
  const Real lo = joint.lo[0], hi = joint.hi[0], coarse = degToRad(10.0), fine = degToRad(1.0);
  scan(lo, hi, coarse);
  if (bestCost < std::numeric_limits<Real>::infinity())
    scan(std::max(lo, bestA - coarse), std::min(hi, bestA + coarse), fine);
  else
    scan(lo, hi, fine);
  return bestCost < std::numeric_limits<Real>::infinity();
}

// Turns joint j so that the point `from` (world, moving with it) points from its pivot toward `to`:
// IK-1's shortest arc when that rotation lies within the limits (with, for a ball joint given a
// pole, the twist about the pivot–goal axis that turns `elbow` toward it); else the member of the
// family nearest that rotation which the limits admit (ballDirectionWithinLimits); else the clamped
// shortest arc (the goal direction is outside the limits).
void aimJoint(Context& c, int j, const Vec3& from, const Vec3& to, const Vec3* elbow) {
  const Joint& joint = c.skeleton.joint(j);
  const Frame f = c.frames[static_cast<size_t>(j)];
  const Vec3 u = from - f.position, v = to - f.position;
  if (joint.type == JointType::Hinge) {
    alignJoint(c, j, f, {from}, {to}, {1.0}, c.options.enforceLimits, false, nullptr);
    c.refresh();
    return;
  }
  if (joint.type != JointType::Ball && joint.type != JointType::Free) return;
  const AxisAngle swing = analyticSingleJoint(u, v);
  const Quat current = c.local[static_cast<size_t>(j)];
  Quat world = glm::angleAxis(swing.angle, swing.axis);
  const Real distance = glm::length(v);
  const bool usePole = elbow && c.options.usePole && distance > 1e-12;
  const Vec3 n = distance > 1e-12 ? v / distance : Vec3(0.0);
  const Vec3 pole = c.options.polePoint - f.position;
  if (usePole) {
    // Twist about the goal axis: the elbow (after the swing) toward the pole's side of that axis.
    const Vec3 el = world * (*elbow - f.position);
    const Vec3 ep = perpendicularPart(el, n), pp = perpendicularPart(pole, n);
    if (glm::length(ep) > 1e-12 && glm::length(pp) > 1e-12)
      world = glm::angleAxis(std::atan2(glm::dot(n, glm::cross(ep, pp)), glm::dot(ep, pp)), n) * world;
  }
  const Quat preferred = glm::normalize(glm::conjugate(f.pre) * world * f.pre * current);
  if (joint.type == JointType::Free || withinLimits(c, joint, preferred) || rotationUnlimited(joint) ||
      glm::length(u) < 1e-12 || distance < 1e-12) {
    setLocal(c, j, preferred);
    return;
  }
  // The family of rotations taking the lever onto the goal direction, in the joint's frames.
  const Quat preInverse = glm::conjugate(f.pre);
  const Vec3 lever = glm::normalize(glm::conjugate(current) * (preInverse * u));
  const Vec3 goal = preInverse * n;
  const Vec3 elbowLocal = elbow ? glm::conjugate(current) * (preInverse * (*elbow - f.position)) : Vec3(0.0);
  const Vec3 poleLocal = preInverse * pole;
  auto cost = [&](const Quat& q) {
    if (usePole) {  // the elbow's angle from the pole about the goal axis
      const Vec3 el = q * elbowLocal;
      const Vec3 ep = perpendicularPart(el, goal), pp = perpendicularPart(poleLocal, goal);
      const Real lengths = glm::length(ep) * glm::length(pp);
      return lengths > 1e-15 ? -glm::dot(ep, pp) / lengths : 0.0;
    }
    return 1.0 - std::abs(glm::dot(q, preferred));
  };
  Quat best;
  setLocal(c, j, ballDirectionWithinLimits(joint, lever, goal, cost, &best) ? best : preferred);
}

class Analytic final : public Method {
 public:
  Analytic(std::vector<int> joints) : joints_(std::move(joints)) {}
  bool finished() const override { return done_; }

  void iterate(Context& c) override {
    done_ = true;
    const Effector& e = c.effectors[0];
    if (joints_.size() == 1) {
      // IK-1 on the lever pivot → effector (hinges: projected onto the plane of the hinge), within
      // the limits where a rotation within them reaches the goal.
      aimJoint(c, joints_[0], effectorPosition(e, c.frames), e.targetPosition, nullptr);
      return;
    }
    // Two bones: each candidate bend of the elbow (law of cosines), then the shoulder aimed at the
    // goal; the candidate that ends nearest the goal wins (the first exact one, in order of
    // preference: smallest bend change, current bend plane).
    const int shoulder = joints_[0], elbow = joints_[1];
    const Pose start = c.pose;
    std::vector<Pose> bends = elbowCandidates(c, shoulder, elbow, e);
    Pose best = start;
    Real bestResidual = std::numeric_limits<Real>::infinity();
    for (Pose& bend : bends) {
      c.pose = std::move(bend);
      c.refresh();
      const Vec3 el = c.frames[static_cast<size_t>(elbow)].position;
      aimJoint(c, shoulder, effectorPosition(e, c.frames), e.targetPosition, &el);
      const Real r = glm::length(effectorPosition(e, c.frames) - e.targetPosition);
      if (r < bestResidual) bestResidual = r, best = c.pose;
      if (r <= 1e-9 * (1.0 + glm::length(e.targetPosition))) break;
    }
    c.pose = best;
    c.refresh();
  }

 private:
  // Law of cosines at the elbow: the bends about axis k that make |wrist − shoulder| equal the
  // target distance (clamped into the reachable interval). With A = elbow − shoulder,
  // B = wrist − elbow,
  //   |A + R(θ)B|² = |A|² + |B|² + 2 (A·B∥ + P cos θ + Q sin θ),  P = A·B⊥, Q = A·(k × B)
  // so cos(θ − φ) = (d² − |A|² − |B|² − 2 A·B∥) / (2 r), r = hypot(P, Q), φ = atan2(Q, P): θ = φ ± δ.
  // A hinge elbow bends about its axis. A ball or free elbow may bend about any axis: the normal of
  // the arm's plane first, then that normal turned about the upper arm by ±10°, ±20°, … (a limited
  // elbow may allow the bend only in some planes). Candidates outside the limits are skipped, unless
  // none is inside (then the first, clamped: the goal is too near or too far).
  std::vector<Pose> elbowCandidates(Context& c, int shoulder, int elbow, const Effector& e) const {
    const Frame f = c.frames[static_cast<size_t>(elbow)];
    const Vec3 s = c.frames[static_cast<size_t>(shoulder)].position;
    const Vec3 A = f.position - s, B = effectorPosition(e, c.frames) - f.position;
    const Joint& joint = c.skeleton.joint(elbow);
    const Real d = glm::length(e.targetPosition - s);
    std::vector<Vec3> axes;
    if (joint.type == JointType::Hinge) {
      axes.push_back(f.pre * joint.axis);
    } else {
      Vec3 k = glm::cross(A, B);
      if (glm::length(k) < 1e-12) k = glm::cross(A, (c.options.usePole ? c.options.polePoint : s + Vec3(0, 0, 1)) - s);
      if (glm::length(k) < 1e-12 && glm::length(A) >= 1e-12) k = anyPerpendicular(A);
      if (glm::length(k) >= 1e-12 && glm::length(A) >= 1e-12) {
        k = glm::normalize(k);
        const Vec3 a = glm::normalize(A);
        axes.push_back(k);
        for (int step = 1; step < 18; ++step)
          for (Real sign : {1.0, -1.0}) axes.push_back(glm::angleAxis(sign * Real(step) * kPi / 18.0, a) * k);
        axes.push_back(glm::angleAxis(kPi, a) * k);
      }
    }
    std::vector<Pose> inside, outside;
    for (const Vec3& k : axes) {
      const Vec3 Bpar = glm::dot(B, k) * k, Bperp = B - Bpar;
      const Real P = glm::dot(A, Bperp), Q = glm::dot(A, glm::cross(k, B));
      const Real r = std::hypot(P, Q);
      if (r < 1e-12) continue;
      const Real x =
          std::clamp((d * d - glm::dot(A, A) - glm::dot(B, B) - 2.0 * glm::dot(A, Bpar)) / (2.0 * r), -1.0, 1.0);
      const Real phi = std::atan2(Q, P), delta = std::acos(x);
      Real thetas[2] = {wrapAngle(phi + delta), wrapAngle(phi - delta)};
      if (std::abs(thetas[1]) < std::abs(thetas[0])) std::swap(thetas[0], thetas[1]);
      for (Real theta : thetas) {
        Pose pose = c.pose;
        bool ok = true;
        if (joint.type == JointType::Hinge) {
          Real& value = pose.dofs[static_cast<size_t>(joint.firstDof)];
          value = bestHingeValue(value + theta, joint.lo[0], joint.hi[0], c.options.enforceLimits);
          ok = !c.options.enforceLimits || (value >= joint.lo[0] && value <= joint.hi[0]);
          if (c.options.enforceLimits) clampJointToLimits(c.skeleton, pose, elbow);
        } else {
          const Quat local = glm::normalize(glm::conjugate(f.pre) * glm::angleAxis(theta, k) * f.pre *
                                            c.local[static_cast<size_t>(elbow)]);
          ok = withinLimits(c, joint, local);
          if (joint.type == JointType::Ball) {
            const Vec3 angles = c.options.enforceLimits ? eulerWithinLimits(joint, local) : eulerXYZFromQuat(local);
            for (int i = 0; i < 3; ++i) pose.dofs[static_cast<size_t>(joint.firstDof + i)] = angles[i];
          } else {
            pose.rotations[static_cast<size_t>(elbow)] = local;
          }
          if (c.options.enforceLimits) clampJointToLimits(c.skeleton, pose, elbow);
        }
        (ok ? inside : outside).push_back(std::move(pose));
      }
    }
    if (inside.empty() && !outside.empty()) inside.push_back(std::move(outside.front()));
    if (inside.empty()) inside.push_back(c.pose);
    return inside;
  }

  std::vector<int> joints_;
  bool done_ = false;
};

}  // namespace

std::unique_ptr<Method> makeAnalytic(const Context& c, std::string* why) {
  if (c.effectors.size() != 1) {
    *why = "analytic IK needs exactly one effector";
    return nullptr;
  }
  std::vector<int> moving;
  for (int j = c.effectors[0].joint; j >= 0; j = c.skeleton.joint(j).parent) {
    const JointType t = c.skeleton.joint(j).type;
    if (t == JointType::Prismatic) {
      *why = "analytic IK handles rotational joints only";
      return nullptr;
    }
    if (t != JointType::Fixed) moving.insert(moving.begin(), j);
  }
  if (moving.empty() || moving.size() > 2) {
    *why = "analytic IK needs one or two moving joints above the effector, found " + std::to_string(moving.size());
    return nullptr;
  }
  return std::make_unique<Analytic>(std::move(moving));
}

}  // namespace detail
}  // namespace pba::ik
