// The IK driver: validation, repeatability, the reachability check, the iteration loop and the
// stopping rules (IK slides, "Stopping"), around the methods of ccd.cpp, fabrik.cpp,
// jacobian_solvers.cpp and analytic.cpp.
#include "physics/ik/solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <tuple>

#include "physics/core/validate.h"
#include "physics/ik/exercises.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik {

const char* statusName(SolveStatus s) {
  switch (s) {
    case SolveStatus::Success:
      return "success";
    case SolveStatus::Unreachable:
      return "unreachable";
    case SolveStatus::Stalled:
      return "stalled";
    case SolveStatus::IterationCap:
      return "iteration_cap";
    case SolveStatus::TimeCap:
      return "time_cap";
    case SolveStatus::NotApplicable:
      return "not_applicable";
    case SolveStatus::InvalidInput:
      return "invalid_input";
  }
  return "?";
}

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

// What solve() keeps between the solves of a thread, so that a warm solve allocates nothing: the
// Context's storage, the last method (reused for the same kind, Method::resetForReuse) and the
// driver's lists. thread_local: solve() may run on several threads at once. A solve takes it out and
// puts it back at the end, so that a solve inside a solve would find it empty and use its own.
struct Workspace {
  detail::ContextStorage storage;
  std::unique_ptr<detail::Method> method;
  SolverKind methodKind = SolverKind::Analytic;  // of `method`
  std::vector<Vec3> points;                      // effector points of a method that defers the pose
  std::vector<Real> progress;                    // combined residual per iteration (stall detection)
};
thread_local Workspace threadWorkspace;
// Solves of larger skeletons keep nothing: their allocations are a small part of their cost, and a
// thread would otherwise hold the storage of the largest skeleton it ever solved.
constexpr int kKeptJoints = 64;

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

// Sets w.method to a method for c's options: the last one, returned to a fresh one's state, when it
// is of that kind and can be (Method::resetForReuse); else a new one (null, with *why, when the
// method does not apply).
void prepareMethod(Workspace& w, const detail::Context& c, std::string* why) {
  if (w.method && w.methodKind == c.options.solver && w.method->resetForReuse()) return;
  w.method = makeMethod(c, why);
  w.methodKind = c.options.solver;
}

using Clock = std::chrono::steady_clock;
SolveResult solveIn(detail::Context& c, Workspace& w, Clock::time_point start);

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

SolveResult solve(const Skeleton& skeleton, Pose& pose, const std::vector<Effector>& effectors, const SolveOptions& o) {
  const auto start = Clock::now();
  if (Status st = validateInputs(skeleton, pose, effectors, o); !st) {
    SolveResult result;
    result.message = st.error();
    return result;
  }
  if (o.fromRest) pose = skeleton.restPose();
  Workspace w = std::move(threadWorkspace);  // taken out, put back below (see Workspace)
  w.storage.clear();
  detail::Context c{std::move(w.storage), skeleton, pose, effectors, o};
  SolveResult result = solveIn(c, w, start);
  w.storage = std::move(static_cast<detail::ContextStorage&>(c));
  // A method that cannot serve the next solve is not kept: its storage (a Jacobian's matrices) would
  // stay allocated for nothing.
  if (w.method && !w.method->resetForReuse()) w.method.reset();
  if (skeleton.jointCount() <= kKeptJoints) threadWorkspace = std::move(w);
  return result;
}

