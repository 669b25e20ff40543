// Jacobian IK methods (Workbook §2.5, Algorithm 2; IK slides; Buss 2004 "Introduction to inverse
// kinematics with Jacobian transpose, pseudoinverse and damped least squares methods"; Buss & Kim 2005).
// Each step linearises ė = J θ̇ at the current pose and solves J Δθ ≈ Δe, as the sources state it:
//   JT     the exercise IK-7: steepest descent of f(θ) = ½ Σ wₖ² |gₖ − eₖ(θ)|² on the full (weighted)
//          error, with the step length of Buss 2004 §4.
//   pinv   Δθ = J⁺ Δe = Σ_{σᵢ > c σ_max} σᵢ⁻¹ (uᵢ·Δe) vᵢ  (SVD; c = singularCutoff drops near-singular
//          directions, which would otherwise give huge steps: IK slides "Degenerate cases").
//   DLS    the exercise IK-4: minimises |J Δθ − Δe|² + λ² |Δθ|² (Buss 2004 §5).
//   SDLS   Buss & Kim 2005 §4: each singular direction's step is clamped to its own γᵢ ≤ γ_max, from
//          the motion the step asks of the effectors and the motion its joints would produce (the
//          exercise IK-8); the sum is clamped to γ_max = π/4.
// Δe is each effector's error clamped to maxErrorStep (Buss's D_max, the clamping of Buss & Kim's
// experiments) to keep the linearisation valid. DOF weights wⱼ scale the columns (J̃ = J W) and the
// step (Δθ = W Δỹ). Joint limits: the pose is clamped after each step (IK-6); with ZeroColumns, DOFs
// at a limit whose step points outward lose their column and the step is solved again (IK slides,
// "Joint limits").
// Departures from the sources, off by default (SolveOptions): maxJointStep scales any step down to
// a largest DOF change; jacobianLineSearch halves a step until f decreases (JT: from Buss's α until
// Armijo's sufficient decrease 10⁻⁴ α |Jᵀ r|² holds, so JT cannot diverge).
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "physics/exercises/not_implemented.h"
#include "physics/ik/exercises.h"
#include "physics/ik/jacobian.h"
#include "physics/ik/least_squares.h"
#include "physics/ik/solver_internal.h"

