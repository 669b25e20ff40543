// The IK driver: validation, repeatability, the reachability check, the iteration loop and the
// stopping rules (IK slides, "Stopping"), around the methods of ccd.cpp, fabrik.cpp,
// jacobian_solvers.cpp and analytic.cpp.
#include "physics/ik/solver.h"

#include "physics/core/enum_names.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "physics/core/validate.h"
#include "physics/ik/exercises.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik {

namespace {
constexpr auto kStatusNames = enumNames<SolveStatus>({{SolveStatus::Success, "success"},
                                                      {SolveStatus::Unreachable, "unreachable"},
                                                      {SolveStatus::Stalled, "stalled"},
                                                      {SolveStatus::IterationCap, "iteration_cap"},
                                                      {SolveStatus::TimeCap, "time_cap"},
                                                      {SolveStatus::NotApplicable, "not_applicable"},
                                                      {SolveStatus::InvalidInput, "invalid_input"}});
}  // namespace

const char* statusName(SolveStatus s) { return kStatusNames.name(s).data(); }

namespace {

Status validateInputs(const Skeleton& s, const Pose& pose, const std::vector<Effector>& effectors,
                      const SolveOptions& o) {
  if (s.jointCount() == 0) return Error{"skeleton: has no joints"};
  if (Status st = validate(s, pose); !st) return st;
  for (size_t k = 0; k < effectors.size(); ++k) {
    const Effector& e = effectors[k];
    // The field's name is built only for a message (a solve of 10 links is a few microseconds).
    auto f = [k] { return "effectors[" + std::to_string(k) + "]"; };
    if (e.joint < 0 || e.joint >= s.jointCount()) return Error{f() + ".joint: no joint " + std::to_string(e.joint)};
    if (!isFinite(e.localOffset)) return checkFinite(f() + ".localOffset", e.localOffset);
    if (!isFinite(e.targetPosition)) return checkFinite(f() + ".targetPosition", e.targetPosition);
    if (!(isFinite(e.weight) && e.weight > 0.0)) return checkPositive(f() + ".weight", e.weight);
    const Quat& q = e.targetOrientation;
    // isFinite first: an ordered comparison with NaN would raise the invalid-operation trap.
    const bool unit = isFinite(q.w) && isFinite(Vec3(q.x, q.y, q.z)) && std::abs(glm::dot(q, q) - 1.0) < 1e-6;
    if (e.kind == EffectorKind::PositionOrientation && !unit)
      return Error{f() + ".targetOrientation: must be a unit quaternion"};
  }
  return validate(o);
}

// The restart poses' generator: SplitMix64 (Steele, Lea & Flood 2014), fully specified, so that the
// restarts are the same on every platform and library (std::uniform_real_distribution is not).
class RestartRng {
 public:
  explicit RestartRng(unsigned long long seed) : state_(seed) {}
  Real uniform() {  // [0, 1)
    unsigned long long z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<Real>(z >> 11) * 0x1.0p-53;
  }

 private:
  unsigned long long state_;
};

// A random pose inside the limits for the joints on a path to an effector (the others keep theirs):
// scalar DOFs uniform in [lo, hi], free joints a uniform axis and an angle in [0, maxRotation].
void randomizeActiveJoints(detail::Context& c, RestartRng& rng) {
  const Skeleton& s = c.skeleton;
  for (int i = 0; i < s.dofCount(); ++i)
    if (c.active[static_cast<size_t>(s.dofJoint(i))])
      c.pose.dofs[static_cast<size_t>(i)] = s.dofLo(i) + (s.dofHi(i) - s.dofLo(i)) * rng.uniform();
  for (int j = 0; j < s.jointCount(); ++j) {
    const Joint& joint = s.joint(j);
    if (c.active[static_cast<size_t>(j)] && joint.type == JointType::Free) {
      const Real z = 2.0 * rng.uniform() - 1.0, phi = 2.0 * kPi * rng.uniform();
      const Real rxy = std::sqrt(std::max(0.0, 1.0 - z * z));
      c.pose.rotations[static_cast<size_t>(j)] =
          glm::angleAxis(joint.maxRotation * rng.uniform(), Vec3(rxy * std::cos(phi), rxy * std::sin(phi), z));
    }
  }
}

std::unique_ptr<detail::Method> makeMethod(const detail::Context& c, std::string* why) {
  switch (c.options.solver) {
    case SolverKind::Analytic:
      return detail::makeAnalytic(c, why);
    case SolverKind::Ccd:
      return detail::makeCcd();
    case SolverKind::Fabrik:
      return detail::makeFabrik();
    case SolverKind::GradientDescent:
    case SolverKind::Lbfgs:
      return detail::makeDescentMethod(c.options.solver);
    default:
      return detail::makeJacobianMethod(c.options.solver);
  }
}

}  // namespace