namespace {

// solve() on its Context, with the storage of the workspace w.
SolveResult solveIn(detail::Context& c, Workspace& w, Clock::time_point start) {
  const Skeleton& skeleton = c.skeleton;
  Pose& pose = c.pose;
  const std::vector<Effector>& effectors = c.effectors;
  const SolveOptions& o = c.options;
  SolveResult result;
  c.refresh();
  c.meanBone = meanBoneLength(skeleton, effectors);
  c.orientationScale = o.orientationScale > 0.0 ? o.orientationScale : c.meanBone;
  c.maxErrorStep = o.maxErrorStep > 0.0 ? o.maxErrorStep : c.meanBone;
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
  c.insideCosHalf.assign(J, 2.0);
  c.eulerRanges.assign(J, {});
  const Joint* previous = nullptr;  // the last ball joint: chains repeat the same limits
  for (size_t j = 0; j < J; ++j) {
    const Joint& joint = skeleton.joint(static_cast<int>(j));
    if (joint.type != JointType::Ball) continue;
    if (previous && std::equal(joint.lo, joint.lo + 3, previous->lo) &&
        std::equal(joint.hi, joint.hi + 3, previous->hi)) {
      const auto p = static_cast<size_t>(previous - &skeleton.joint(0));
      c.insideCosHalf[j] = c.insideCosHalf[p];
      c.eulerRanges[j] = c.eulerRanges[p];
      previous = &joint;
      continue;
    }
    previous = &joint;
    Real L = 0.5 * kPi;
    for (int k = 0; k < 3; ++k) L = std::min({L, -joint.lo[k], joint.hi[k]});
    if (L > 0.0) c.insideCosHalf[j] = std::cos(0.5 * L) + 1e-12;
    for (int k = 0; k < 3; ++k) {
      const Real bound = k == 1 ? 0.5 * kPi : kPi;  // principal angles: b in [−π/2, π/2], a and c in (−π, π]
      detail::Context::EulerRange& r = c.eulerRanges[j][static_cast<size_t>(k)];
      if (joint.lo[k] <= -bound && joint.hi[k] >= bound) {
        r.cosHalf = -2.0;
      } else if (joint.lo[k] >= -kPi && joint.hi[k] <= kPi) {
        const Real mid = 0.5 * (joint.lo[k] + joint.hi[k]), half = 0.5 * (joint.hi[k] - joint.lo[k]);
        r = {std::cos(mid), std::sin(mid), std::cos(half)};
      }  // else a range across ±π: no test (cosHalf 2)
    }
  }

  std::string why;
  prepareMethod(w, c, &why);
  const std::unique_ptr<detail::Method>& method = w.method;
  auto finish = [&](SolveStatus status) {
    if (method) method->finish(c);
    c.flushPose();
    const Residual r = residual(effectors, c.frames);
    result.status = status;
    result.positionResidual = r.position;
    result.orientationResidual = r.orientation;
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
  };
  if (!method) {
    result.message = why;
    return finish(SolveStatus::NotApplicable);
  }
  if (o.recordHistory) result.effectorPath.assign(effectors.size(), {});
  std::vector<Vec3>& points = w.points;
  points.clear();
  auto effectorPoint = [&](size_t k) {
    return method->posesDeferred() ? points[k] : effectorPosition(effectors[k], c.frames);
  };
  auto record = [&](Real positionResidual) {
    if (!o.recordHistory) return;
    result.residualHistory.push_back(positionResidual);
    for (size_t k = 0; k < effectors.size(); ++k) result.effectorPath[k].push_back(effectorPoint(k));
  };

  // Reachability (Aristidou & Lasenby 2011, Algorithm 1, first test): a goal farther from the root
  // than the sum of the bones on its path cannot be reached. A lone position effector is then
  // stretched toward it, and the method refines from there (the gradient vanishes at the exact
  // stretched pose, so the methods keep it).
  bool unreachable = false;
  for (const Effector& e : effectors) {
    int root = e.joint;
    while (skeleton.joint(root).parent >= 0) root = skeleton.joint(root).parent;
    if (glm::length(e.targetPosition - c.frames[static_cast<size_t>(root)].position) > reach(skeleton, root, e) + 1e-12)
      unreachable = true;
  }
  if (unreachable && effectors.size() == 1 && effectors[0].kind == EffectorKind::Position) {
    detail::stretchToward(c, effectors[0]);
    c.flushPose();
  }

  std::vector<Real>& progress = w.progress;
  progress.clear();
  progress.reserve(16);
  auto measure = [&]() {
    Residual r;
    if (method->posesDeferred()) {  // position effectors only (FABRIK's condition for deferring)
      method->effectorPoints(c, points);
      for (size_t k = 0; k < effectors.size(); ++k)
        r.position = std::max(r.position, glm::length(effectors[k].targetPosition - points[k]));
    } else {
      r = residual(effectors, c.frames);
    }
    return std::pair<Residual, Real>{r, r.position + c.orientationScale * r.orientation};
  };
  auto [r, score] = measure();
  record(r.position);
  progress.push_back(score);
  // Stall recovery: the best attempt so far (its pose and score) and the restart poses' generator.
  Pose best;
  Real bestScore = std::numeric_limits<Real>::infinity();
  RestartRng rng(o.restartSeed);
  auto keepBest = [&]() {  // after method->finish(): the pose and frames of the attempt are current
    const Residual now = residual(effectors, c.frames);
    const Real s = now.position + c.orientationScale * now.orientation;
    if (s < bestScore) bestScore = s, best = pose;
  };
  auto stop = [&](SolveStatus status) {
    if (result.restarts > 0) {
      method->finish(c);
      c.flushPose();
      const Pose last = pose;
      keepBest();
      if (!(best.dofs == last.dofs && best.rotations == last.rotations)) {
        pose = best;
        c.refresh();
      }
    }
    return finish(status);
  };
  for (int it = 0;; ++it) {
    if (r.position <= o.tolerance && r.orientation <= o.angleTolerance) return finish(SolveStatus::Success);
    // A closed-form method that did not succeed has found the nearest reachable pose: the goal is
    // out of its workspace (too far, too near, or outside the limits).
    if (method->finished()) return finish(SolveStatus::Unreachable);
    const int k = o.stallIterations;
    const bool stalled = k > 0 && static_cast<int>(progress.size()) > k &&
                         !(score < (1.0 - o.stallRatio) * progress[progress.size() - 1 - static_cast<size_t>(k)]);
    // Crawling counts as stuck when a restart is left: less than 10 % progress over the last k
    // iterations, a rate at which the tolerance would take more than twice the iterations that
    // remain (CCD along a limit can gain 1 % per pass for hundreds of passes). Methods that speed up
    // near the goal (DLS: linear while the error clamp acts, then quadratic) are never this slow.
    bool slow = false;
    if (!stalled && k > 0 && static_cast<int>(progress.size()) > k && result.restarts < o.restarts) {
      const Real rate = score / progress[progress.size() - 1 - static_cast<size_t>(k)];
      const Real goal = o.tolerance + c.orientationScale * o.angleTolerance;
      if (score > goal && rate > 0.9 && rate < 1.0)
        slow = Real(k) * std::log(goal / score) / std::log(rate) > 2.0 * Real(o.maxIterations - it);
    }
    // A restart needs iterations to get anywhere: at least 2k must remain (an interactive solve with
    // a cap of 30 keeps refining its warm start instead of jumping to a random pose it cannot finish).
    if ((stalled || slow) && !unreachable && result.restarts < o.restarts &&
        o.maxIterations - it >= 2 * std::max(k, 1) &&
        !(o.maxSeconds > 0.0 && std::chrono::duration<double>(Clock::now() - start).count() > o.maxSeconds)) {
      // A local minimum short of a reachable goal: keep this attempt if it is the best, then start
      // again from a random pose of the joints that move the effectors, with a fresh method.
      method->finish(c);
      c.flushPose();
      keepBest();
      randomizeActiveJoints(c, rng);
      c.refresh();
      prepareMethod(w, c, &why);
      ++result.restarts;
      progress.clear();
      std::tie(r, score) = measure();
      record(r.position);
      progress.push_back(score);
      continue;
    }
    if (stalled) return stop(unreachable ? SolveStatus::Unreachable : SolveStatus::Stalled);
    if (it >= o.maxIterations) return stop(unreachable ? SolveStatus::Unreachable : SolveStatus::IterationCap);
    if (o.maxSeconds > 0.0 && std::chrono::duration<double>(Clock::now() - start).count() > o.maxSeconds)
      return stop(SolveStatus::TimeCap);
    method->iterate(c);
    switch (method->framesAfterIterate()) {
      case detail::Method::FramesAfterIterate::Refresh:
        c.refresh();
        break;
      case detail::Method::FramesAfterIterate::FromCache:
        c.refreshFrames();
        break;
      case detail::Method::FramesAfterIterate::Current:
        break;
    }
    result.iterations = it + 1;
    std::tie(r, score) = measure();
    record(r.position);
    progress.push_back(score);
  }
}

}  // namespace

}  // namespace pba::ik