namespace pba::ik {

// ***** IK-4: the damped least-squares step (IK slides, "Inverting J"; Buss 2004 §5) *****
// Inputs: the Jacobian J (rows: effector coordinates [m or scaled rad], columns: DOFs), the error Δe
// (rows entries) and the damping λ ≥ 0. Output: the change of the DOFs Δθ (J.cols entries).
// (1) Buss §5 writes the damped step so that the only system to solve is small and square (rows × rows,
//     not columns × columns): work out that matrix (gram(J) gives J Jᵀ) and where λ enters it.
// (2) Solve it with solveSpd; when the solve fails (λ = 0 and J singular), return zeros.
// (3) Turn the solution back into a change of the DOFs (multiplyTransposed).
// Check: with λ = 0 and J invertible the step solves J Δθ = Δe exactly (the pseudo-inverse step of
// Workbook §2.5); a larger λ shortens the step; a singular J with λ > 0 gives a finite step.
// *****
std::vector<Real> dampedLeastSquaresStep([[maybe_unused]] const Matrix& J,
                                         [[maybe_unused]] const std::vector<Real>& error,
                                         [[maybe_unused]] Real lambda) {
  // BEGIN SOLUTION
  Matrix A = gram(J);
  for (int i = 0; i < A.rows; ++i) A(i, i) += lambda * lambda;
  std::vector<Real> f;
  if (!solveSpd(A, error, f)) return std::vector<Real>(static_cast<size_t>(J.cols), 0.0);
  return multiplyTransposed(J, f);
  // END SOLUTION
  // STUB: return exercises::notImplemented("IK-4", std::vector<Real>(static_cast<size_t>(J.cols), 0.0));
}

// Start-up probe: tells the lab whether IK-4 is still a stub.
PBA_EXERCISE_PROBE(dampedLeastSquaresStep(Matrix(1, 1), std::vector<Real>{0.0}, 0.1));

// ***** IK-7: the Jacobian-transpose step and its length (Workbook §2.5; IK slides, "Jacobian
// transpose"; Buss 2004 §4) *****
// Inputs: J (rows: effector coordinates [m, or scaled rad], columns: DOFs) and the full error r (rows
// entries: goal minus effector, weighted). Output: the step's direction (J.cols entries) and its length
// α ≥ 0 [1]; the solver moves the DOFs by α times the direction.
// (1) The direction: the steepest-descent direction of ½|r|² over the DOFs, written with J
//     (multiplyTransposed). It needs no inverse of anything.
// (2) The length: to first order, moving by α times the direction changes the effectors by α times J
//     times the direction (multiply). Choose the α that brings the linearised error closest to the goal
//     (a least-squares problem in one unknown: set the derivative of the squared error to zero).
// (3) A zero direction (r = 0, or r orthogonal to every column) is a stationary point: return α = 0 so
//     that the solver stops. If the predicted change comes out zero, take α = 1.
// Check: α is positive whenever the direction is not zero; along the direction no other α leaves a
// smaller linearised error; for J the identity the step with its α is r itself.
// *****
TransposeStep jacobianTransposeStep(const Matrix& J, const std::vector<Real>& error) {
  // BEGIN SOLUTION
  TransposeStep out;
  out.direction = multiplyTransposed(J, error);
  const Real gg = dot(out.direction, out.direction);
  if (!(gg > 0.0)) return out;
  const std::vector<Real> jjr = multiply(J, out.direction);
  const Real denom = dot(jjr, jjr);
  out.alpha = denom > 0.0 ? dot(error, jjr) / denom : 1.0;
  return out;
  // END SOLUTION
  // STUB: return exercises::notImplemented("IK-7", TransposeStep{}, J, error);
}

// Start-up probe: tells the lab whether IK-7 is still a stub.
PBA_EXERCISE_PROBE(jacobianTransposeStep(Matrix(1, 1), std::vector<Real>{0.0}));

// ***** IK-8: selectively damped least squares, the damping of one singular direction (Buss & Kim
// 2005, "Selectively damped least squares for inverse kinematics", §4) *****
// Inputs: one singular triple of J (u: J.rows entries, the effector rows in blocks of 3; v: J.cols
// entries; σ > 0), ρ (J.cols entries, ρⱼ [m/rad]: the sum over the effector blocks of the length of
// column j's block, how far the effectors move per unit change of DOF j) and γ_max [rad]. Output: γᵢ
// [rad], the largest change of any one DOF that this direction's step may make (the solver clamps
// the direction's undamped step to it).
// (1) Nᵢ [1]: how much effector motion this direction asks for per unit of error: the sum over the
//     effector blocks of the length of u's block (a block is 3 consecutive rows).
// (2) Mᵢ [1]: how much effector motion the joints would make for that step: each DOF's share of v
//     (its absolute value) times that DOF's ρ, summed over the DOFs, then divided by σ (the undamped
//     step along this direction is 1/σ times larger than its share of the error).
// (3) γᵢ: γ_max when the joints would move the effectors no more than asked (Mᵢ ≤ Nᵢ); otherwise
//     γ_max scaled down by how many times more they would move.
// Check: a single hinge moving one effector gets γ_max; a direction whose joints swing the effectors
// far more than asked (small σ) gets proportionally less; the result never exceeds γ_max and is ≥ 0.
// *****
Real selectiveDampingLimit(const std::vector<Real>& u, const std::vector<Real>& v, Real sigma,
                           const std::vector<Real>& rho, Real gammaMax) {
  // BEGIN SOLUTION
  Real N = 0.0;
  for (size_t r = 0; r + 2 < u.size(); r += 3) N += glm::length(Vec3(u[r], u[r + 1], u[r + 2]));
  Real M = 0.0;
  for (size_t col = 0; col < v.size(); ++col) M += std::abs(v[col]) * rho[col];
  M /= sigma;
  return (M > N ? N / M : 1.0) * gammaMax;
  // END SOLUTION
  // STUB: return exercises::notImplemented("IK-8", 0.0, u, v, sigma, rho, gammaMax);
}

// Start-up probe: tells the lab whether IK-8 is still a stub.
PBA_EXERCISE_PROBE(selectiveDampingLimit(std::vector<Real>{1.0, 0.0, 0.0}, std::vector<Real>{1.0}, 1.0,
                                         std::vector<Real>{1.0}, 0.5));

namespace detail {
namespace {

constexpr Real kSdlsGammaMax = kPi / 4.0;  // [rad] Buss & Kim 2005, γ_max

class JacobianMethod final : public Method {
 public:
  explicit JacobianMethod(SolverKind kind) : kind_(kind) {}

