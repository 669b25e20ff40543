// Gradient descent and L-BFGS on the IK least-squares objective (CMU asst4, "Gradient IK", and the
// extensions it asks for: line searches, quasi-Newton, joint limits by projected gradient).
//
// Objective (least_squares.h): f(θ) = ½ Σₖ wₖ² |gₖ − eₖ(θ)|² (+ orientation rows) [m²].
// Gradient by the chain rule: ∂f/∂θⱼ = −Σₖ rₖ · ∂eₖ/∂θⱼ, i.e. ∇f = −Jᵀ r with the Jacobian columns
// aⱼ × (e − pⱼ) of IK-3. For a planar hinge this is asst4's ⟨q − p, R(π/2)(p − pⱼ)⟩ up to its sign
// convention, since R(π/2) v = ẑ × v. Joints that do not move an effector have zero columns, as asst4
// requires. (asst4 also zeroes the root's gradient to keep its character upright; our skeletons fix
// the root's position, and a DOF weight can hold its rotation back.)
// In the scaled variables y (θ = θ₀ + W y, W the DOF weights) the gradient is g = −J̃ᵀ r.
//
// gradient  Δy = −α g, the step length α by SolveOptions::lineSearch:
//   fixed          α = gradientStep: asst4's method (a small constant, several steps per frame). Stable
//                  only below 2/λ_max(J̃ᵀJ̃); above it f oscillates or grows, which the lab shows.
//   backtracking   α₀ = |g|² / |J̃ g|², the minimiser of the linearised model along −g, halved until
//                  f(θ + α d) ≤ f(θ) + c₁ α ∇f·d with c₁ = 10⁻⁴ (Armijo's sufficient decrease; the
//                  one backtrack() of least_squares.h, shared with the Jacobian methods' option).
//   golden         golden-section search for the minimum of φ(α) = f(θ + α d) on [0, α_max], α_max the
//                  step that turns some DOF by lineSearchMaxStep: an exact line search (kGoldenIterations
//                  evaluations of FK), falling back to backtracking if it finds no decrease.
// lbfgs     d = −H g, H the limited-memory BFGS estimate of the inverse Hessian from the last m pairs
//           s = Δy, y = Δg (two-loop recursion, Nocedal & Wright 2006, Algorithm 7.4, with
//           H₀ = (sᵀy / yᵀy) I), then Armijo backtracking from α = 1 (the first step, with no memory
//           yet, starts from the gradient's α₀). A pair with sᵀy ≤ ε |s| |y| is skipped so H stays
//           positive definite; a direction that is not a descent direction resets the memory.
// Joint limits (projected gradient, asst4 extension): every trial pose is projected onto the box of
// the limits, and a DOF at a bound whose descent direction points outward is frozen for the step (its
// gradient entry zeroed, Bertsekas' projected gradient). L-BFGS restarts its memory whenever that set
// of frozen DOFs changes, and on every step when the skeleton has free joints (their columns turn
// about an axis chosen anew each step, so pairs from different steps describe different variables).
#include <cmath>
#include <deque>
#include <memory>

#include "physics/ik/least_squares.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik::detail {
namespace {

constexpr int kGoldenIterations = 30;            // the bracket shrinks by 0.618³⁰ ≈ 5·10⁻⁷
constexpr Real kInvGolden = 0.6180339887498949;  // (√5 − 1) / 2
constexpr Real kCurvatureEpsilon = 1e-10;        // relative sᵀy below which a pair is skipped

struct Pair {
  std::vector<Real> s, y;
  Real rho;  // 1 / (yᵀs)
};

class DescentMethod final : public Method {
 public:
  explicit DescentMethod(SolverKind kind) : kind_(kind) {}
  /// Every step leaves c.frames current: the accepted trial's frames (acceptTrial) or the start's.
  FramesAfterIterate framesAfterIterate() const override { return FramesAfterIterate::Current; }

