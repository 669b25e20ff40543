// Cyclic coordinate descent (Workbook §2.4, Algorithm 1; IK slides, "Other techniques").
// One pass visits every joint from the tips toward the root. Each joint turns so that the effector
// points below it swing toward their goals (alignJoint: the exact single-joint optimum, clamped to the
// limits). A 6-DOF effector adds three virtual points at s·(x̂, ŷ, ẑ) of its frame, with goals at the
// same points of the goal frame (s = orientation scale [m/rad]), so one least-squares rule aligns
// position and orientation together.
//
// Cost: O(n) per pass for a chain with one effector. Going from the tips to the root, a joint's pivot
// and pre-rotation depend only on its ancestors, which this pass has not moved yet, so the frames from
// the forward kinematics at the start of the pass stay valid; only the effector points move, and they
// are updated incrementally by each joint's rotation (no full FK per joint, unlike the naive loop).
//
// SolveOptions::ccdMaxTurn (ours, off by default): each joint turns by at most that angle per pass
// (docs/performance-ik-ccd.md, "CCD on 1,000 limited hinges"). A hinge carrying one point then turns by
// half-angle quaternions while it stays inside its limits (turnHingeCapped): IK-2's rotation, cut to
// the cap, composed with the hinge's own rotation about the same axis, its angle written once at the
// end (flushPose), as FABRIK's forward pass does; at a limit it takes alignJoint's angle and clamp.
#include <algorithm>
#include <cmath>
#include <memory>

#include "physics/exercises/not_implemented.h"
#include "physics/ik/exercises.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik {

// ***** IK-2: the CCD joint update as a quaternion (Workbook §2.4, Algorithm 1) *****
// Inputs in world axes [m]: the joint's pivot, the effector, the target. Output: the unit quaternion
// (glm::dquat, constructor order (w, x, y, z)) that turns the direction pivot → effector onto the
// direction pivot → target by the smallest angle.
// (1) The two directions from the pivot. If either is (almost) zero there is no defined rotation:
//     return the identity.
// (2) Work out the quaternion without trigonometry: the dot and cross products give the cosine and sine
//     of the angle (times the lengths), and the half-angle identities turn them into the quaternion's
//     scalar and vector parts up to a common positive factor. Normalise.
// (3) When the directions are opposite the axis is undefined: any half turn about an axis perpendicular
//     to the first direction will do (anyPerpendicular).
// Check: the result turns the first direction exactly onto the second's direction; it has unit length;
// parallel directions give the identity.
// *****
Quat ccdJointUpdate([[maybe_unused]] const Vec3& pivot, [[maybe_unused]] const Vec3& effector,
                    [[maybe_unused]] const Vec3& target) {
  // BEGIN SOLUTION
  const Vec3 v1 = effector - pivot, v2 = target - pivot;
  const Real l1 = glm::length(v1), l2 = glm::length(v2);
  if (l1 < 1e-12 || l2 < 1e-12) return Quat(1, 0, 0, 0);
  const Real w = l1 * l2 + glm::dot(v1, v2);
  if (w <= 1e-12 * l1 * l2) {
    const Vec3 n = anyPerpendicular(v1);
    return Quat(0.0, n.x, n.y, n.z);
  }
  const Vec3 x = glm::cross(v1, v2);
  return glm::normalize(Quat(w, x.x, x.y, x.z));
  // END SOLUTION
  // STUB: return exercises::notImplemented("IK-2", Quat(1, 0, 0, 0));
}

// Start-up probe: tells the lab whether IK-2 is still a stub.
PBA_EXERCISE_PROBE(ccdJointUpdate(Vec3(0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0)));

