#pragma once
// Small dense linear algebra for the Jacobian IK methods: a row-major matrix, products with vectors,
// J Jᵀ, a Cholesky solve and the singular value decomposition. The factorisations come from Eigen 3.4
// (docs/architecture.md §1: linear algebra that is not the lesson), except the SVD of a wide J, which is
// our own one-sided Jacobi (a 3 × n Jacobian needs no QR step first); the lesson, the damped
// least-squares step of IK-4, is written on top of solveSpd.
#include <memory>
#include <vector>

#include "physics/core/types.h"

namespace pba::ik {

struct Matrix {
  int rows = 0, cols = 0;
  std::vector<Real> data;  ///< row-major

  Matrix() = default;
  Matrix(int r, int c) : rows(r), cols(c), data(static_cast<size_t>(r) * static_cast<size_t>(c), 0.0) {}
  Real& operator()(int r, int c) {
    return data[static_cast<size_t>(r) * static_cast<size_t>(cols) + static_cast<size_t>(c)];
  }
  Real operator()(int r, int c) const {
    return data[static_cast<size_t>(r) * static_cast<size_t>(cols) + static_cast<size_t>(c)];
  }
};

/// y = J x (x has J.cols entries).
std::vector<Real> multiply(const Matrix& J, const std::vector<Real>& x);
/// y = Jᵀ x (x has J.rows entries).
std::vector<Real> multiplyTransposed(const Matrix& J, const std::vector<Real>& x);
/// The same into y, reusing its storage.
void multiplyTransposed(const Matrix& J, const std::vector<Real>& x, std::vector<Real>& y);
/// A = J Jᵀ (rows × rows, symmetric).
Matrix gram(const Matrix& J);

/// Relative pivot below which solveSpd calls a matrix singular: a Cholesky pivot (L_ii²) under
/// kSingularPivot × the largest diagonal entry of A. Such an A has a condition number ≳ 10¹³: a
/// solve would lose all but three digits, and a singular J Jᵀ rounds to pivots of about 10⁻¹⁶ of
/// its scale, never to exact zeros or negatives (an absolute test misses them).
inline constexpr Real kSingularPivot = 1e-13;

/// Solves A x = b for symmetric positive definite A by Cholesky (Eigen's LLT). False (x untouched)
/// when A is not positive definite to working precision: a pivot ≤ kSingularPivot × max Aᵢᵢ (also
/// A = 0, and any non-finite entry).
bool solveSpd(const Matrix& A, const std::vector<Real>& b, std::vector<Real>& x);

/// Thin SVD of J (one-sided Jacobi on the rows of a wide J, Eigen's two-sided Jacobi SVD for a tall one;
/// linalg.cpp says why): J = Σᵢ σᵢ uᵢ vᵢᵀ over min(rows, cols) terms,
/// σ sorted decreasing. Singular values at or below max(rows, cols) · ε · σ_max (Eigen's rank
/// threshold) are numerically zero: reported as exactly 0, with an empty vᵢ.
struct Svd {
  std::vector<Real> sigma;           ///< singular values, decreasing, ≥ 0
  std::vector<std::vector<Real>> u;  ///< left singular vectors (J.rows entries each)
  std::vector<std::vector<Real>> v;  ///< right singular vectors (J.cols entries each); empty where σ = 0
};
Svd svd(const Matrix& J);
/// The same into `out`, keeping the factorisation's storage in `workspace` from call to call (a solver
/// that decomposes a J of the same size every step allocates nothing after the first). Same result.
class SvdWorkspace {
 public:
  SvdWorkspace();
  ~SvdWorkspace();
  SvdWorkspace(const SvdWorkspace&) = delete;
  SvdWorkspace& operator=(const SvdWorkspace&) = delete;
  struct Impl;
  Impl& impl() { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};
void svd(const Matrix& J, Svd& out, SvdWorkspace& workspace);

Real dot(const std::vector<Real>& a, const std::vector<Real>& b);

}  // namespace pba::ik