  void iterate(Context& c) override {
    leastSquaresSystem(c, sys_);  // reuses the buffers of the previous step
    LeastSquaresSystem& sys = sys_;
    Matrix& J = sys.J;
    std::vector<Real> delta = step(c, J, sys.residual, sys.clamped);
    if (c.options.enforceLimits && c.options.limitMode == JacobianLimitMode::ZeroColumns &&
        zeroBlockedColumns(c, J, delta))
      delta = step(c, J, sys.residual, sys.clamped);
    // α: 1 for pinv, DLS and SDLS; Buss's step length for JT. slope: ∇f·Δ for JT's Armijo test, 0
    // (ask only for decrease) for the others, whose step is not a multiple of the gradient.
    Real alpha = 1.0, slope = 0.0;
    if (kind_ == SolverKind::JacobianTranspose) {
      // IK-7's length on the final J; ∇f·(Jᵀ r) = −|Jᵀ r|² for the Armijo test. α = 0: stationary.
      const TransposeStep t = jacobianTransposeStep(J, sys.residual);
      if (!(t.alpha > 0.0)) return;
      alpha = t.alpha;
      slope = -dot(t.direction, t.direction);
    }
    const Real largest = alpha * maxAbs(delta);
    if (c.options.maxJointStep > 0.0 && largest > c.options.maxJointStep) alpha *= c.options.maxJointStep / largest;
    if (c.options.jacobianLineSearch) {
      lineSearch(c, delta, alpha, slope);
      return;
    }
    // As published: take the step.
    if (alpha != 1.0)  // (a product by 1 is exact: skipping it changes nothing)
      for (Real& x : delta) x *= alpha;
    applyStep(c.skeleton, c.pose, c.frames, sys.layout, delta);
    projectOntoLimits(c);
  }

 private:
  // Δθ = W Δỹ for the method; JT returns the unscaled direction W J̃ᵀ r (α comes separately).
  std::vector<Real> step(const Context& c, const Matrix& J, const std::vector<Real>& full,
                         const std::vector<Real>& clamped) {
    std::vector<Real> dy;
    switch (kind_) {
      case SolverKind::JacobianTranspose:
        dy = jacobianTransposeStep(J, full).direction;  // IK-7
        dy.resize(static_cast<size_t>(J.cols), 0.0);    // a stub's step is empty: no move
        break;
      case SolverKind::DampedLeastSquares:
        dy = dampedLeastSquaresStep(J, clamped, c.options.damping);
        break;
      case SolverKind::PseudoInverse:
        dy = pseudoInverseStep(J, clamped, c.options.singularCutoff);
        break;
      default:
        dy = selectivelyDampedStep(J, clamped);
        break;
    }
    if (!sys_.unitDofWeights)
      for (size_t i = 0; i < dy.size(); ++i) dy[i] *= sys_.dofWeights[i];
    return dy;
  }

  std::vector<Real> pseudoInverseStep(const Matrix& J, const std::vector<Real>& e, Real cutoff) {
    svd(J, svd_, svdWorkspace_);
    const Svd& d = svd_;
    std::vector<Real> out(static_cast<size_t>(J.cols), 0.0);
    const Real sigmaMax = d.sigma.empty() ? 0.0 : d.sigma[0];
    for (size_t i = 0; i < d.sigma.size(); ++i) {
      if (d.v[i].empty() || d.sigma[i] <= cutoff * sigmaMax) continue;
      const Real coef = dot(d.u[i], e) / d.sigma[i];
      for (size_t k = 0; k < out.size(); ++k) out[k] += coef * d.v[i][k];
    }
    return out;
  }

