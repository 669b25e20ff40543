// Jacobian IK methods (Workbook §2.5, Algorithm 2; IK slides; Buss 2004 "Introduction to inverse
// kinematics with Jacobian transpose, pseudoinverse and damped least squares methods"; Buss & Kim 2005).
// Each step linearises ė = J θ̇ at the current pose and solves J Δθ ≈ Δe:
//   JT     Δθ = α Jᵀ r, r the full (weighted) error: the steepest-descent direction of
//          f(θ) = ½ Σ wₖ² |gₖ − eₖ(θ)|². α starts at Buss's ⟨r, J Jᵀ r⟩ / |J Jᵀ r|² and is halved until
//          f decreases by the Armijo amount 10⁻⁴ α |Jᵀ r|² (backtracking line search): every accepted
//          step decreases f, so JT cannot diverge; no acceptable step means a stall.
//   pinv   Δθ = J⁺ Δe = Σ_{σᵢ > c σ_max} σᵢ⁻¹ (uᵢ·Δe) vᵢ  (SVD; c = singularCutoff drops near-singular
//          directions, which would otherwise give huge steps: IK slides "Degenerate cases").
//   DLS    Δθ = Jᵀ (J Jᵀ + λ² I)⁻¹ Δe = Σ σᵢ/(σᵢ² + λ²) (uᵢ·Δe) vᵢ: minimises |J Δθ − Δe|² + λ² |Δθ|².
//   SDLS   Buss & Kim 2005 §4: each singular direction gets its own clamp γᵢ = min(1, Nᵢ/Mᵢ) γ_max,
//          Nᵢ = Σₖ |uᵢ,ₖ| (effector blocks), Mᵢ = σᵢ⁻¹ Σⱼ |vⱼᵢ| Σₖ |J_kj| — the ratio of the motion the
//          step asks for to the motion the joints would produce; γ_max = π/4.
// Δe is each effector's error clamped to maxErrorStep (Buss's D_max) to keep the linearisation valid.
// DOF weights wⱼ scale the columns (J̃ = J W) and the step (Δθ = W Δỹ). Joint limits: the pose is
// clamped after each step; with ZeroColumns, DOFs at a limit whose step points outward lose their
// column and the step is solved again (IK slides, "Joint limits").
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
// (1) Form the small square matrix A = J Jᵀ (rows × rows) with gram(J).
// (2) Add the damping: A(i, i) += λ² for every i. A is then symmetric positive definite for λ > 0.
// (3) Solve A f = Δe with solveSpd(A, error, f). If it fails (λ = 0 and J singular), return zeros.
// (4) Return Δθ = Jᵀ f with multiplyTransposed(J, f) (J.cols entries).
//     With λ = 0 this is the pseudo-inverse step Jᵀ (J Jᵀ)⁻¹ Δe of Workbook §2.5.
// *****
std::vector<Real> dampedLeastSquaresStep([[maybe_unused]] const Matrix& J, [[maybe_unused]] const std::vector<Real>& error,
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

namespace detail {
namespace {

constexpr Real kSdlsGammaMax = kPi / 4.0;  // [rad] Buss & Kim 2005, γ_max
constexpr Real kArmijo = 1e-4;             // sufficient-decrease constant of the JT line search
constexpr int kMaxHalvings = 30;

class JacobianMethod final : public Method {
 public:
  explicit JacobianMethod(SolverKind kind) : kind_(kind) {}

  void iterate(Context& c) override {
    LeastSquaresSystem sys = leastSquaresSystem(c);
    layout_ = std::move(sys.layout);
    weights_ = std::move(sys.dofWeights);
    Matrix& J = sys.J;
    const std::vector<Real>& full = sys.residual;
    const std::vector<Real>& clamped = sys.clamped;
    std::vector<Real> delta = step(c, J, full, clamped);
    if (c.options.enforceLimits && c.options.limitMode == JacobianLimitMode::ZeroColumns && zeroBlockedColumns(c, J, delta))
      delta = step(c, J, full, clamped);
    if (kind_ == SolverKind::JacobianTranspose) {
      jacobianTransposeStep(c, J, full, delta);
      return;
    }
    // Safeguard (our addition to the texts' methods): halve the step until the objective does not
    // increase. Near a stretched, unreachable pose the Gauss-Newton model of pinv/DLS/SDLS ignores the
    // large residual's curvature term and would oscillate (Buss 2004 §6 notes the jitter); this keeps
    // every accepted step a descent step. It almost always accepts the full step.
    clampMaxAbs(delta, c.options.maxJointStep);
    backtrack(c, delta, 1.0, 0.0);
  }

 private:
  // Δθ = W Δỹ for the method; JT returns the unscaled direction (the line search picks α).
  std::vector<Real> step(const Context& c, const Matrix& J, const std::vector<Real>& full, const std::vector<Real>& clamped) {
    std::vector<Real> dy;
    switch (kind_) {
      case SolverKind::JacobianTranspose: dy = multiplyTransposed(J, full); break;
      case SolverKind::DampedLeastSquares: dy = dampedLeastSquaresStep(J, clamped, c.options.damping); break;
      case SolverKind::PseudoInverse: dy = pseudoInverseStep(J, clamped, c.options.singularCutoff); break;
      default: dy = selectivelyDampedStep(c, J, clamped); break;
    }
    for (size_t i = 0; i < dy.size(); ++i) dy[i] *= weights_[i];
    return dy;
  }

  static std::vector<Real> pseudoInverseStep(const Matrix& J, const std::vector<Real>& e, Real cutoff) {
    const Svd d = svd(J);
    std::vector<Real> out(static_cast<size_t>(J.cols), 0.0);
    const Real sigmaMax = d.sigma.empty() ? 0.0 : d.sigma[0];
    for (size_t i = 0; i < d.sigma.size(); ++i) {
      if (d.v[i].empty() || d.sigma[i] <= cutoff * sigmaMax) continue;
      const Real coef = dot(d.u[i], e) / d.sigma[i];
      for (size_t k = 0; k < out.size(); ++k) out[k] += coef * d.v[i][k];
    }
    return out;
  }

  static void clampMaxAbs(std::vector<Real>& v, Real limit) {
    const Real largest = maxAbs(v);
    if (largest > limit) for (Real& x : v) x *= limit / largest;
  }

  std::vector<Real> selectivelyDampedStep(const Context& c, const Matrix& J, const std::vector<Real>& e) const {
    const Svd d = svd(J);
    const int n = J.cols;
    // ρⱼ = Σₖ |J_kj| (3-row blocks: each effector's position, and orientation, rows).
    std::vector<Real> rho(static_cast<size_t>(n), 0.0);
    for (int r = 0; r + 2 < J.rows; r += 3)
      for (int col = 0; col < n; ++col) rho[static_cast<size_t>(col)] += glm::length(Vec3(J(r, col), J(r + 1, col), J(r + 2, col)));
    std::vector<Real> total(static_cast<size_t>(n), 0.0);
    for (size_t i = 0; i < d.sigma.size(); ++i) {
      if (d.v[i].empty()) continue;
      const Real alpha = dot(d.u[i], e);
      Real N = 0.0;
      for (size_t r = 0; r + 2 < d.u[i].size(); r += 3) N += glm::length(Vec3(d.u[i][r], d.u[i][r + 1], d.u[i][r + 2]));
      Real M = 0.0;
      for (int col = 0; col < n; ++col) M += std::abs(d.v[i][static_cast<size_t>(col)]) * rho[static_cast<size_t>(col)];
      M /= d.sigma[i];
      const Real gamma = (M > N ? N / M : 1.0) * kSdlsGammaMax;
      std::vector<Real> phi(d.v[i]);
      for (Real& x : phi) x *= alpha / d.sigma[i];
      clampMaxAbs(phi, gamma);
      for (int col = 0; col < n; ++col) total[static_cast<size_t>(col)] += phi[static_cast<size_t>(col)];
    }
    clampMaxAbs(total, kSdlsGammaMax);
    (void)c;
    return total;
  }

  // Zeroes the columns of DOFs at a limit whose step points outward. True when any was zeroed.
  bool zeroBlockedColumns(const Context& c, Matrix& J, const std::vector<Real>& delta) const {
    bool any = false;
    for (int i = 0; i < c.skeleton.dofCount(); ++i) {
      const Real v = c.pose.dofs[static_cast<size_t>(i)], d = delta[static_cast<size_t>(i)];
      const bool blocked = (v <= c.skeleton.dofLo(i) + 1e-12 && d < 0.0) || (v >= c.skeleton.dofHi(i) - 1e-12 && d > 0.0);
      if (!blocked) continue;
      for (int r = 0; r < J.rows; ++r) J(r, i) = 0.0;
      any = true;
    }
    return any;
  }

  void jacobianTransposeStep(Context& c, const Matrix& J, const std::vector<Real>& full, const std::vector<Real>& direction) {
    // |J̃ᵀ r|² is the directional derivative's magnitude; Buss's α uses J̃ J̃ᵀ r.
    std::vector<Real> g = multiplyTransposed(J, full);
    const Real slope = dot(g, g);
    if (!(slope > 0.0)) return;
    const std::vector<Real> jjr = multiply(J, g);
    const Real denom = dot(jjr, jjr);
    Real alpha = denom > 0.0 ? dot(full, jjr) / denom : 1.0;
    const Real largest = maxAbs(direction);
    if (largest * alpha > c.options.maxJointStep) alpha = c.options.maxJointStep / largest;
    backtrack(c, direction, alpha, kArmijo * slope);
  }

  // Tries pose + α·direction (clamped to the limits), halving α until f decreases by at least
  // α·armijoSlope (strictly, when armijoSlope is 0). Leaves the pose unchanged when no α works.
  void backtrack(Context& c, const std::vector<Real>& direction, Real alpha, Real armijoSlope) {
    const Real f0 = objective(c, c.frames);
    const Pose start = c.pose;
    std::vector<Real> trial(direction.size());
    for (int h = 0; h < kMaxHalvings; ++h, alpha *= 0.5) {
      for (size_t i = 0; i < trial.size(); ++i) trial[i] = alpha * direction[i];
      const Real f = trialObjective(c, start, c.frames, layout_, trial, scratch_);
      if (armijoSlope > 0.0 ? f <= f0 - alpha * armijoSlope : f < f0) return;
    }
    c.pose = start;  // no acceptable step: the driver sees no progress and reports a stall
  }

  SolverKind kind_;
  JacobianLayout layout_;
  std::vector<Real> weights_;
  std::vector<Frame> scratch_;
};

}  // namespace

std::unique_ptr<Method> makeJacobianMethod(SolverKind kind) { return std::make_unique<JacobianMethod>(kind); }

}  // namespace detail
}  // namespace pba::ik
