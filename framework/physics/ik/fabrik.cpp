// FABRIK: forward and backward reaching inverse kinematics (Aristidou & Lasenby 2011, Algorithms 1
// and 2; CMU asst4 lists it among the extensions).
//   backward: put the end on the goal, then walk toward the base, placing each point on the line to
//             its successor at the bone's length;
//   forward:  put the base back, then walk toward the end the same way.
//
// Plain FABRIK works on points. On a single chain of ball or free joints that no limit restricts
// (the setting of the FABRIK paper) every placement of the points is a pose, so the solver iterates
// on the points alone (IK-5's passes, fabrik_passes.cpp) and turns them into joint angles once, when
// the driver stops (finish()).
//
// Everywhere else (trees, hinges, prismatic joints, limits) FABRIK runs on rigid bodies: joint j's
// body is its frame (pivot P_j, world rotation R_j) with the points fixed in it: the pivots of its
// child joints and its effector points. The passes apply the same rule to bodies instead of points,
// which keeps what the point version loses: the twist of each bone (a ball knuckle followed by
// hinges: the plane the finger bends in), the rigid shape of a body with several children (a palm,
// or the coincident branch joints of Buss's double Y) and the joint constraints (Aristidou &
// Lasenby §4.2 apply them inside the passes too, as rotational and orientational constraints).
//   backward, tips to root: body j proposes, for each child joint c (already moved) and each
//     effector, where it would go by the point rule: the attachment point onto the child's new pivot
//     (or the goal), the pivot on the line back toward its old place (IK-5's fabrikBackward on the
//     two points), the body turned by the shortest arc between the old and new bone directions. The
//     joint between body j and child c must then be possible: a hinge leaves one angle, so body j
//     swings about the child's hinge axis to the pivot nearest the rule's; limits clamp the relative
//     rotation, and body j moves to match. Several proposals (a sub-base, §4.3 "multiple end
//     effectors"): the pivot goes to their centroid (as in the paper) and the body turns to the
//     rotation that best carries its points onto the children's new pivots and goals (weighted
//     Horn fit; ties, e.g. coincident points, broken toward the mean of the proposed rotations).
//   forward, root to tips: each joint's pivot is fixed by its parent; the joint turns its body from
//     the backward pass's orientation so that its points move toward their backward-pass places
//     (IK-5's fabrikForward for one point, the same Horn fit for several; hinges and prismatic
//     joints by the exact one-DOF optimum), then clamps to its limits. The pose is always valid.
// 6-DOF effectors: the backward pass puts the body on the goal frame; the forward pass aligns three
// extra points s·(x̂, ŷ, ẑ) of the effector frame with the goal frame's, as CCD does.
// Two departures of ours, options off by default (SolveOptions, fabrik_options.cpp): fabrikHingeTwist
// (the placed part below a hinge turns about the line to its goal, choosing the plane the hinge bends
// in) and fabrikLimitFit (a limited ball joint takes the best rotation inside its limits, not the
// clamp of the best rotation).
// Cost: O(n) per iteration (a Horn fit, a 4 × 4 eigenproblem, only at bodies with several points).
// Limits without trigonometry where they do not act: a ball joint's are skipped when its rotation is
// surely inside them (Context::surelyWithinLimits), a hinge's when its angle's direction lies inside
// its range (HingeRange; the hinge then turns by half-angle quaternions, its angle written once at
// the end); only at or past a limit do the Euler angles or the hinge angle and IK-6's clamp decide.
// Bones turn by arcBetween (one square root; the same rotation as shortestArc to rounding).
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <span>

