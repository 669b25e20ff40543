#pragma once
// Internals shared by the IK methods (not part of the public interface): the state of one solve and
// the per-method iteration functions called by solve() in solver.cpp.
#include <array>
#include <memory>
#include <span>
#include <vector>

#include "physics/ik/exercises.h"
#include "physics/ik/solver.h"

namespace pba::ik::detail {

/// The per-joint storage of a Context (its base), kept between solves: solve() lends it out of the
/// caller's SolveWorkspace and takes it back, so that a solve reuses the capacity of the last one and
/// allocates nothing once warm. Each solve fills every member anew (from clear()).
struct ContextStorage {
  std::vector<Frame> frames;
  /// Per joint j: indices of the effectors in its subtree (j is an ancestor of the effector's joint),
  /// as belowList[belowStart[j] .. belowStart[j + 1]) — one allocation, not one per joint.
  std::vector<int> belowStart, belowList;
  /// Per joint: true when it lies on the path from the root to some effector.
  std::vector<char> active;
  /// Per ball joint: cos(L/2) with L = min(π/2, the smallest |limit| of its three DOFs); 2 (never)
  /// when a range excludes 0. A local rotation q with |q.w| ≥ it turns by less than L, and below
  /// π/2 no XYZ Euler angle exceeds the rotation angle: q is within the limits, no Euler angles
  /// needed to tell (see surelyWithinLimits).
  std::vector<Real> insideCosHalf;
  /// Per ball joint and XYZ Euler angle k, the range [lo_k, hi_k] as its middle m and half width h,
  /// for the second test of surelyWithinLimits (see principalEulerInside).
  struct EulerRange {
    Real cosMid = 1.0, sinMid = 0.0;  ///< cos m, sin m
    Real cosHalf = 2.0;               ///< cos h; −2: every principal value is inside; 2: no test
  };
  std::vector<std::array<EulerRange, 3>> eulerRanges;
  std::vector<Quat> local;  ///< R_dof per joint for `pose` (see Context)
  /// Per joint: the half angles refresh() computed for a ball joint's `local` (EulerHalfAngles; the
  /// Jacobian's axes reuse the entries whose angles still match the pose).
  std::vector<EulerHalfAngles> half;
  /// Per joint: its DOFs in `pose` lag behind `local` (alignJoint defers a ball joint's quaternion →
  /// Euler conversion, two atan2 and a hypot, while no limit needs the angles; FABRIK's forward pass a
  /// hinge's angle, an atan2, while it stays inside its limits); flushPose() writes them.
  std::vector<char> staleEuler;
  /// What forward kinematics reads of each joint, packed (a Joint with its name and limits is ~250
  /// bytes; walking 1,000 of them per pass cost more than the arithmetic).
  struct Link {
    int parent;
    bool identityRest;  ///< restRotation is the identity: skip one quaternion product
    bool prismatic;     ///< translation depends on the pose
    Vec3 offset;
    Quat rest;
  };
  std::vector<Link> links;  ///< filled by the first refresh()

  /// The state of a new solve, keeping every member's capacity: empties them, but for frames, local
  /// and half, which the solve's first refresh() rewrites entry by entry.
  void clear();
};

/// Everything one solve works on. `frames` is kept up to date with `pose` by the driver after every
/// iteration (methods that change the pose call refresh() before reading frames again).
///
/// `local` caches every joint's own rotation R_dof for `pose`, so that forward kinematics needs no
/// trigonometry: a ball joint's R_dof from its Euler DOFs costs three sincos, the dominant cost of
/// CCD and FABRIK on long chains before this cache. alignJoint() keeps `local` current for the
/// joints it turns; methods that write pose.dofs directly (Jacobian, analytic) call refresh().
struct Context : ContextStorage {
  const Skeleton& skeleton;
  Pose& pose;
  const std::vector<Effector>& effectors;
  const SolveOptions& options;
  Real meanBone = 1.0;          ///< [m] mean distance between a joint and its parent (≥ 1e-6)
  Real orientationScale = 1.0;  ///< [m/rad] resolved options.orientationScale
  Real maxErrorStep = 1.0;      ///< [m] resolved options.maxErrorStep
  std::span<const int> effectorsBelow(int j) const {
    const auto first = static_cast<size_t>(belowStart[static_cast<size_t>(j)]);
    return std::span<const int>(belowList).subspan(first,
                                                   static_cast<size_t>(belowStart[static_cast<size_t>(j) + 1]) - first);
  }
  /// True when ball joint j's local rotation q is surely within its limits, so that clamping would
  /// change nothing and no Euler angles are needed: a small rotation (|q.w| ≥ insideCosHalf), or
  /// principal XYZ Euler angles that lie inside their ranges by a margin (principalEulerInside).
  /// Conservative: false says nothing.
  bool surelyWithinLimits(int j, const Quat& q) const {
    return std::abs(q.w) >= insideCosHalf[static_cast<size_t>(j)] || principalEulerInside(j, q);
  }
  /// The principal XYZ Euler angles of q (eulerXYZFromQuat: x = atan2(s, c) for each angle) lie
  /// inside joint j's ranges by a margin, told without trigonometry: x ∈ [m − h, m + h] ⊆ [−π, π] ⇔
  /// cos(x − m) ≥ cos h ⇔ c cos m + s sin m ≥ cos h · √(s² + c²); asked with a margin of 10⁻⁹ (the
  /// entries are those of a rotation matrix, of order 1), so that a true answer is also eulerXYZFromQuat's
  /// and eulerWithinLimits then returns these angles unchanged. solver.cpp.
  bool principalEulerInside(int j, const Quat& q) const;

