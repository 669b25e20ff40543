// FABRIK: forward and backward reaching inverse kinematics (Aristidou & Lasenby 2011, Algorithms 1
// and 2; CMU asst4 lists it among the extensions). It works on joint positions only:
//   backward: put the end on the goal, then walk toward the base, placing each point on the line to
//             its successor at the bone's length;
//   forward:  put the base back, then walk toward the end the same way.
// Trees (Aristidou & Lasenby §4.3, "multiple end effectors"): the active part of the skeleton splits
// into segments between sub-bases (joints with several active children). The backward pass runs on
// the segments from the leaves; a sub-base takes the centroid of the positions its child segments
// propose and becomes the goal of the segment above it. The forward pass runs from the root.
//
// Back to joint angles. Our skeleton is a tree of DOFs, so after the passes every joint, from the root
// outward, turns so that its children (as placed by FK of the already-updated parents) move onto their
// FABRIK positions (alignJoint, clamped to the limits), and the next iteration restarts from the FK
// positions. For ball and free joints without limits this reproduces plain FABRIK exactly; hinges and
// limits project each bone onto what the joint can reach. Cost: O(n) per iteration.
// On a single chain of ball or free joints that no limit restricts (the setting of the FABRIK paper)
// the conversion is exact and adds nothing, so that case iterates on the points alone and turns
// them into joint angles once, when the driver stops (finish()).
// Orientation goals of 6-DOF effectors are ignored by FABRIK (position-only method; use CCD or a
// Jacobian method for them).
#include <memory>

#include "physics/exercises/not_implemented.h"
#include "physics/ik/exercises.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik {

// ***** IK-5: FABRIK's backward and forward passes (Aristidou & Lasenby 2011, Algorithm 1) *****
// Backward pass (fabrikBackward), on points p[0..n-1] with lengths[i] = |p[i+1] − p[i]|:
// (1) Move the last point onto the target: p[n−1] = target.
// (2) For i from n−2 down to 0: the direction d = p[i] − p[i+1]; if |d| is (almost) zero leave p[i]
//     where it is (no direction is defined); otherwise p[i] = p[i+1] + lengths[i] · d / |d|.
// Forward pass (fabrikForward):
// (3) Move the first point back onto the base: p[0] = base.
// (4) For i from 1 to n−1: d = p[i] − p[i−1]; if |d| is (almost) zero leave p[i]; otherwise
//     p[i] = p[i−1] + lengths[i−1] · d / |d|.
// *****
void fabrikBackward([[maybe_unused]] std::vector<Vec3>& points, [[maybe_unused]] const std::vector<Real>& lengths,
                    [[maybe_unused]] const Vec3& target) {
  // BEGIN SOLUTION
  if (points.empty()) return;
  points.back() = target;
  for (size_t i = points.size() - 1; i-- > 0;) {
    const Vec3 d = points[i] - points[i + 1];
    const Real l = glm::length(d);
    if (l > 1e-12) points[i] = points[i + 1] + d * (lengths[i] / l);
  }
  return;
  // END SOLUTION
  // STUB: exercises::markNotImplemented("IK-5");
}

void fabrikForward([[maybe_unused]] std::vector<Vec3>& points, [[maybe_unused]] const std::vector<Real>& lengths,
                   [[maybe_unused]] const Vec3& base) {
  // BEGIN SOLUTION
  if (points.empty()) return;
  points.front() = base;
  for (size_t i = 1; i < points.size(); ++i) {
    const Vec3 d = points[i] - points[i - 1];
    const Real l = glm::length(d);
    if (l > 1e-12) points[i] = points[i - 1] + d * (lengths[i - 1] / l);
  }
  return;
  // END SOLUTION
  // STUB: exercises::markNotImplemented("IK-5");
}