  void iterate(Context& c) override {
    leastSquaresSystem(c, sys_);  // reuses the buffers of the previous step
    const LeastSquaresSystem& sys = sys_;
    const size_t n = sys.dofWeights.size();
    const bool free = !sys.layout.freeJoints.empty();
    std::vector<Real>& g = g_;  // (members: storage kept across steps)
    multiplyTransposed(sys.J, sys.residual, g);
    for (Real& x : g) x = -x;
    frozenDofs(c, g, frozen_);
    const std::vector<char>& frozen = frozen_;
    for (size_t i = 0; i < n; ++i)
      if (frozen[i]) g[i] = 0.0;
    const bool lbfgs = kind_ == SolverKind::Lbfgs;
    if (lbfgs) remember(c, sys, g, frozen);
    if (maxAbs(g) == 0.0) return;  // stationary point, or every DOF blocked: the driver sees a stall

    std::vector<Real>& d = d_;
    if (lbfgs) {
      lbfgsDirection(g, d);
    } else {
      d.assign(g.begin(), g.end());
      for (Real& x : d) x = -x;
    }
    for (size_t i = 0; i < n; ++i)
      if (frozen[i]) d[i] = 0.0;
    Real slope = dot(g, d);  // ∇f · d < 0 for a descent direction
    if (!(slope < 0.0)) {
      memory_.clear();
      d.assign(g.begin(), g.end());
      for (Real& x : d) x = -x;
      slope = dot(g, d);
    }

    assignPose(start_, c.pose, free);
    const Real f0 = objective(c, c.frames);
    std::vector<Real>& wd = wd_;
    wd.resize(n);
    for (size_t i = 0; i < n; ++i) wd[i] = sys.dofWeights[i] * d[i];
    const Real alphaMax = c.options.lineSearchMaxStep / maxAbs(wd);
    auto f = [&](Real alpha) {
      for (size_t i = 0; i < n; ++i) delta_[i] = alpha * wd[i];
      return trialObjective(c, start_, c.frames, sys.layout, delta_, scratch_);
    };
    delta_.resize(n);
    // L-BFGS with a memory starts its search at α = 1; α₀ (a product J d) serves the other cases.
    const bool unitStep = lbfgs && !memory_.empty();
    const Real alpha0 = unitStep ? 1.0 : std::min(alphaMax, modelMinimiser(sys.J, d, slope));

    bool accepted = false;
    if (!lbfgs && c.options.lineSearch == LineSearch::Fixed) {
      f(std::min(c.options.gradientStep, alphaMax));  // asst4: no test, the step is taken
      accepted = true;
    } else if (!lbfgs && c.options.lineSearch == LineSearch::GoldenSection) {
      accepted = golden(f, f0, alphaMax);
    }
    if (!accepted) accepted = backtrack(f, f0, unitStep ? std::min<Real>(1.0, alphaMax) : alpha0, slope);
    if (!accepted) {
      assignPose(c.pose, start_, free);  // no decrease found: the driver reports a stall (frames: start_'s)
      memory_.clear();
      havePrevious_ = false;
      return;
    }
    acceptTrial(c, scratch_);  // the last trial evaluated is the pose accepted: its frames are current
    if (lbfgs) {
      // s in the scaled variables, from the pose actually reached (after the projection).
      s_.assign(n, 0.0);
      for (int i = 0; i < c.skeleton.dofCount(); ++i) {
        const auto k = static_cast<size_t>(i);
        s_[k] = (c.pose.dofs[k] - start_.dofs[k]) / sys.dofWeights[k];
      }
      for (size_t i = static_cast<size_t>(c.skeleton.dofCount()); i < n; ++i) s_[i] = delta_[i] / sys.dofWeights[i];
      previousGradient_.swap(g_);  // g_ and frozen_ are recomputed from scratch next step
      previousFrozen_.swap(frozen_);
      previousHadFree_ = !sys.layout.freeJoints.empty();
      havePrevious_ = true;
    }
  }

 private:
  // DOFs at a limit whose descent direction (−g) points out of the box.
  void frozenDofs(const Context& c, const std::vector<Real>& g, std::vector<char>& frozen) {
    frozen.assign(g.size(), 0);
    if (!c.options.enforceLimits) return;
    if (lo_.size() != static_cast<size_t>(c.skeleton.dofCount())) {  // the limits, read once per solve
      lo_.resize(static_cast<size_t>(c.skeleton.dofCount()));
      hi_.resize(lo_.size());
      for (int i = 0; i < c.skeleton.dofCount(); ++i) {
        lo_[static_cast<size_t>(i)] = c.skeleton.dofLo(i);
        hi_[static_cast<size_t>(i)] = c.skeleton.dofHi(i);
      }
    }
    for (int i = 0; i < c.skeleton.dofCount(); ++i) {
      const auto k = static_cast<size_t>(i);
      const Real v = c.pose.dofs[k];
      frozen[k] = (v <= lo_[k] + 1e-12 && g[k] > 0.0) || (v >= hi_[k] - 1e-12 && g[k] < 0.0);
    }
  }