namespace detail {
// The contents of a SolveWorkspace.
struct SolveStorage {
  ContextStorage context;
  std::unique_ptr<Method> method;
  SolverKind methodKind = SolverKind::Analytic;  // of `method`
  std::vector<Vec3> points;                      // effector points of a method that defers the pose
  std::vector<Real> progress;                    // combined residual per iteration (stall detection)
};
}  // namespace detail

SolveWorkspace::SolveWorkspace() : storage_(std::make_unique<detail::SolveStorage>()) {}
SolveWorkspace::~SolveWorkspace() = default;
SolveWorkspace::SolveWorkspace(const SolveWorkspace&) : SolveWorkspace() {}
SolveWorkspace& SolveWorkspace::operator=(const SolveWorkspace&) { return *this; }  // scratch, not state
SolveWorkspace::SolveWorkspace(SolveWorkspace&&) noexcept = default;
SolveWorkspace& SolveWorkspace::operator=(SolveWorkspace&&) noexcept = default;
detail::SolveStorage& SolveWorkspace::storage() {
  if (!storage_) storage_ = std::make_unique<detail::SolveStorage>();
  return *storage_;
}

namespace {

using Clock = std::chrono::steady_clock;

// Sets w.method to a method for c's options: the last one, returned to a fresh one's state, when it
// is of that kind and can be (Method::resetForReuse); else a new one (null, with *why, when the
// method does not apply).
void prepareMethod(detail::SolveStorage& w, const detail::Context& c, std::string* why) {
  if (w.method && w.methodKind == c.options.solver && w.method->resetForReuse()) return;
  w.method = makeMethod(c, why);
  w.methodKind = c.options.solver;
}

// ---- Setup: the caches a solve reads, filled once per solve ----

// Per joint, the effectors below it (c.belowStart, c.belowList) and whether any is (c.active).
void listEffectorsBelowJoints(detail::Context& c) {
  const Skeleton& skeleton = c.skeleton;
  const std::vector<Effector>& effectors = c.effectors;
  const auto J = static_cast<size_t>(skeleton.jointCount());
  detail::bucketLists(
      J,
      [&](auto visit) {
        for (size_t k = 0; k < effectors.size(); ++k)
          for (int j = effectors[k].joint; j >= 0; j = skeleton.joint(j).parent)
            visit(static_cast<size_t>(j), static_cast<int>(k));
      },
      c.belowStart, c.belowList);
  c.active.assign(J, 0);
  for (size_t j = 0; j < J; ++j) c.active[j] = c.belowStart[j + 1] > c.belowStart[j];
}

// One ball joint's limit caches (see ContextStorage::insideCosHalf and eulerRanges).
void cacheBallLimits(const Joint& joint, Real& insideCosHalf, std::array<detail::Context::EulerRange, 3>& ranges) {
  Real L = 0.5 * kPi;
  for (int k = 0; k < 3; ++k) L = std::min({L, -joint.lo[k], joint.hi[k]});
  if (L > 0.0) insideCosHalf = std::cos(0.5 * L) + 1e-12;
  for (int k = 0; k < 3; ++k) {
    const Real bound = k == 1 ? 0.5 * kPi : kPi;  // principal angles: b in [−π/2, π/2], a and c in (−π, π]
    detail::Context::EulerRange& r = ranges[static_cast<size_t>(k)];
    if (joint.lo[k] <= -bound && joint.hi[k] >= bound) {
      r.cosHalf = -2.0;
    } else if (joint.lo[k] >= -kPi && joint.hi[k] <= kPi) {
      const Real mid = 0.5 * (joint.lo[k] + joint.hi[k]), half = 0.5 * (joint.hi[k] - joint.lo[k]);
      r = {std::cos(mid), std::sin(mid), std::cos(half)};
    }  // else a range across ±π: no test (cosHalf 2)
  }
}

// Every ball joint's limit caches; a joint with the same limits as the ball joint before it (chains
// repeat them) copies that one's.
void cacheLimits(detail::Context& c) {
  const Skeleton& skeleton = c.skeleton;
  const auto J = static_cast<size_t>(skeleton.jointCount());
  c.insideCosHalf.assign(J, 2.0);
  c.eulerRanges.assign(J, {});
  const Joint* previous = nullptr;  // the last ball joint
  for (size_t j = 0; j < J; ++j) {
    const Joint& joint = skeleton.joint(static_cast<int>(j));
    if (joint.type != JointType::Ball) continue;
    if (previous && std::equal(joint.lo, joint.lo + 3, previous->lo) &&
        std::equal(joint.hi, joint.hi + 3, previous->hi)) {
      const auto p = static_cast<size_t>(previous - &skeleton.joint(0));
      c.insideCosHalf[j] = c.insideCosHalf[p];
      c.eulerRanges[j] = c.eulerRanges[p];
    } else {
      cacheBallLimits(joint, c.insideCosHalf[j], c.eulerRanges[j]);
    }
    previous = &joint;
  }
}

void setUp(detail::Context& c) {
  c.refresh();
  c.meanBone = meanBoneLength(c.skeleton, c.effectors);
  c.orientationScale = c.options.orientationScale > 0.0 ? c.options.orientationScale : c.meanBone;
  c.maxErrorStep = c.options.maxErrorStep > 0.0 ? c.options.maxErrorStep : c.meanBone;
  listEffectorsBelowJoints(c);
  cacheLimits(c);
}

// Reachability (Aristidou & Lasenby 2011, Algorithm 1, first test): a goal farther from the root than
// the sum of the bones on its path cannot be reached.
bool anyGoalOutOfReach(const detail::Context& c) {
  const Skeleton& skeleton = c.skeleton;
  bool unreachable = false;
  for (const Effector& e : c.effectors) {
    int root = e.joint;
    while (skeleton.joint(root).parent >= 0) root = skeleton.joint(root).parent;
    if (glm::length(e.targetPosition - c.frames[static_cast<size_t>(root)].position) > reach(skeleton, root, e) + 1e-12)
      unreachable = true;
  }
  return unreachable;
}

// ---- The iteration, its stopping rules and the stall and restart policy ----

// One solve after setUp(): iterates the method until a stopping rule holds (IK slides, "Stopping"),
// restarting it from a random pose when it stalls short of a reachable goal.
class SolveLoop {
 public:
  SolveLoop(detail::Context& c, detail::SolveStorage& w, Clock::time_point start)
      : c_(c), w_(w), o_(c.options), start_(start), rng_(c.options.restartSeed) {}