namespace detail {
namespace {

// ccdMaxTurn's update of hinge j (pivot and pre-rotation `f`) carrying the one point `point` toward
// `goal`, without angles. IK-2's rotation of the projections onto the hinge's plane is
// q = (cos ½θ, sin ½θ a) (a the world axis; its vector part lies along ±a), cut to the cap:
// (cos ½δ, ±sin ½δ a) when cos ½θ < cos ½δ (a half turn, whose axis IK-2 may pick off a, is always
// cut). The hinge's rotation (W, S u) about its local axis u (a = R_pre u) turns about the same axis,
// so the new one is the product (W w − S s, (W s + S w) u), of angle ψ with
// (cos ψ, sin ψ) = (W'² − S'², 2 W' S'). When `range` holds ψ (HingeRange: inside the limits by a
// margin, with W' > 0 so that ψ is the angle itself, not ψ ± 2π) the hinge takes it and the point
// turns by θ about the axis, p + u∥ + cos θ u⊥ + sin θ a × u⊥, and the function returns true; else
// false, nothing changed.
bool turnHingeCapped(Context& c, int j, const Frame& f, const HingeRange& range, Real cosHalfCap, Real sinHalfCap,
                     Vec3& point, const Vec3& goal) {
  const Joint& joint = c.skeleton.joint(j);
  const Vec3 a = f.pre * joint.axis, p = f.position;
  const Vec3 u = point - p, uPerp = perpendicularPart(u, a);
  const Quat q = ccdJointUpdate(Vec3(0.0), uPerp, perpendicularPart(goal - p, a));
  Real w = q.w, s = glm::dot(Vec3(q.x, q.y, q.z), a);
  if (w < cosHalfCap) w = cosHalfCap, s = s < 0.0 ? -sinHalfCap : sinHalfCap;
  const Quat& local = c.local[static_cast<size_t>(j)];
  const Real W = local.w, S = glm::dot(Vec3(local.x, local.y, local.z), joint.axis);
  const Real W1 = W * w - S * s, S1 = W * s + S * w;
  if (!(W1 > 0.0) || !range.holds(W1 * W1 - S1 * S1, 2.0 * W1 * S1, W1 * W1 + S1 * S1)) return false;
  c.local[static_cast<size_t>(j)] = glm::normalize(Quat(W1, S1 * joint.axis.x, S1 * joint.axis.y, S1 * joint.axis.z));
  c.staleEuler[static_cast<size_t>(j)] = 1;
  point = p + (u - uPerp) + (w * w - s * s) * uPerp + (2.0 * w * s) * glm::cross(a, uPerp);
  return true;
}

class Ccd final : public Method {
 public:
  FramesAfterIterate framesAfterIterate() const override { return FramesAfterIterate::FromCache; }
  void iterate(Context& c) override {
    buildPoints(c);
    const bool clamp = c.options.enforceLimits;
    const Real maxTurn = c.options.ccdMaxTurn;
    if (maxTurn > 0.0 && clamp && range_.empty()) hingeRanges(c.skeleton, range_);
    const Real cosHalfCap = std::cos(0.5 * std::min(maxTurn, kPi)), sinHalfCap = std::sin(0.5 * std::min(maxTurn, kPi));
    for (int j = c.skeleton.jointCount() - 1; j >= 0; --j) {
      const std::span<const int> below = c.effectorsBelow(j);
      if (below.empty() || c.skeleton.joint(j).type == JointType::Fixed) continue;
      const Frame& f = c.frames[static_cast<size_t>(j)];
      // ccdMaxTurn on a limited hinge below which lies one point: the update without angles.
      const auto e0 = below.size() == 1 ? static_cast<size_t>(below[0]) : 0;
      const bool capped =
          maxTurn > 0.0 && clamp && below.size() == 1 && first_[e0 + 1] - first_[e0] == 1 &&
          c.skeleton.joint(j).type == JointType::Hinge && range_[static_cast<size_t>(j)].valid &&
          turnHingeCapped(c, j, f, range_[static_cast<size_t>(j)], cosHalfCap, sinHalfCap,
                          points_[static_cast<size_t>(first_[e0])], goals_[static_cast<size_t>(first_[e0])]);
      if (!capped) {
        from_.clear();
        to_.clear();
        w_.clear();
        for (int e : below)
          for (int k = first_[static_cast<size_t>(e)]; k < first_[static_cast<size_t>(e) + 1]; ++k) {
            from_.push_back(points_[static_cast<size_t>(k)]);
            to_.push_back(goals_[static_cast<size_t>(k)]);
            w_.push_back(weights_[static_cast<size_t>(k)]);
          }
        if (maxTurn > 0.0 && c.staleEuler[static_cast<size_t>(j)]) c.flushJoint(j);  // alignJoint reads the angle
        Vec3 t(0.0);
        const Quat q = alignJoint(c, j, f, from_, to_, w_, clamp, true, &t, maxTurn);
        for (int e : below)
          for (int k = first_[static_cast<size_t>(e)]; k < first_[static_cast<size_t>(e) + 1]; ++k) {
            Vec3& pt = points_[static_cast<size_t>(k)];
            pt = f.position + q * (pt - f.position) + t;
          }
      }
      // Stop the pass once every goal is met: the joints nearer the root would only make rotations
      // that the tolerance cannot see (position effectors; 6-DOF ones always finish the pass).
      if (positionsOnly_ && goalsMet(c.options.tolerance)) return;
    }
  }

 private:
  bool goalsMet(Real tolerance) const {
    for (size_t k = 0; k < points_.size(); ++k)
      if (glm::distance(points_[k], goals_[k]) > tolerance) return false;
    return true;
  }

  void buildPoints(const Context& c) {
    positionsOnly_ = true;
    points_.clear();
    goals_.clear();
    weights_.clear();
    first_.assign(1, 0);
    for (const Effector& e : c.effectors) {
      points_.push_back(effectorPosition(e, c.frames));
      goals_.push_back(e.targetPosition);
      weights_.push_back(e.weight);
      if (e.kind == EffectorKind::PositionOrientation) {
        positionsOnly_ = false;
        const Quat E = effectorOrientation(e, c.frames);
        const Real s = c.orientationScale;
        for (int k = 0; k < 3; ++k) {
          Vec3 axis(0.0);
          axis[k] = s;
          points_.push_back(effectorPosition(e, c.frames) + E * axis);
          goals_.push_back(e.targetPosition + e.targetOrientation * axis);
          weights_.push_back(e.weight);
        }
      }
      first_.push_back(static_cast<int>(points_.size()));
    }
  }

  std::vector<Vec3> points_, goals_, from_, to_;
  std::vector<Real> weights_, w_;
  std::vector<int> first_;         // effector e owns points [first_[e], first_[e + 1])
  std::vector<HingeRange> range_;  // per joint (hingeRanges), for ccdMaxTurn with limits
  bool positionsOnly_ = true;
};

}  // namespace

std::unique_ptr<Method> makeCcd() { return std::make_unique<Ccd>(); }

}  // namespace detail
}  // namespace pba::ik