// Start-up probe: tells the lab whether IK-5 is still a stub.
namespace {
void probeFabrikPasses() {
  std::vector<Vec3> points{Vec3(0.0), Vec3(1.0, 0.0, 0.0)};
  const std::vector<Real> lengths{1.0};
  fabrikBackward(points, lengths, Vec3(0.0, 1.0, 0.0));
  fabrikForward(points, lengths, Vec3(0.0));
}
}  // namespace
PBA_EXERCISE_PROBE(probeFabrikPasses());

namespace detail {
namespace {

class Fabrik final : public Method {
 public:
  FramesAfterIterate framesAfterIterate() const override { return FramesAfterIterate::Current; }
  bool posesDeferred() const override { return pointsOnly_ && pointsLoaded_; }
  void effectorPoints(const Context& /*c*/, std::vector<Vec3>& points) const override { points.assign(1, pts_.back()); }

  void iterate(Context& c) override {
    if (!built_) build(c);
    if (pointsOnly_) {
      // Plain FABRIK (Aristidou & Lasenby 2011, Algorithm 1): on an unconstrained chain the joint
      // angles reproduce the points exactly, so they are computed once, in finish().
      if (!pointsLoaded_) {
        syncPositions(c);
        load(segments_[0]);
        pointsLoaded_ = true;
      }
      fabrikBackward(pts_, lens_, c.effectors[0].targetPosition);
      fabrikForward(pts_, lens_, q_[static_cast<size_t>(segments_[0][0])]);
      return;
    }
    syncPositions(c);
    backward(c);
    forward();
    toAngles(c);
  }

  void finish(Context& c) override {
    if (!posesDeferred()) return;
    const std::vector<int>& seg = segments_[0];
    for (size_t i = 0; i < seg.size(); ++i) q_[static_cast<size_t>(seg[i])] = pts_[i];
    toAngles(c);
    pointsLoaded_ = false;
  }

 private:
  // Nodes: joints [0, J) (only active ones used), then one node per effector [J, J + E).
  void build(const Context& c) {
    built_ = true;
    const int J = c.skeleton.jointCount(), E = static_cast<int>(c.effectors.size());
    parent_.assign(static_cast<size_t>(J + E), -1);
    std::vector<std::vector<int>> kids(static_cast<size_t>(J + E));
    used_.assign(static_cast<size_t>(J + E), 0);
    for (int j = 0; j < J; ++j) {
      if (!c.active[static_cast<size_t>(j)]) continue;
      used_[static_cast<size_t>(j)] = 1;
      parent_[static_cast<size_t>(j)] = c.skeleton.joint(j).parent;
      if (parent_[static_cast<size_t>(j)] >= 0) kids[static_cast<size_t>(parent_[static_cast<size_t>(j)])].push_back(j);
    }
    for (int e = 0; e < E; ++e) {
      used_[static_cast<size_t>(J + e)] = 1;
      parent_[static_cast<size_t>(J + e)] = c.effectors[static_cast<size_t>(e)].joint;
      kids[static_cast<size_t>(c.effectors[static_cast<size_t>(e)].joint)].push_back(J + e);
    }
    kids_ = kids;
    // Segments, parents first: depth-first from every break node (root, sub-base).
    segments_.clear();
    std::vector<int> stack;
    for (int j = 0; j < J; ++j)
      if (used_[static_cast<size_t>(j)] && parent_[static_cast<size_t>(j)] < 0) stack.push_back(j);
    while (!stack.empty()) {
      const int start = stack.back();
      stack.pop_back();
      for (int child : kids[static_cast<size_t>(start)]) {
        std::vector<int> seg{start, child};
        int n = child;
        while (n < J && kids[static_cast<size_t>(n)].size() == 1) {
          n = kids[static_cast<size_t>(n)][0];
          seg.push_back(n);
        }
        if (n < J && !kids[static_cast<size_t>(n)].empty()) stack.push_back(n);
        segments_.push_back(std::move(seg));
      }
    }
    // Points only: one chain from the root to a single position effector through ball or free joints
    // that no limit restricts. Then every point placement is reachable by the joint angles.
    pointsOnly_ = E == 1 && segments_.size() == 1 && c.effectors[0].kind == EffectorKind::Position;
    for (int j = 0; j < J && pointsOnly_; ++j) {
      const Joint& joint = c.skeleton.joint(j);
      if (!used_[static_cast<size_t>(j)]) continue;
      const bool rotates = joint.type == JointType::Ball || joint.type == JointType::Free;
      pointsOnly_ = rotates && (!c.options.enforceLimits || rotationUnlimited(joint));
    }
    buildLookahead(c);
    q_.assign(static_cast<size_t>(J + E), Vec3(0.0));
    length_.assign(static_cast<size_t>(J + E), 0.0);
    sum_.assign(static_cast<size_t>(J + E), Vec3(0.0));
    count_.assign(static_cast<size_t>(J + E), 0);
  }