  /// Writes the DOFs of every joint marked stale from `local` (see staleEuler).
  void flushPose();
  /// The same for joint j (marked stale).
  void flushJoint(int j);
  /// Flushes, recomputes `local` from the pose, then every frame. O(n) with trigonometry.
  void refresh();
  /// Every frame from the cached `local` (valid when only alignJoint() changed the pose). O(n).
  void refreshFrames();
  /// Joint j's frame from its parent's entry in `frames` and the cached local rotation. O(1).
  Frame frameFromParent(int j) const;
  Frame frameFrom(int j, const Frame* parent) const {
    return linkFrame(j, parent, pose, local[static_cast<size_t>(j)]);
  }
  /// frameFrom() without the product by the local rotation: the pivot and R_pre, with rotation left
  /// at R_pre, for a method that sets joint j's rotation next.
  Frame pivotFrom(int j, const Frame* parent) const { return pivotOf(j, parent, pose); }
  /// The same for any pose p and local rotation of joint j.
  Frame linkFrame(int j, const Frame* parent, const Pose& p, const Quat& localRotation) const {
    Frame f = pivotOf(j, parent, p);
    f.rotation = f.pre * localRotation;
    return f;
  }
  /// Joint j's pivot and R_pre for pose p (rotation = R_pre), from its parent's frame.
  Frame pivotOf(int j, const Frame* parent, const Pose& p) const {
    const Link& link = links[static_cast<size_t>(j)];
    const Vec3 t = link.prismatic ? jointTranslation(skeleton.joint(j), p) : link.offset;
    Frame f;
    if (parent) {
      f.pre = link.identityRest ? parent->rotation : parent->rotation * link.rest;
      f.position = parent->position + parent->rotation * t;
    } else {
      f.pre = link.rest;
      f.position = t;
    }
    f.rotation = f.pre;
    return f;
  }
  /// What refresh() computes (the local rotations and every frame), for another pose p, into the
  /// given buffers: a trial pose of a line search, whose buffers the method swaps with `local` and
  /// `frames` when it accepts the pose (no second forward kinematics). O(n) with trigonometry.
  void evaluate(const Pose& p, std::vector<Quat>& localOut, std::vector<EulerHalfAngles>& halfOut,
                std::vector<Frame>& framesOut) const;
};

/// Lists of items per bucket, list[start[b] .. start[b + 1]) for b < buckets, each in the order
/// `each` visits them (a counting sort, with no buffer besides the two outputs): each(visit) must
/// call visit(bucket, item) for every pair, the same way both times it is called.
template <class Each>
void bucketLists(size_t buckets, Each each, std::vector<int>& start, std::vector<int>& list) {
  start.assign(buckets + 2, 0);
  each([&](size_t b, int) { ++start[b + 2]; });
  for (size_t i = 2; i < start.size(); ++i) start[i] += start[i - 1];  // start[b + 1] = where b begins
  list.resize(static_cast<size_t>(start.back()));
  each([&](size_t b, int item) { list[static_cast<size_t>(start[b + 1]++)] = item; });  // now where b ends
  start.pop_back();
}

/// One IK method: iterate() does one pass (CCD, FABRIK) or one step (Jacobian methods).
class Method {
 public:
  virtual ~Method() = default;
  virtual void iterate(Context& c) = 0;
  /// True when the method solved the problem in closed form and needs no more iterations.
  virtual bool finished() const { return false; }
  /// How the driver brings `frames` up to date after iterate(): methods that change the pose only
  /// through alignJoint() keep `local` current (FromCache), FABRIK also leaves every frame
  /// current (Current); the others need the full refresh().
  enum class FramesAfterIterate { Refresh, FromCache, Current };
  virtual FramesAfterIterate framesAfterIterate() const { return FramesAfterIterate::Refresh; }
  /// True while the method iterates on points alone and the pose lags behind (FABRIK on an
  /// unconstrained chain): the driver then measures the residual on effectorPoints() and calls
  /// finish() once, before its final measurement, to write the pose and the frames.
  virtual bool posesDeferred() const { return false; }
  virtual void effectorPoints(const Context& /*c*/, std::vector<Vec3>& /*points*/) const {}
  virtual void finish(Context& /*c*/) {}
  /// For a new solve with the same kind of method: returns the method to the state of a freshly made
  /// one (keeping the capacity of its storage) and true; false, the default, when it cannot, and the
  /// driver makes a new one.
  virtual bool resetForReuse() { return false; }
};

std::unique_ptr<Method> makeCcd();
std::unique_ptr<Method> makeFabrik();
std::unique_ptr<Method> makeJacobianMethod(SolverKind kind);
/// Gradient descent or L-BFGS (descent_solvers.cpp).
std::unique_ptr<Method> makeDescentMethod(SolverKind kind);
/// nullptr with *why set when the skeleton/effectors are not a single joint or a two-bone limb.
std::unique_ptr<Method> makeAnalytic(const Context& c, std::string* why);

/// The part of x perpendicular to the unit vector a: x − (x·a) a (the projection onto the plane
/// normal to a, e.g. a hinge's plane of motion).
inline Vec3 perpendicularPart(const Vec3& x, const Vec3& a) { return x - glm::dot(x, a) * a; }

/// The shortest arc from u to v (the turn of a bone onto its new direction in FABRIK's passes) as the
/// quaternion (|u||v| + u·v, u × v) = 2|u||v| cos(θ/2) · (cos(θ/2), sin(θ/2) n̂) (θ the angle between
/// u and v, n̂ their unit normal): the rotation shortestArc() gives, not normalised — the callers
/// normalise the product they make of it, once. One square root and no division, where the unit
/// vectors of shortestArc (Eigen's FromTwoVectors) take four roots and eight divisions; the same
/// rotation to rounding. Zero vectors and (nearly) opposite ones, 1 + cos θ < 10⁻¹² (Eigen's
/// threshold), where the axis u × v is lost: shortestArc itself.
inline Quat arcBetween(const Vec3& u, const Vec3& v) {
  const Real uu = glm::dot(u, u), vv = glm::dot(v, v);
  if (uu < 1e-24 || vv < 1e-24) return Quat(1, 0, 0, 0);
  const Real lengths = std::sqrt(uu * vv), w = lengths + glm::dot(u, v);
  if (w < 1e-12 * lengths) return shortestArc(u, v);
  const Vec3 axis = glm::cross(u, v);
  return Quat(w, axis.x, axis.y, axis.z);
}

/// A hinge's range [lo, hi], for telling without its angle whether an angle lies inside it (FABRIK's
/// passes): x ∈ [m − h, m + h] ⇔ cos(x − m) ≥ cos h, with m and h the middle and half width of the
/// range, so for (cos x, sin x) = (cx, sx)/r: cx cos m + sx sin m ≥ r cos h. Valid only for a range
/// inside (−π, π), where every angle of it has one direction and the reverse is true as well.
struct HingeRange {
  Real cosMid = 1.0, sinMid = 0.0, cosHalf = 1.0;
  bool valid = false;  ///< the range lies inside (−π, π)
  /// x inside the range by a margin (10⁻¹² of r): IK-6's clamp would leave it. False near a limit,
  /// where the angle and the clamp decide, and for r = 0.
  bool holds(Real cx, Real sx, Real r) const {
    return valid && r > 0.0 && cx * cosMid + sx * sinMid >= (cosHalf + 1e-12) * r;
  }
};
/// Per joint, its HingeRange (valid for hinges whose range lies inside (−π, π)); the cosines are
/// computed once per distinct range (a chain repeats one). align.cpp.
void hingeRanges(const Skeleton& s, std::vector<HingeRange>& out);
/// alignJoint's hinge update (the exact one-DOF optimum, Workbook §2.4) without angles while it stays
/// inside the limits (Workbook §2.7's clamp, which would then change nothing; FABRIK's forward pass,
/// Aristidou & Lasenby 2011 §4.2): ψ = d + atan2(S, C) (bestAngleTerms; d the hinge's angle) as a direction,
/// (cos ψ, sin ψ) ∝ (cos d C − sin d S, sin d C + cos d S), with cos d = w² − s², sin d = 2ws from its
/// local rotation (w, s a). When `range` holds ψ, the hinge takes R(ψ) = (1 + cos ψ, sin ψ a)
/// normalised and is marked stale (its angle is written by flushPose, one atan2, instead of an
/// atan2 and two sincos here). Returns false, doing nothing, otherwise: alignJoint then turns it by
/// the angle and clamps. `from` in world coordinates, as for alignJoint.
bool turnHingeWithinLimits(Context& c, int j, const Frame& f, const HingeRange& range, const std::vector<Vec3>& from,
                           const std::vector<Vec3>& to, const std::vector<Real>& w);

/// Rotates/translates joint j (whose world pre-rotation and pivot are `frame`) to best carry the
/// points `from[i]` (world, currently attached below j) onto `to[i]` with weights w[i]:
/// minimises Σ wᵢ |T(fromᵢ) − toᵢ|² over the joint's DOFs, exactly for a hinge, prismatic or a single
/// point on a ball/free joint, by a few per-axis sweeps otherwise. Clamps to limits when asked.
/// Returns the world rotation actually applied about the pivot (identity for prismatic) and, through
/// *translation, the world translation applied (prismatic).
/// `useExercise` routes single-point ball/free updates through IK-2 (ccdJointUpdate), as CCD does.
/// `maxTurn` > 0 [rad] (SolveOptions::ccdMaxTurn, ours): a rotational joint turns by at most this
/// before the limits clamp it; 0, the published update. Updates c.local[j] (not c.frames).
Quat alignJoint(Context& c, int j, const Frame& frame, const std::vector<Vec3>& from, const std::vector<Vec3>& to,
                const std::vector<Real>& w, bool clampLimits, bool useExercise, Vec3* translation, Real maxTurn = 0.0);

/// The rotation angle about the unit axis `a` through `p` that best carries the points `from` onto
/// `to` (weights w): θ = atan2(Σ wᵢ a·(u⊥ᵢ × v⊥ᵢ), Σ wᵢ u⊥ᵢ·v⊥ᵢ) (align.cpp). 0 when undefined.
Real bestAngle(const Vec3& a, const Vec3& p, const std::vector<Vec3>& from, const std::vector<Vec3>& to,
               const std::vector<Real>& w);
/// The two sums of bestAngle, *S = Σ wᵢ a·(u⊥ᵢ × v⊥ᵢ) and *C = Σ wᵢ u⊥ᵢ·v⊥ᵢ: the best turn is the angle
/// of the vector (C, S).
void bestAngleTerms(const Vec3& a, const Vec3& p, const std::vector<Vec3>& from, const std::vector<Vec3>& to,
                    const std::vector<Real>& w, Real* S, Real* C);
/// The representative ψ − 2π, ψ or ψ + 2π of a hinge optimum ψ whose value clamped into [lo, hi] is
/// closest to ψ in angle (ψ itself when clampLimits is false). The caller clamps.
Real bestHingeValue(Real psi, Real lo, Real hi, bool clampLimits);

/// The rotation R maximising Σ wᵢ toᵢ·(R fromᵢ) (Horn's quaternion method: the least-squares
/// rotation carrying the vectors `from` onto `to`), nearest `reference` where the vectors leave a
/// rotation free (collinear or coincident points). fit_rotation.cpp.
Quat fitRotation(const std::vector<Vec3>& from, const std::vector<Vec3>& to, const std::vector<Real>& w,
                 const Quat& reference);

/// XYZ Euler angles (a, b, c) of a ball joint's local rotation q in the representation its limits
/// admit. Every rotation has two, the principal one (b in [−π/2, π/2], eulerXYZFromQuat) and
/// (a + π, π − b, c + π); limits wider than ±90° on b admit rotations only in the second, and an
/// angle may also need a shift by 2π into [lo, hi]. Returns the one inside the limits, else the one
/// that clamping moves least (principal on ties); *inside says which case it was (may be null).
Vec3 eulerWithinLimits(const Joint& joint, const Quat& q, bool* inside = nullptr);

/// Sets ball or free joint j's local rotation to `wanted`, clamped to its limits (IK-6) when
/// clampLimits and a limit can act; keeps c.local[j] current (a ball joint's Euler angles are left
/// to flushPose() when no clamp was needed). Returns the local rotation actually applied (c.local[j]).
const Quat& setJointRotation(Context& c, int j, const Quat& wanted, bool clampLimits);

/// True when joint j's rotation limits admit every rotation (ball: Euler ranges cover [−π, π] ×
/// [−π/2, π/2] × [−π, π]; free: maxRotation ≥ π), so clamping can never change it. Hinges,
/// prismatic and fixed joints: false.
bool rotationUnlimited(const Joint& joint);

/// IK-6's clamp on candidate values of joint k that are not the pose's: the `count` scalar DOFs
/// `values` (hinge angle, displacement, Euler angles) are written into the pose's slots of joint k,
/// clamped there and read back, and the slots are restored. Inline: FABRIK's passes call it per joint.
inline Vec3 clampedByLimits(Context& c, int k, const Real* values, int count) {
  Real* slots = c.pose.dofs.data() + c.skeleton.joint(k).firstDof;
  Vec3 saved(0.0), out(0.0);
  for (int i = 0; i < count; ++i) saved[i] = slots[i], slots[i] = values[i];
  clampJointToLimits(c.skeleton, c.pose, k);
  for (int i = 0; i < count; ++i) out[i] = slots[i], slots[i] = saved[i];
  return out;
}
/// The same for a free joint's rotation q.
inline Quat clampedRotation(Context& c, int k, const Quat& q) {
  Quat& slot = c.pose.rotations[static_cast<size_t>(k)];
  const Quat saved = slot;
  slot = q;
  clampJointToLimits(c.skeleton, c.pose, k);
  const Quat out = slot;
  slot = saved;
  return out;
}

/// SolveOptions::fabrikLimitFit (ours): ball joint j with pivot and pre-rotation `f` takes, when its
/// best rotation `wanted` (local) leaves its limits, the local rotation inside them that best carries
/// the points `from` (its frame) onto `goals` (world, relative to the pivot) with weights w. Writes
/// the pose and c.local[j]. Returns false, doing nothing, when `wanted` is within the limits or the
/// joint is no limited ball joint. `scratch`: reused storage. fabrik_options.cpp.
bool fitBallWithinLimits(Context& c, int j, const Frame& f, const Quat& wanted, const std::vector<Vec3>& from,
                         const std::vector<Vec3>& goals, const std::vector<Real>& w, std::vector<Vec3>& scratch);

/// SolveOptions::fabrikHingeTwist (ours): the turns φ about the unit axis *d from `pivot` toward
/// `goal` that bring a hinge's world axis `axis` perpendicular to oldP − pivot (the hinge's plane
/// through oldP), or nearest it. Writes 0 or 2 angles into phi[0..1] and returns their count (0 when
/// no turn changes the plane: goal at the pivot, or the axis or oldP − pivot along *d).
int hingePlaneTurns(const Vec3& axis, const Vec3& pivot, const Vec3& goal, const Vec3& oldP, Vec3* d, Real* phi);

/// fabrikHingeTwist's turns, deferred: FABRIK's backward pass turns the part it has placed below a
/// hinge as one piece, but moves only the hinge's own body at once; every other joint of the part
/// gets the turns made after it was placed when the pass ends (apply), so a turn costs O(1), not the
/// size of the part. Parts are told apart by their one effector.
class DeferredTurns {
 public:
  void build(const Context& c);
  void reset();  ///< start of a pass: no turns yet
  /// The one position effector below joint j (the part it belongs to), or -1 (never turned).
  int effectorOf(int j) const { return effector_[static_cast<size_t>(j)]; }
  /// Joint j's body was just placed.
  void placed(int j) {
    if (const int e = effectorOf(j); e >= 0) placed_[static_cast<size_t>(j)] = turns_[static_cast<size_t>(e)];
  }
  /// Turns the part below hinge k by φ about the unit axis d through `pivot`; returns body k's new
  /// rotation (from R).
  Quat turn(int k, Real phi, const Vec3& d, const Vec3& pivot, const Quat& R);
  /// End of the pass: each active joint below a turned hinge gets the turns made after its placing.
  void apply(const Context& c, std::vector<Vec3>& P, std::vector<Quat>& R) const;

 private:
  struct Motion {  // x ↦ q x + t
    Quat q{1, 0, 0, 0};
    Vec3 t{0.0};
  };
  std::vector<int> effector_;   // per joint: see effectorOf
  std::vector<Motion> turns_;   // per effector: the turns made this pass, composed
  std::vector<Motion> placed_;  // per joint: its effector's turns when the joint was placed
};

/// The straight pose toward the goal for a single unreachable position effector: each joint on the
/// path, from the root, turns its bone toward the goal (Aristidou & Lasenby 2011, Algorithm 1, lines
/// 3–8). Exact for ball and free joints without limits; best effort otherwise.
void stretchToward(Context& c, const Effector& e);

}  // namespace pba::ik::detail