  std::vector<Real> selectivelyDampedStep(const Matrix& J, const std::vector<Real>& e) {
    svd(J, svd_, svdWorkspace_);
    const Svd& d = svd_;
    const int n = J.cols;
    // ρⱼ = Σₖ |J_kj| (3-row blocks: each effector's position, and orientation, rows).
    std::vector<Real>& rho = rho_;
    rho.assign(static_cast<size_t>(n), 0.0);
    for (int r = 0; r + 2 < J.rows; r += 3)
      for (int col = 0; col < n; ++col)
        rho[static_cast<size_t>(col)] += glm::length(Vec3(J(r, col), J(r + 1, col), J(r + 2, col)));
    std::vector<Real> total(static_cast<size_t>(n), 0.0);
    for (size_t i = 0; i < d.sigma.size(); ++i) {
      if (d.v[i].empty()) continue;  // σᵢ = 0: no response (Buss & Kim sum over σᵢ ≠ 0)
      const Real alpha = dot(d.u[i], e);
      const Real gamma = selectiveDampingLimit(d.u[i], d.v[i], d.sigma[i], rho, kSdlsGammaMax);  // IK-8
      std::vector<Real>& phi = phi_;
      const Real scale = alpha / d.sigma[i];  // once, not per entry (phi's stores could alias sigma)
      phi.resize(d.v[i].size());
      for (size_t k = 0; k < phi.size(); ++k) phi[k] = d.v[i][k] * scale;
      clampMaxAbs(phi, gamma);
      for (int col = 0; col < n; ++col) total[static_cast<size_t>(col)] += phi[static_cast<size_t>(col)];
    }
    clampMaxAbs(total, kSdlsGammaMax);
    return total;
  }

  // Zeroes the columns of DOFs at a limit whose step points outward. True when any was zeroed.
  bool zeroBlockedColumns(const Context& c, Matrix& J, const std::vector<Real>& delta) const {
    bool any = false;
    for (int i = 0; i < c.skeleton.dofCount(); ++i) {
      const Real v = c.pose.dofs[static_cast<size_t>(i)], d = delta[static_cast<size_t>(i)];
      const bool blocked =
          (v <= c.skeleton.dofLo(i) + 1e-12 && d < 0.0) || (v >= c.skeleton.dofHi(i) - 1e-12 && d > 0.0);
      if (!blocked) continue;
      for (int r = 0; r < J.rows; ++r) J(r, i) = 0.0;
      any = true;
    }
    return any;
  }

  // The line-search option (ours, SolveOptions::jacobianLineSearch): pose + α·delta, α halved until
  // f decreases (by Armijo's amount when slope < 0). Near a stretched, unreachable pose the
  // Gauss-Newton model of pinv/DLS/SDLS ignores the large residual's curvature term and can
  // oscillate (Buss 2004 §6 notes the jitter). No acceptable α leaves the pose unchanged: the driver
  // sees no progress and reports a stall.
  void lineSearch(Context& c, const std::vector<Real>& delta, Real alpha, Real slope) {
    const Real f0 = objective(c, c.frames);
    const Pose start = c.pose;
    std::vector<Real> trial(delta.size());
    auto f = [&](Real a) {
      for (size_t i = 0; i < trial.size(); ++i) trial[i] = a * delta[i];
      return trialObjective(c, start, c.frames, sys_.layout, trial, scratch_);
    };
    if (!backtrack(f, f0, alpha, slope)) c.pose = start;
  }

  SolverKind kind_;
  LeastSquaresSystem sys_;  // J, r and the layout of the current step, storage kept across steps
  TrialFrames scratch_;
  std::vector<Real> rho_;      // SDLS: ρⱼ, the motion of the effectors per unit of DOF j
  std::vector<Real> phi_;      // SDLS: one singular direction's clamped step
  Svd svd_;                    // pinv and SDLS: the decomposition of the step, storage kept
  SvdWorkspace svdWorkspace_;  // across steps
};

}  // namespace

std::unique_ptr<Method> makeJacobianMethod(SolverKind kind) { return std::make_unique<JacobianMethod>(kind); }

}  // namespace detail
}  // namespace pba::ik