  void syncPositions(const Context& c) {
    const int J = c.skeleton.jointCount();
    for (size_t n = 0; n < q_.size(); ++n) {
      if (!used_[n]) continue;
      q_[n] = n < static_cast<size_t>(J) ? c.frames[n].position : effectorPosition(c.effectors[n - static_cast<size_t>(J)], c.frames);
    }
    for (size_t n = 0; n < q_.size(); ++n)
      if (used_[n] && parent_[n] >= 0) length_[n] = glm::length(q_[n] - q_[static_cast<size_t>(parent_[n])]);
  }

  void load(const std::vector<int>& seg) {
    pts_.resize(seg.size());
    lens_.resize(seg.size() - 1);
    for (size_t i = 0; i < seg.size(); ++i) pts_[i] = q_[static_cast<size_t>(seg[i])];
    for (size_t i = 0; i + 1 < seg.size(); ++i) lens_[i] = length_[static_cast<size_t>(seg[i + 1])];
  }

  void backward(const Context& c) {
    const int J = c.skeleton.jointCount();
    std::fill(sum_.begin(), sum_.end(), Vec3(0.0));
    std::fill(count_.begin(), count_.end(), 0);
    base_ = q_;
    for (size_t s = segments_.size(); s-- > 0;) {
      const std::vector<int>& seg = segments_[s];
      const auto end = static_cast<size_t>(seg.back());
      Vec3 target = end >= static_cast<size_t>(J) ? c.effectors[end - static_cast<size_t>(J)].targetPosition
                                                  : (count_[end] > 0 ? sum_[end] / Real(count_[end]) : q_[end]);
      load(seg);
      fabrikBackward(pts_, lens_, target);
      for (size_t i = 1; i < seg.size(); ++i) q_[static_cast<size_t>(seg[i])] = pts_[i];
      sum_[static_cast<size_t>(seg[0])] += pts_[0];
      count_[static_cast<size_t>(seg[0])] += 1;
    }
  }

  void forward() {
    for (const std::vector<int>& seg : segments_) {
      const auto start = static_cast<size_t>(seg[0]);
      const Vec3 base = parent_[start] < 0 ? base_[start] : q_[start];
      load(seg);
      fabrikForward(pts_, lens_, base);
      for (size_t i = 0; i < seg.size(); ++i) q_[static_cast<size_t>(seg[i])] = pts_[i];
    }
  }