  SolveResult run();

 private:
  Real elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  bool overTime() const { return o_.maxSeconds > 0.0 && elapsed() > o_.maxSeconds; }
  bool converged() const { return residual_.position <= o_.tolerance && residual_.orientation <= o_.angleTolerance; }
  Real pastScore() const {  // the score stallIterations ago (needs more entries than that)
    return w_.progress[w_.progress.size() - 1 - static_cast<size_t>(o_.stallIterations)];
  }
  bool enoughHistory() const {
    return o_.stallIterations > 0 && static_cast<int>(w_.progress.size()) > o_.stallIterations;
  }
  bool stalled() const;
  bool crawling(int it) const;
  bool mayRestart(int it) const;
  void restart();
  void iterate(int it);
  void measure();
  void record();
  void startAttempt();
  void keepBest();
  SolveResult stop(SolveStatus status);
  SolveResult finish(SolveStatus status);

  detail::Context& c_;
  detail::SolveStorage& w_;
  const SolveOptions& o_;
  Clock::time_point start_;
  SolveResult result_;
  bool unreachable_ = false;
  Residual residual_;  // of the current pose
  Real score_ = 0.0;   // residual_.position + orientationScale · residual_.orientation
  // Stall recovery: the best attempt so far (its pose and score) and the restart poses' generator.
  Pose best_;
  Real bestScore_ = std::numeric_limits<Real>::infinity();
  RestartRng rng_;
};

SolveResult SolveLoop::run() {
  std::string why;
  prepareMethod(w_, c_, &why);
  if (!w_.method) {
    result_.message = why;
    return finish(SolveStatus::NotApplicable);
  }
  if (o_.recordHistory) result_.effectorPath.assign(c_.effectors.size(), {});
  w_.points.clear();
  // A lone position effector is stretched toward an unreachable goal, and the method refines from
  // there (the gradient vanishes at the exact stretched pose, so the methods keep it).
  unreachable_ = anyGoalOutOfReach(c_);
  if (unreachable_ && c_.effectors.size() == 1 && c_.effectors[0].kind == EffectorKind::Position) {
    detail::stretchToward(c_, c_.effectors[0]);
    c_.flushPose();
  }
  w_.progress.reserve(16);
  startAttempt();
  for (int it = 0;; ++it) {
    if (converged()) return finish(SolveStatus::Success);
    // A closed-form method that did not succeed has found the nearest reachable pose: the goal is
    // out of its workspace (too far, too near, or outside the limits).
    if (w_.method->finished()) return finish(SolveStatus::Unreachable);
    const bool stuck = stalled();
    if ((stuck || crawling(it)) && mayRestart(it)) {  // crawling: asked only when not stalled
      restart();
      continue;
    }
    if (stuck) return stop(unreachable_ ? SolveStatus::Unreachable : SolveStatus::Stalled);
    if (it >= o_.maxIterations) return stop(unreachable_ ? SolveStatus::Unreachable : SolveStatus::IterationCap);
    if (overTime()) return stop(SolveStatus::TimeCap);
    iterate(it);
  }
}

// Less than the stall ratio of progress over the last stallIterations iterations.
bool SolveLoop::stalled() const { return enoughHistory() && !(score_ < (1.0 - o_.stallRatio) * pastScore()); }

// Short of a stall, crawling counts as stuck when a restart is left: less than 10 % progress over the
// last k iterations, a rate at which the tolerance would take more than twice the iterations that
// remain (CCD along a limit can gain 1 % per pass for hundreds of passes). Methods that speed up near
// the goal (DLS: linear while the error clamp acts, then quadratic) are never this slow.
bool SolveLoop::crawling(int it) const {
  if (!enoughHistory() || result_.restarts >= o_.restarts) return false;
  const Real rate = score_ / pastScore();
  const Real goal = o_.tolerance + c_.orientationScale * o_.angleTolerance;
  if (!(score_ > goal && rate > 0.9 && rate < 1.0)) return false;
  return Real(o_.stallIterations) * std::log(goal / score_) / std::log(rate) > 2.0 * Real(o_.maxIterations - it);
}

// A restart needs a reachable goal, a restart left, and iterations to get anywhere: at least 2k must
// remain (an interactive solve with a cap of 30 keeps refining its warm start instead of jumping to a
// random pose it cannot finish).
bool SolveLoop::mayRestart(int it) const {
  return !unreachable_ && result_.restarts < o_.restarts &&
         o_.maxIterations - it >= 2 * std::max(o_.stallIterations, 1) && !overTime();
}

// A local minimum short of a reachable goal: keep this attempt if it is the best, then start again
// from a random pose of the joints that move the effectors, with a fresh method.
void SolveLoop::restart() {
  w_.method->finish(c_);
  c_.flushPose();
  keepBest();
  randomizeActiveJoints(c_, rng_);
  c_.refresh();
  std::string why;
  prepareMethod(w_, c_, &why);
  ++result_.restarts;
  startAttempt();
}

void SolveLoop::iterate(int it) {
  w_.method->iterate(c_);
  switch (w_.method->framesAfterIterate()) {
    case detail::Method::FramesAfterIterate::Refresh:
      c_.refresh();
      break;
    case detail::Method::FramesAfterIterate::FromCache:
      c_.refreshFrames();
      break;
    case detail::Method::FramesAfterIterate::Current:
      break;
  }
  result_.iterations = it + 1;
  measure();
  record();
  w_.progress.push_back(score_);
}

// The residual and score of the current pose (a method that defers the pose gives its effector points).
void SolveLoop::measure() {
  const std::vector<Effector>& effectors = c_.effectors;
  Residual r;
  if (w_.method->posesDeferred()) {  // position effectors only (FABRIK's condition for deferring)
    w_.method->effectorPoints(c_, w_.points);
    for (size_t k = 0; k < effectors.size(); ++k)
      r.position = std::max(r.position, glm::length(effectors[k].targetPosition - w_.points[k]));
  } else {
    r = residual(effectors, c_.frames);
  }
  residual_ = r;
  score_ = r.position + c_.orientationScale * r.orientation;
}

// History (SolveOptions::recordHistory): the residual and every effector's position.
void SolveLoop::record() {
  if (!o_.recordHistory) return;
  result_.residualHistory.push_back(residual_.position);
  const bool deferred = w_.method->posesDeferred();
  for (size_t k = 0; k < c_.effectors.size(); ++k)
    result_.effectorPath[k].push_back(deferred ? w_.points[k] : effectorPosition(c_.effectors[k], c_.frames));
}

// The first measurement of an attempt, and a fresh progress history for the stall rules.
void SolveLoop::startAttempt() {
  w_.progress.clear();
  measure();
  record();
  w_.progress.push_back(score_);
}

// After method->finish(): the pose and frames of the attempt are current.
void SolveLoop::keepBest() {
  const Residual now = residual(c_.effectors, c_.frames);
  const Real s = now.position + c_.orientationScale * now.orientation;
  if (s < bestScore_) bestScore_ = s, best_ = c_.pose;
}

// An unsuccessful end: after restarts, the best attempt's pose.
SolveResult SolveLoop::stop(SolveStatus status) {
  if (result_.restarts > 0) {
    w_.method->finish(c_);
    c_.flushPose();
    const Pose last = c_.pose;
    keepBest();
    if (!(best_.dofs == last.dofs && best_.rotations == last.rotations)) {
      c_.pose = best_;
      c_.refresh();
    }
  }
  return finish(status);
}

SolveResult SolveLoop::finish(SolveStatus status) {
  if (w_.method) w_.method->finish(c_);
  c_.flushPose();
  const Residual r = residual(c_.effectors, c_.frames);
  result_.status = status;
  result_.positionResidual = r.position;
  result_.orientationResidual = r.orientation;
  result_.seconds = elapsed();
  return result_;
}

}  // namespace