  // α minimising the linear model ½|r − α J̃ d|² along d: −∇f·d / |J̃ d|² (∇f·d = −rᵀJ̃ d).
  static Real modelMinimiser(const Matrix& J, const std::vector<Real>& d, Real slope) {
    const std::vector<Real> jd = multiply(J, d);
    const Real curvature = dot(jd, jd);
    return curvature > 0.0 ? -slope / curvature : 1.0;
  }

  // Golden-section search on [0, alphaMax]; leaves the pose at the best point found if it decreases f.
  template <typename F>
  static bool golden(F& f, Real f0, Real alphaMax) {
    Real a = 0.0, b = alphaMax;
    Real x1 = b - kInvGolden * (b - a), x2 = a + kInvGolden * (b - a);
    Real f1 = f(x1), f2 = f(x2);
    for (int it = 0; it < kGoldenIterations; ++it) {
      if (f1 <= f2) {
        b = x2, x2 = x1, f2 = f1;
        x1 = b - kInvGolden * (b - a);
        f1 = f(x1);
      } else {
        a = x1, x1 = x2, f1 = f2;
        x2 = a + kInvGolden * (b - a);
        f2 = f(x2);
      }
    }
    return f(0.5 * (a + b)) < f0;
  }

  // Adds the pair of the previous step (s, y = g − g_prev) to the memory, or restarts it.
  void remember(const Context& c, const LeastSquaresSystem& sys, const std::vector<Real>& g,
                const std::vector<char>& frozen) {
    if (!havePrevious_) return;
    havePrevious_ = false;
    if (frozen != previousFrozen_ || previousHadFree_ || !sys.layout.freeJoints.empty() || g.size() != s_.size()) {
      memory_.clear();
      return;
    }
    Pair p = std::move(spare_);  // the storage of the pair dropped last, if any
    p.s.assign(s_.begin(), s_.end());
    p.y.assign(g.begin(), g.end());
    p.rho = 0.0;
    for (size_t i = 0; i < g.size(); ++i) p.y[i] -= previousGradient_[i];
    const Real sy = dot(p.s, p.y);
    if (!(sy > kCurvatureEpsilon * std::sqrt(dot(p.s, p.s) * dot(p.y, p.y)))) return;
    p.rho = 1.0 / sy;
    memory_.push_back(std::move(p));
    while (static_cast<int>(memory_.size()) > c.options.lbfgsMemory) {
      spare_ = std::move(memory_.front());
      memory_.pop_front();
    }
  }

  // −H g by the two-loop recursion (Nocedal & Wright 2006, Algorithm 7.4).
  void lbfgsDirection(const std::vector<Real>& g, std::vector<Real>& q) {
    q.assign(g.begin(), g.end());
    std::vector<Real>& a = alphas_;
    a.resize(memory_.size());
    for (size_t k = memory_.size(); k-- > 0;) {
      a[k] = memory_[k].rho * dot(memory_[k].s, q);
      for (size_t i = 0; i < q.size(); ++i) q[i] -= a[k] * memory_[k].y[i];
    }
    if (!memory_.empty()) {
      const Pair& last = memory_.back();
      const Real gamma = dot(last.s, last.y) / dot(last.y, last.y);
      for (Real& x : q) x *= gamma;
    }
    for (size_t k = 0; k < memory_.size(); ++k) {
      const Real b = memory_[k].rho * dot(memory_[k].y, q);
      for (size_t i = 0; i < q.size(); ++i) q[i] += memory_[k].s[i] * (a[k] - b);
    }
    for (Real& x : q) x = -x;
  }

  SolverKind kind_;
  LeastSquaresSystem sys_;  // J, r and the layout of the current step, storage kept across steps
  Pose start_;
  std::vector<Real> delta_;
  TrialFrames scratch_;
  // L-BFGS state
  std::deque<Pair> memory_;
  Pair spare_{{}, {}, 0.0};  // the last pair dropped from memory_: its vectors are reused
  std::vector<Real> g_, d_, wd_, alphas_, lo_, hi_;
  std::vector<char> frozen_;
  std::vector<Real> s_, previousGradient_;
  std::vector<char> previousFrozen_;
  bool havePrevious_ = false, previousHadFree_ = false;
};

}  // namespace

std::unique_ptr<Method> makeDescentMethod(SolverKind kind) { return std::make_unique<DescentMethod>(kind); }

}  // namespace pba::ik::detail