#include "physics/ik/exercises.h"
#include "physics/ik/fabrik_tree.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik {
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
        pts_.clear();
        for (int j : chain_) pts_.push_back(c.frames[static_cast<size_t>(j)].position);
        pts_.push_back(effectorPosition(c.effectors[0], c.frames));
        lens_.resize(pts_.size() - 1);
        for (size_t i = 0; i + 1 < pts_.size(); ++i) lens_[i] = glm::length(pts_[i + 1] - pts_[i]);
        base_ = pts_.front();
        pointsLoaded_ = true;
      }
      fabrikBackward(pts_, lens_, c.effectors[0].targetPosition);
      fabrikForward(pts_, lens_, base_);
      return;
    }
    backward(c);
    forward(c);
  }

  bool resetForReuse() override {  // build() fills every member anew at the next iteration
    built_ = pointsOnly_ = pointsLoaded_ = false;
    return true;
  }

  void finish(Context& c) override {
    if (!posesDeferred()) return;
    // The forward pass onto the points: each joint's child (or the effector) onto its point.
    for (size_t i = 0; i < chain_.size(); ++i) {
      const auto j = static_cast<size_t>(chain_[i]);
      P_[j] = pts_[i];
      R_[j] = c.frames[j].rotation;
    }
    target_[0] = pts_.back();
    forward(c);
    target_[0] = c.effectors[0].targetPosition;
    pointsLoaded_ = false;
  }

 private:
  void build(const Context& c) {
    built_ = true;
    const int J = c.skeleton.jointCount(), E = static_cast<int>(c.effectors.size());
    tree_.build(c);
    target_.resize(static_cast<size_t>(E));
    for (int e = 0; e < E; ++e) target_[static_cast<size_t>(e)] = c.effectors[static_cast<size_t>(e)].targetPosition;
    // Points only: one chain from the root to a single position effector through ball or free joints
    // that no limit restricts. Then every point placement is reachable by the joint angles.
    chain_.clear();
    pointsOnly_ = E == 1 && c.effectors[0].kind == EffectorKind::Position;
    for (int j = 0; j < J && pointsOnly_; ++j) {
      if (!c.active[static_cast<size_t>(j)]) continue;
      chain_.push_back(j);
      const Joint& joint = c.skeleton.joint(j);
      const bool rotates = joint.type == JointType::Ball || joint.type == JointType::Free;
      pointsOnly_ = rotates && (!c.options.enforceLimits || rotationUnlimited(joint));
    }
    hingeRanges(c.skeleton, hingeRange_);
    lever_.assign(static_cast<size_t>(J), -1.0);
    for (int j = 0; j < J; ++j)
      if (c.skeleton.joint(j).type != JointType::Prismatic)
        lever_[static_cast<size_t>(j)] = glm::length(c.skeleton.joint(j).offset);
    limited_.assign(static_cast<size_t>(J), 0);
    for (int j = 0; j < J; ++j) limited_[static_cast<size_t>(j)] = !rotationUnlimited(c.skeleton.joint(j));
    if (c.options.fabrikHingeTwist) turns_.build(c);
    P_.assign(static_cast<size_t>(J), Vec3(0.0));
    R_.assign(static_cast<size_t>(J), Quat(1, 0, 0, 0));
    two_.assign(2, Vec3(0.0));
    one_.assign(1, 0.0);
  }

  // |translation| of joint k (its bone, as a lever of its parent's body), kept for the joints that are
  // not prismatic.
  Real lever(const Context& c, int k) const {
    const Real l = lever_[static_cast<size_t>(k)];
    return l >= 0.0 ? l : glm::length(translationOf(c.skeleton.joint(k), c.pose));
  }

  // jointTranslation() inline: a joint's translation is its offset unless it is prismatic.
  static Vec3 translationOf(const Joint& joint, const Pose& pose) {
    return joint.type == JointType::Prismatic ? jointTranslation(joint, pose) : joint.offset;
  }

  // The points of joint j's body: in its frame (from_), their goals (to_, world) and weights.
  // Effectors first (6-DOF ones add three points at s·x̂, s·ŷ, s·ẑ of their frame), then child joints.
  void bodyPoints(const Context& c, int j) {
    from_.clear();
    to_.clear();
    w_.clear();
    for (int e : tree_.effectorsOn(j)) {
      const Effector& eff = c.effectors[static_cast<size_t>(e)];
      from_.push_back(eff.localOffset);
      to_.push_back(target_[static_cast<size_t>(e)]);
      w_.push_back(eff.weight);
      if (eff.kind == EffectorKind::PositionOrientation) {
        for (int k = 0; k < 3; ++k) {
          Vec3 axis(0.0);
          axis[k] = c.orientationScale;
          from_.push_back(eff.localOffset + axis);
          to_.push_back(target_[static_cast<size_t>(e)] + eff.targetOrientation * axis);
          w_.push_back(eff.weight);
        }
      }
    }
    for (int k : tree_.kids(j)) {
      from_.push_back(translationOf(c.skeleton.joint(k), c.pose));
      to_.push_back(P_[static_cast<size_t>(k)]);
      w_.push_back(1.0);
    }
  }

  // The point rule on one lever b of body (P, R): the point onto `goal`, the pivot back toward P.
  void propose(const Vec3& P, const Quat& R, const Vec3& b, const Vec3& goal, Vec3* Pp, Quat* Rp) {
    propose(P, R, P + R * b, glm::length(b), goal, Pp, Rp);
  }
  // The same with the lever's point a = P + R b and its length |b| given (a child's pivot before the
  // pass, c.frames: the same sum, the same bits).
  void propose(const Vec3& P, const Quat& R, const Vec3& a, Real length, const Vec3& goal, Vec3* Pp, Quat* Rp) {
    two_[0] = P;
    two_[1] = a;
    one_[0] = length;
    fabrikBackward(two_, one_, goal);
    *Pp = two_[0];
    *Rp = glm::normalize(arcBetween(P - a, two_[0] - goal) * R);
  }

  // Joint k (child of body j) must relate body j's proposal (*Pp, *Rp) to body k's new pose: moves
  // the proposal to the nearest one the joint allows. `oldP`, `oldR`: body j's pose before the pass.
  // Only ball and free joints start from the point rule's proposal (the caller's propose()); the others
  // fix body j from body k and their one DOF, and a hinge asks for the proposal only where its optimum
  // is undefined.
  void constrain(Context& c, int k, const Vec3& oldP, const Quat& oldR, Vec3* Pp, Quat* Rp) {
    const Joint& joint = c.skeleton.joint(k);
    const Vec3& Pk = P_[static_cast<size_t>(k)];
    const Quat& Rk = R_[static_cast<size_t>(k)];
    const Quat restInverse = glm::conjugate(joint.restRotation);
    const bool clamp = c.options.enforceLimits;
    switch (joint.type) {
      case JointType::Fixed:
        *Rp = Rk * restInverse;
        break;
      case JointType::Prismatic: {
        // No rotation: body j's orientation follows; the displacement puts its pivot nearest oldP.
        *Rp = Rk * restInverse;
        const Vec3 u = *Rp * (joint.restRotation * joint.axis), base = Pk - *Rp * joint.offset;
        Real d = glm::dot(base - oldP, u);
        if (clamp) d = clampedByLimits(c, k, &d, 1)[0];
        *Pp = base - u * d;
        return;
      }
      case JointType::Hinge: {
        // Body j = R(−θ about w) · R_k · Q⁻¹ with w = R_k a: its pivot turns about w through P_k,
        // from P_k − R_k Q⁻¹ t at θ = 0. The angle that brings it nearest oldP (the point rule's
        // pivot lies on the line from P_k to oldP); where that is undefined (lever along the axis,
        // or oldP on it), the twist of the rule's proposal.
        const Vec3 w = Rk * joint.axis;
        const Vec3 t = translationOf(joint, c.pose);
        const bool identityRest = c.links[static_cast<size_t>(k)].identityRest;  // skip products by 1
        const Vec3 u = perpendicularPart(-(Rk * (identityRest ? t : restInverse * t)), w),
                   v = perpendicularPart(oldP - Pk, w);
        const Real S = glm::dot(w, glm::cross(u, v)), C = glm::dot(u, v);
        const bool defined = std::abs(S) + std::abs(C) > 1e-12 * (glm::dot(t, t) + glm::dot(oldP - Pk, oldP - Pk));
        // θ = −atan2(S, C): (cos θ, sin θ) = (C, −S)/r, r = |(C, S)|. The limit is the clamp of
        // Workbook §2.7 (IK-6) applied inside the pass, as Aristidou & Lasenby 2011 §4.2 apply
        // their rotational constraints. Inside the limits, where the clamp would change nothing,
        // no angle is needed (HingeRange): R(−θ about a) = (cos ½θ, −sin ½θ a) is (1 + cos θ,
        // −sin θ a) normalised, here (r + C, S a) normalised. At or past a limit, the angle.
        const Real r = std::sqrt(S * S + C * C);
        if (defined && clamp && hingeRange_[static_cast<size_t>(k)].holds(C, -S, r)) {
          const Quat turned = Rk * Quat(r + C, S * joint.axis.x, S * joint.axis.y, S * joint.axis.z);
          *Rp = glm::normalize(identityRest ? turned : turned * restInverse);
          break;
        }
        Real theta;
        if (defined) {
          theta = -std::atan2(S, C);
        } else {
          propose(oldP, oldR, t, Pk, Pp, Rp);
          const Quat local = glm::conjugate(*Rp * joint.restRotation) * Rk;
          theta = 2.0 * std::atan2(glm::dot(Vec3(local.x, local.y, local.z), joint.axis), local.w);
        }
        if (clamp) {
          theta = bestHingeValue(theta, joint.lo[0], joint.hi[0], true);
          theta = clampedByLimits(c, k, &theta, 1)[0];
        }
        *Rp = glm::normalize(Rk * glm::angleAxis(-theta, joint.axis) * restInverse);
        break;
      }
      case JointType::Ball:
      case JointType::Free: {
        if (!clamp || !limited_[static_cast<size_t>(k)]) return;
        const Quat parent = c.links[static_cast<size_t>(k)].identityRest ? *Rp : *Rp * joint.restRotation;
        // A product of unit quaternions, unit to rounding: good enough for the test, whose margins
        // (10⁻¹², 10⁻⁹) are far above it; normalised only when the limits need a closer look.
        const Quat product = glm::conjugate(parent) * Rk;
        if (joint.type == JointType::Ball && c.surelyWithinLimits(k, product)) return;
        const Quat local = glm::normalize(product);
        Quat allowed = local;
        if (joint.type == JointType::Ball) {
          const Vec3 e = eulerWithinLimits(joint, local);
          const Vec3 clamped = clampedByLimits(c, k, &e[0], 3);
          if (clamped == e) return;
          allowed = quatFromEulerXYZ(clamped);
        } else {
          allowed = clampedRotation(c, k, local);
          if (allowed == local) return;
        }
        *Rp = glm::normalize(Rk * glm::conjugate(allowed) * restInverse);
        break;
      }
    }
    *Pp = Pk - *Rp * translationOf(joint, c.pose);
  }

  void backward(Context& c) {
    const int J = c.skeleton.jointCount();
    const bool twist = c.options.fabrikHingeTwist;
    if (twist) turns_.reset();
    for (int j = J - 1; j >= 0; --j) {
      if (!c.active[static_cast<size_t>(j)]) continue;
      const Vec3 oldP = c.frames[static_cast<size_t>(j)].position;  // body j before the pass
      const Quat oldR = c.frames[static_cast<size_t>(j)].rotation;
      int proposals = 0;
      Vec3 sumP(0.0), Pp(0.0);
      Quat sumR(0, 0, 0, 0), Rp(1, 0, 0, 0);
      auto add = [&](const Vec3& p, const Quat& r) {
        ++proposals;
        sumP += p;
        sumR = sumR + (glm::dot(sumR, r) < 0.0 ? -r : r);
        Pp = p;
        Rp = r;
      };
      for (int e : tree_.effectorsOn(j)) {
        const Effector& eff = c.effectors[static_cast<size_t>(e)];
        if (eff.kind == EffectorKind::PositionOrientation) {
          // The body onto the goal frame: exact, position and orientation.
          add(eff.targetPosition - eff.targetOrientation * eff.localOffset, eff.targetOrientation);
          continue;
        }
        propose(oldP, oldR, eff.localOffset, eff.targetPosition, &Pp, &Rp);
        add(Pp, Rp);
      }
      for (int k : tree_.kids(j)) {
        const Joint& kid = c.skeleton.joint(k);
        if (kid.type == JointType::Ball || kid.type == JointType::Free)
          propose(oldP, oldR, c.frames[static_cast<size_t>(k)].position, lever(c, k), P_[static_cast<size_t>(k)], &Pp,
                  &Rp);
        else if (twist && kid.type == JointType::Hinge && turns_.effectorOf(k) >= 0)
          twistBelow(c, k, oldP, oldR);
        constrain(c, k, oldP, oldR, &Pp, &Rp);
        add(Pp, Rp);
      }
      if (proposals == 1) {
        P_[static_cast<size_t>(j)] = Pp;
        R_[static_cast<size_t>(j)] = Rp;
        if (twist) turns_.placed(j);
        continue;
      }
      // A sub-base: the pivot at the centroid of the proposals (Aristidou & Lasenby §4.3), the body
      // turned to carry its points best onto their new places.
      const Vec3 P = sumP / Real(proposals);
      bodyPoints(c, j);
      for (Vec3& t : to_) t -= P;
      P_[static_cast<size_t>(j)] = P;
      R_[static_cast<size_t>(j)] = fitRotation(from_, to_, w_, glm::normalize(sumR));
    }
    if (twist) turns_.apply(c, P_, R_);
  }

  // fabrikHingeTwist (ours): the part below hinge k, placed by this pass, with one position effector
  // on its goal, turns about the line from P_k to the goal by the candidate (hingePlaneTurns) whose
  // hinge-constrained pivot for the parent lies nearest oldP; φ = 0 is the published pass. Ties (no
  // limit acting: both candidates reach the point rule's pivot) keep the smaller turn.
  void twistBelow(Context& c, int k, const Vec3& oldP, const Quat& oldR) {
    const auto e = static_cast<size_t>(turns_.effectorOf(k));
    const Vec3 Pk = P_[static_cast<size_t>(k)];
    const Quat Rk = R_[static_cast<size_t>(k)];
    Vec3 d(0.0);
    Real phi[3] = {0.0, 0.0, 0.0};
    const int count = 1 + hingePlaneTurns(Rk * c.skeleton.joint(k).axis, Pk, target_[e], oldP, &d, phi + 1);
    Real bestPhi = 0.0, bestScore = std::numeric_limits<Real>::infinity();
    const Real lever = glm::length(oldP - Pk);
    for (int i = 0; i < count; ++i) {
      R_[static_cast<size_t>(k)] = glm::normalize(glm::angleAxis(phi[i], d) * Rk);
      Vec3 Pp = oldP;
      Quat Rp = oldR;
      constrain(c, k, oldP, oldR, &Pp, &Rp);
      // The distance, plus a tie-break far below it (10⁻⁹ of the lever per radian): the smaller turn.
      const Real score = glm::length(Pp - oldP) + 1e-9 * lever * std::abs(phi[i]);
      if (score < bestScore) bestScore = score, bestPhi = phi[i];
    }
    R_[static_cast<size_t>(k)] = Rk;
    // Body k turns now (the caller's constrain() reads it), its descendants when the pass ends.
    if (bestPhi != 0.0) R_[static_cast<size_t>(k)] = turns_.turn(k, bestPhi, d, Pk, Rk);
  }

  // Root outward: each joint's pivot from its (already updated) parent, then the joint turns its
  // body's points toward their backward-pass places. Leaves every frame current.
  void forward(Context& c) {
    const int J = c.skeleton.jointCount();
    const bool clamp = c.options.enforceLimits;
    for (int j = 0; j < J; ++j) {
      const Joint& joint = c.skeleton.joint(j);
      const Frame* parent = joint.parent >= 0 ? &c.frames[static_cast<size_t>(joint.parent)] : nullptr;
      if (!c.active[static_cast<size_t>(j)] || joint.type == JointType::Fixed) {
        c.frames[static_cast<size_t>(j)] = c.frameFrom(j, parent);
        continue;
      }
      const bool rotates = joint.type == JointType::Ball || joint.type == JointType::Free;
      Frame f = rotates ? c.pivotFrom(j, parent) : c.frameFrom(j, parent);  // a ball's rotation is set below
      Vec3 from, to;
      Real length = 0.0;
      if (rotates) {
        if (onePoint(c, j, &from, &to, &length)) {
          setJointRotation(c, j, pointRule(f, R_[static_cast<size_t>(j)], from, to, length), clamp);
        } else {
          bodyPoints(c, j);
          turnBall(c, j, f, clamp);
        }
      } else {
        bodyPoints(c, j);
        for (size_t i = 0; i < from_.size(); ++i) from_[i] = f.position + f.rotation * from_[i];
        if (!(joint.type == JointType::Hinge && clamp &&
              turnHingeWithinLimits(c, j, f, hingeRange_[static_cast<size_t>(j)], from_, to_, w_))) {
          if (c.staleEuler[static_cast<size_t>(j)]) c.flushJoint(j);  // alignJoint turns from the angle
          alignJoint(c, j, f, from_, to_, w_, clamp, false, nullptr);
        }
        if (joint.type == JointType::Prismatic) f = c.frameFrom(j, parent);  // a hinge's pivot stays
      }
      // Field by field: a copy of f would reload the rotation just stored as scalars in 16-byte pieces
      // (a store-forwarding stall per joint).
      Frame& out = c.frames[static_cast<size_t>(j)];
      out.position = f.position;
      out.pre = f.pre;
      out.rotation = f.pre * c.local[static_cast<size_t>(j)];
    }
  }

  // forward() for a ball or free joint: the point rule (IK-5's fabrikForward on the one body point,
  // the body turned by the shortest arc from its backward-pass orientation), or the Horn fit of its
  // points, nearest the backward-pass orientation. Then the limits (IK-6).
  // Look-ahead: a ball joint followed by hinges (a finger: ball knuckle, hinged phalanges) cannot be
  // turned by its child alone: one point leaves the twist about the bone free, and the hinges below
  // can then only bend in the wrong plane. Such joints also aim their deeper descendants (joints and
  // effectors, FabrikTree) at their backward-pass places, in the fit; the descendants keep the
  // shape they have at the start of the pass (their places in c.frames, which forward() has not
  // reached yet).
  void turnBall(Context& c, int j, const Frame& f, bool clamp) {
    const int J = c.skeleton.jointCount();
    const Quat& reference = R_[static_cast<size_t>(j)];
    if (const std::span<const int> deeper = tree_.deeper(j); !deeper.empty()) {
      const Frame& old = c.frames[static_cast<size_t>(j)];
      const Quat oldInverse = glm::conjugate(old.rotation);
      for (int n : deeper) {
        const bool effector = n >= J;
        const Vec3 now = effector ? effectorPosition(c.effectors[static_cast<size_t>(n - J)], c.frames)
                                  : c.frames[static_cast<size_t>(n)].position;
        from_.push_back(oldInverse * (now - old.position));
        to_.push_back(effector ? target_[static_cast<size_t>(n - J)] : P_[static_cast<size_t>(n)]);
        w_.push_back(tree_.lookaheadWeight(j));
      }
    }
    Quat wanted;
    if (from_.size() == 1) {
      wanted = pointRule(f, reference, from_[0], to_[0], glm::length(from_[0]));
    } else {
      for (Vec3& t : to_) t -= f.position;
      wanted = glm::normalize(glm::conjugate(f.pre) * fitRotation(from_, to_, w_, reference));
    }
    if (clamp && c.options.fabrikLimitFit) {  // ours: the best rotation inside the limits
      goals_.assign(to_.begin(), to_.end());
      if (from_.size() == 1) goals_[0] -= f.position;  // the fit above left several goals relative
      if (fitBallWithinLimits(c, j, f, wanted, from_, goals_, w_, moved_)) return;
    }
    setJointRotation(c, j, wanted, clamp);
  }

  // The point rule of the forward pass for a body with one point (`from` in its frame, headed for
  // `to`, world), from its backward-pass orientation `reference`: IK-5's fabrikForward puts the point
  // on the line from the pivot toward `to`, and the body turns by the shortest arc onto it. Returns
  // the joint's wanted local rotation (before its limits).
  Quat pointRule(const Frame& f, const Quat& reference, const Vec3& from, const Vec3& to, Real length) {
    two_[0] = f.position;
    two_[1] = to;
    one_[0] = length;
    fabrikForward(two_, one_, f.position);
    const Quat world = arcBetween(reference * from, two_[1] - f.position) * reference;
    return glm::normalize(glm::conjugate(f.pre) * world);
  }

  // True when the forward pass turns ball or free joint j's body by one point alone, the point rule
  // (pointRule: one position effector or one child, no look-ahead, no limit fit); then its place in
  // the body's frame (*from), its backward-pass place (*to) and |from|. What bodyPoints() would give,
  // without its lists.
  bool onePoint(const Context& c, int j, Vec3* from, Vec3* to, Real* length) const {
    const std::span<const int> effectors = tree_.effectorsOn(j), children = tree_.kids(j);
    if (effectors.size() + children.size() != 1 || c.options.fabrikLimitFit || !tree_.deeper(j).empty()) return false;
    if (!effectors.empty()) {
      const Effector& eff = c.effectors[static_cast<size_t>(effectors[0])];
      if (eff.kind != EffectorKind::Position) return false;
      *from = eff.localOffset;
      *to = target_[static_cast<size_t>(effectors[0])];
      *length = glm::length(*from);
    } else {
      *from = translationOf(c.skeleton.joint(children[0]), c.pose);
      *to = P_[static_cast<size_t>(children[0])];
      *length = lever(c, children[0]);
    }
    return true;
  }

  bool built_ = false, pointsOnly_ = false, pointsLoaded_ = false;
  FabrikTree tree_;                     // active children, effectors and look-ahead per joint
  std::vector<int> chain_;              // points only: the joints from the root
  std::vector<char> limited_;           // per joint: !rotationUnlimited()
  std::vector<Real> lever_;             // per joint: |offset|, −1 for prismatic joints (see lever())
  std::vector<HingeRange> hingeRange_;  // per joint (hingeRanges)
  std::vector<Vec3> P_;                 // per joint: body pivot after the backward pass
  std::vector<Quat> R_;                 // per joint: body rotation after the backward pass
  std::vector<Vec3> target_;            // per effector: where the forward pass aims it
  DeferredTurns turns_;                 // fabrikHingeTwist's turns, applied when the pass ends
  std::vector<Vec3> pts_, two_, from_, to_, goals_, moved_;
  std::vector<Real> lens_, one_, w_;
  Vec3 base_{0.0};
};

}  // namespace

std::unique_ptr<Method> makeFabrik() { return std::make_unique<Fabrik>(); }

}  // namespace detail
}  // namespace pba::ik