Real meanBoneLength(const Skeleton& skeleton, const std::vector<Effector>& effectors) {
  Real bones = 0.0;
  int count = 0;
  for (int j = 0; j < skeleton.jointCount(); ++j)
    if (skeleton.joint(j).parent >= 0) bones += glm::length(skeleton.joint(j).offset), ++count;
  for (const Effector& e : effectors) bones += glm::length(e.localOffset), ++count;
  return std::max(1e-6, count > 0 ? bones / count : 1.0);
}

Real resolvedOrientationScale(const Skeleton& skeleton, const std::vector<Effector>& effectors, const SolveOptions& o) {
  return o.orientationScale > 0.0 ? o.orientationScale : meanBoneLength(skeleton, effectors);
}

SolveResult solve(const Skeleton& skeleton, Pose& pose, const std::vector<Effector>& effectors, const SolveOptions& o,
                  SolveWorkspace& workspace) {
  const auto start = Clock::now();
  if (Status st = validateInputs(skeleton, pose, effectors, o); !st) {
    SolveResult result;
    result.message = st.error();
    return result;
  }
  if (o.fromRest) pose = skeleton.restPose();
  detail::SolveStorage& w = workspace.storage();
  w.context.clear();
  detail::Context c{std::move(w.context), skeleton, pose, effectors, o};  // lent, taken back below
  setUp(c);
  SolveResult result = SolveLoop(c, w, start).run();
  w.context = std::move(static_cast<detail::ContextStorage&>(c));
  // A method that cannot serve the next solve is not kept: its storage (a Jacobian's matrices) would
  // stay allocated for nothing.
  if (w.method && !w.method->resetForReuse()) w.method.reset();
  return result;
}

SolveResult solve(const Skeleton& skeleton, Pose& pose, const std::vector<Effector>& effectors,
                  const SolveOptions& options) {
  SolveWorkspace workspace;
  return solve(skeleton, pose, effectors, options, workspace);
}

}  // namespace pba::ik
