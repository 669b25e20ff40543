// Analytic IK: IK-1 (one joint from the dot and cross products), the two-bone law-of-cosines solution
// with a pole direction, and the "analytic" solver that applies them to a skeleton whose effector
// hangs below one or two moving joints.
#include "physics/ik/analytic.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "physics/exercises/not_implemented.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik {

// ***** IK-1: single-joint analytic IK (Workbook §2.1 task 2) *****
// (1) Normalise both directions: b = boneDirection / |boneDirection|, t = toTarget / |toTarget|.
//     If either is (almost) zero there is nothing to do: return angle 0 (any axis).
// (2) cos θ = b · t (dot product); the rotation axis is b × t (cross product), sin θ = |b × t|.
// (3) θ = atan2(|b × t|, b · t): in [0, π], and never NaN (acos of a dot product slightly above 1 is).
// (4) If |b × t| is (almost) zero the directions are parallel (θ = 0, keep any axis) or opposite
//     (θ = π about any axis perpendicular to b, e.g. b × x̂, or b × ŷ when b is close to x̂).
// (5) Return the unit axis and θ.
// *****
AxisAngle analyticSingleJoint([[maybe_unused]] const Vec3& boneDirection, [[maybe_unused]] const Vec3& toTarget) {
  // BEGIN SOLUTION
  const Real lb = glm::length(boneDirection), lt = glm::length(toTarget);
  if (lb < 1e-12 || lt < 1e-12) return {};
  const Vec3 b = boneDirection / lb, t = toTarget / lt;
  const Vec3 axis = glm::cross(b, t);
  const Real s = glm::length(axis), c = glm::dot(b, t);
  if (s < 1e-12) {
    if (c > 0.0) return {};
    const Vec3 n = glm::cross(b, std::abs(b.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
    return {n / glm::length(n), kPi};
  }
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
  Vec3 m = (pole - s) - glm::dot(pole - s, n) * n;
  if (glm::length(m) < 1e-12) m = glm::cross(n, std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
  m /= glm::length(m);
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

// Applies the world rotation q about joint j's pivot as well as the joint type allows (hinge: the
// component about its axis), clamps, and refreshes the frames.
void rotateJoint(Context& c, int j, const Quat& q) {
  const Joint& joint = c.skeleton.joint(j);
  const Frame& f = c.frames[static_cast<size_t>(j)];
  if (joint.type == JointType::Hinge) {
    const Vec3 a = f.pre * joint.axis;
    c.pose.dofs[static_cast<size_t>(joint.firstDof)] += glm::dot(rotationVector(q), a);
  } else if (joint.type == JointType::Ball || joint.type == JointType::Free) {
    const Quat local = glm::inverse(f.pre) * q * f.pre * jointRotation(joint, c.pose, j);
    if (joint.type == JointType::Ball) {
      const Vec3 e = eulerXYZFromQuat(local);
      for (int k = 0; k < 3; ++k) c.pose.dofs[static_cast<size_t>(joint.firstDof + k)] = e[k];
    } else {
      c.pose.rotations[static_cast<size_t>(j)] = glm::normalize(local);
    }
  }
  if (c.options.enforceLimits) clampJointToLimits(c.skeleton, c.pose, j);
  c.refresh();
}

Real wrapAngle(Real x) { return std::remainder(x, 2.0 * kPi); }

class Analytic final : public Method {
 public:
  Analytic(std::vector<int> joints) : joints_(std::move(joints)) {}
  bool finished() const override { return done_; }

  void iterate(Context& c) override {
    done_ = true;
    const Effector& e = c.effectors[0];
    if (joints_.size() == 1) {
      // IK-1 on the lever pivot → effector (hinges: both projected onto the plane of the hinge).
      const int j = joints_[0];
      const Frame& f = c.frames[static_cast<size_t>(j)];
      Vec3 u = effectorPosition(e, c.frames) - f.position, v = e.targetPosition - f.position;
      if (c.skeleton.joint(j).type == JointType::Hinge) {
        const Vec3 a = f.pre * c.skeleton.joint(j).axis;
        u -= glm::dot(u, a) * a;
        v -= glm::dot(v, a) * a;
      }
      const AxisAngle r = analyticSingleJoint(u, v);
      rotateJoint(c, j, glm::angleAxis(r.angle, r.axis));
      return;
    }
    const int shoulder = joints_[0], elbow = joints_[1];
    bendElbow(c, shoulder, elbow, e);
    // Shoulder: swing the wrist onto the line to the target, then twist the elbow toward the pole.
    const Vec3 s = c.frames[static_cast<size_t>(shoulder)].position;
    const Vec3 w = effectorPosition(e, c.frames);
    if (c.skeleton.joint(shoulder).type == JointType::Hinge) {
      const Frame f = c.frames[static_cast<size_t>(shoulder)];
      alignJoint(c, shoulder, f, {w}, {e.targetPosition}, {1.0}, c.options.enforceLimits, false, nullptr);
      c.refresh();
      return;
    }
    const AxisAngle swing = analyticSingleJoint(w - s, e.targetPosition - s);
    rotateJoint(c, shoulder, glm::angleAxis(swing.angle, swing.axis));
    const Vec3 toTarget = e.targetPosition - s;
    const Real d = glm::length(toTarget);
    if (!c.options.usePole || d < 1e-12) return;
    const Vec3 n = toTarget / d;
    const Vec3 el = c.frames[static_cast<size_t>(elbow)].position - s;
    const Vec3 ep = el - glm::dot(el, n) * n, pp = (c.options.polePoint - s) - glm::dot(c.options.polePoint - s, n) * n;
    if (glm::length(ep) < 1e-12 || glm::length(pp) < 1e-12) return;
    rotateJoint(c, shoulder, glm::angleAxis(std::atan2(glm::dot(n, glm::cross(ep, pp)), glm::dot(ep, pp)), n));
  }

 private:
  // Law of cosines at the elbow: make |wrist − shoulder| equal the target distance (clamped into the
  // reachable interval). The elbow turns about its hinge axis k (or, for a ball/free elbow, about the
  // normal of the arm's plane): with A = elbow − shoulder, B = wrist − elbow,
  //   |A + R(θ)B|² = |A|² + |B|² + 2 (A·B∥ + P cos θ + Q sin θ),  P = A·B⊥, Q = A·(k × B)
  // so cos(θ − φ) = (d² − |A|² − |B|² − 2 A·B∥) / (2 r), r = hypot(P, Q), φ = atan2(Q, P).
  void bendElbow(Context& c, int shoulder, int elbow, const Effector& e) {
    const Frame f = c.frames[static_cast<size_t>(elbow)];
    const Vec3 s = c.frames[static_cast<size_t>(shoulder)].position;
    const Vec3 A = f.position - s, B = effectorPosition(e, c.frames) - f.position;
    const Joint& joint = c.skeleton.joint(elbow);
    Vec3 k;
    if (joint.type == JointType::Hinge) {
      k = f.pre * joint.axis;
    } else {
      k = glm::cross(A, B);
      if (glm::length(k) < 1e-12) k = glm::cross(A, (c.options.usePole ? c.options.polePoint : s + Vec3(0, 0, 1)) - s);
      if (glm::length(k) < 1e-12) k = glm::cross(A, std::abs(A.x) < 0.9 * glm::length(A) ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
      if (glm::length(k) < 1e-12) return;
      k /= glm::length(k);
    }
    const Vec3 Bpar = glm::dot(B, k) * k, Bperp = B - Bpar;
    const Real P = glm::dot(A, Bperp), Q = glm::dot(A, glm::cross(k, B));
    const Real r = std::hypot(P, Q);
    if (r < 1e-12) return;
    const Real d = glm::length(e.targetPosition - s);
    const Real x = std::clamp((d * d - glm::dot(A, A) - glm::dot(B, B) - 2.0 * glm::dot(A, Bpar)) / (2.0 * r), -1.0, 1.0);
    const Real phi = std::atan2(Q, P), delta = std::acos(x);
    Real best = 0.0, bestCost = 1e300;
    for (Real candidate : {wrapAngle(phi + delta), wrapAngle(phi - delta)}) {
      Real cost = std::abs(candidate);
      if (joint.type == JointType::Hinge) {
        const Real value = c.pose.dofs[static_cast<size_t>(joint.firstDof)] + candidate;
        if (value < joint.lo[0] - 1e-12 || value > joint.hi[0] + 1e-12) cost += 10.0;  // prefer the solution inside the limits
      }
      if (cost < bestCost) {
        bestCost = cost;
        best = candidate;
      }
    }
    rotateJoint(c, elbow, glm::angleAxis(best, k));
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
