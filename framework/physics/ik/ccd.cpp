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
#include <cmath>
#include <memory>

#include "physics/exercises/not_implemented.h"
#include "physics/ik/exercises.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik {

// ***** IK-2: the CCD joint update as a quaternion (Workbook §2.4, Algorithm 1) *****
// (1) V1 = effector − pivot (the direction the bone chain points now), V2 = target − pivot (where it
//     should point).
// (2) If either vector is (almost) zero, there is no defined rotation: return the identity.
// (3) The rotation turns V1 onto V2 about n = V1 × V2 by their angle θ. A unit quaternion is
//     (cos θ/2, sin θ/2 · n̂). Write cos θ and sin θ with the dot and cross products and use the
//     half-angle identities: up to a positive factor, the quaternion's scalar part is
//     |V1| |V2| + V1 · V2 and its vector part is V1 × V2. Normalise it: no trigonometry needed.
// (4) When that scalar part is (almost) zero the vectors are opposite: the answer is a half turn,
//     scalar part 0 and vector part any unit vector perpendicular to V1 (anyPerpendicular).
// (5) glm::dquat's constructor takes (w, x, y, z).
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

class Ccd final : public Method {
 public:
  FramesAfterIterate framesAfterIterate() const override { return FramesAfterIterate::FromCache; }
  void iterate(Context& c) override {
    buildPoints(c);
    const bool clamp = c.options.enforceLimits;
    for (int j = c.skeleton.jointCount() - 1; j >= 0; --j) {
      const std::span<const int> below = c.effectorsBelow(j);
      if (below.empty() || c.skeleton.joint(j).type == JointType::Fixed) continue;
      from_.clear();
      to_.clear();
      w_.clear();
      for (int e : below)
        for (int k = first_[static_cast<size_t>(e)]; k < first_[static_cast<size_t>(e) + 1]; ++k) {
          from_.push_back(points_[static_cast<size_t>(k)]);
          to_.push_back(goals_[static_cast<size_t>(k)]);
          w_.push_back(weights_[static_cast<size_t>(k)]);
        }
      const Frame& f = c.frames[static_cast<size_t>(j)];
      Vec3 t(0.0);
      const Quat q = alignJoint(c, j, f, from_, to_, w_, clamp, true, &t);
      for (int e : below)
        for (int k = first_[static_cast<size_t>(e)]; k < first_[static_cast<size_t>(e) + 1]; ++k) {
          Vec3& pt = points_[static_cast<size_t>(k)];
          pt = f.position + q * (pt - f.position) + t;
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
  std::vector<int> first_;  // effector e owns points [first_[e], first_[e + 1])
  bool positionsOnly_ = true;
};

}  // namespace

std::unique_ptr<Method> makeCcd() { return std::make_unique<Ccd>(); }

}  // namespace detail
}  // namespace pba::ik