  // Root outward: each joint's frame from its (already updated) parent, then the joint turns its
  // children onto their FABRIK positions. Leaves every frame current, so the driver skips its FK.
  //
  // Look-ahead. A ball joint followed by hinges (a finger: ball knuckle, hinged phalanges) cannot
  // be placed by its child alone: one point leaves the twist about the bone free, and the hinges
  // below can then only bend in the wrong plane. Such joints also aim the deeper descendants (up to
  // kLookahead levels) at their FABRIK positions. Their current positions are their positions at the
  // start of the pass moved by the rigid turns of the joints above, tracked per joint as (dq, dp).
  void toAngles(Context& c) {
    const int J = c.skeleton.jointCount();
    for (int j = 0; j < J; ++j) {
      const Joint& joint = c.skeleton.joint(j);
      Frame f = c.frameFromParent(j);
      const int parent = joint.parent;
      const Quat dqParent = parent >= 0 ? dq_[static_cast<size_t>(parent)] : Quat(1, 0, 0, 0);
      const Vec3 dpParent = parent >= 0 ? dp_[static_cast<size_t>(parent)] : Vec3(0.0);
      Quat turn(1, 0, 0, 0);
      Vec3 shift(0.0);
      if (used_[static_cast<size_t>(j)] && joint.type != JointType::Fixed && !kids_[static_cast<size_t>(j)].empty()) {
        from_.clear();
        to_.clear();
        w_.clear();
        for (int n : kids_[static_cast<size_t>(j)]) {
          const Vec3 local = n < J ? jointTranslation(c.skeleton.joint(n), c.pose) : c.effectors[static_cast<size_t>(n - J)].localOffset;
          from_.push_back(f.position + f.rotation * local);
          to_.push_back(q_[static_cast<size_t>(n)]);
          w_.push_back(1.0);
        }
        if (lookahead_[static_cast<size_t>(j)])
          for (int n : deeper_[static_cast<size_t>(j)]) {
            from_.push_back(dqParent * base_[static_cast<size_t>(n)] + dpParent);
            to_.push_back(q_[static_cast<size_t>(n)]);
            w_.push_back(1.0);
          }
        turn = alignJoint(c, j, f, from_, to_, w_, c.options.enforceLimits, false, &shift);
        f.rotation = f.pre * c.local[static_cast<size_t>(j)];
      }
      // This subtree's motion so far: x ↦ turn · (dqParent · x + dpParent − p) + p + shift.
      dq_[static_cast<size_t>(j)] = turn * dqParent;
      dp_[static_cast<size_t>(j)] = turn * (dpParent - f.position) + f.position + shift;
      c.frames[static_cast<size_t>(j)] = f;
    }
  }

  // The look-ahead tables of toAngles(): which joints use it, and their descendants 2..kLookahead
  // levels down (joints and effector nodes).
  void buildLookahead(const Context& c) {
    const int J = c.skeleton.jointCount();
    lookahead_.assign(static_cast<size_t>(J), 0);
    deeper_.assign(static_cast<size_t>(J), {});
    dq_.assign(static_cast<size_t>(J), Quat(1, 0, 0, 0));
    dp_.assign(static_cast<size_t>(J), Vec3(0.0));
    for (int j = 0; j < J; ++j) {
      const JointType type = c.skeleton.joint(j).type;
      if (!used_[static_cast<size_t>(j)] || (type != JointType::Ball && type != JointType::Free)) continue;
      std::vector<int> level = kids_[static_cast<size_t>(j)];
      bool hinged = false;
      for (int depth = 2; depth <= kLookahead; ++depth) {
        std::vector<int> next;
        for (int n : level) {
          if (n >= J) continue;
          const JointType t = c.skeleton.joint(n).type;
          hinged = hinged || t == JointType::Hinge || t == JointType::Prismatic;
          for (int k : kids_[static_cast<size_t>(n)]) next.push_back(k);
        }
        deeper_[static_cast<size_t>(j)].insert(deeper_[static_cast<size_t>(j)].end(), next.begin(), next.end());
        level = std::move(next);
      }
      lookahead_[static_cast<size_t>(j)] = hinged && !deeper_[static_cast<size_t>(j)].empty();
    }
  }

  static constexpr int kLookahead = 3;

  bool built_ = false, pointsOnly_ = false, pointsLoaded_ = false;
  std::vector<int> parent_;
  std::vector<std::vector<int>> kids_, segments_;
  std::vector<char> used_;
  std::vector<Vec3> q_, base_, sum_, pts_, from_, to_;
  std::vector<Real> length_, lens_, w_;
  std::vector<int> count_;
  std::vector<char> lookahead_;
  std::vector<std::vector<int>> deeper_;
  std::vector<Quat> dq_;
  std::vector<Vec3> dp_;
};

}  // namespace

std::unique_ptr<Method> makeFabrik() { return std::make_unique<Fabrik>(); }

}  // namespace detail
}  // namespace pba::ik
