#pragma once
// Small dense linear algebra for the Jacobian IK methods: a row-major matrix, J Jᵀ, Cholesky solve and
// the singular value decomposition of a wide matrix J (m × n, m ≤ n: m = 3 or 6 per effector).
//
// SVD route. With m small, J = U Σ Vᵀ is obtained from the symmetric eigenproblem J Jᵀ = U Σ² Uᵀ
// (cyclic Jacobi rotations, unconditionally convergent for symmetric matrices), and vᵢ = Jᵀ uᵢ / σᵢ
// for σᵢ > 0. Squaring doubles the condition number's exponent; singular values below
// 1e-7 · σ_max are therefore reported as zero (their vᵢ are not formed), far below any cut-off used.
#include <vector>

#include "physics/core/types.h"

namespace pba::ik {

struct Matrix {
  int rows = 0, cols = 0;
  std::vector<Real> data;  ///< row-major

  Matrix() = default;
  Matrix(int r, int c) : rows(r), cols(c), data(static_cast<size_t>(r) * static_cast<size_t>(c), 0.0) {}
  Real& operator()(int r, int c) { return data[static_cast<size_t>(r) * static_cast<size_t>(cols) + static_cast<size_t>(c)]; }
  Real operator()(int r, int c) const { return data[static_cast<size_t>(r) * static_cast<size_t>(cols) + static_cast<size_t>(c)]; }
};

/// y = J x (x has J.cols entries).
std::vector<Real> multiply(const Matrix& J, const std::vector<Real>& x);
/// y = Jᵀ x (x has J.rows entries).
std::vector<Real> multiplyTransposed(const Matrix& J, const std::vector<Real>& x);
/// A = J Jᵀ (rows × rows, symmetric).
Matrix gram(const Matrix& J);
/// Solves A x = b for symmetric positive definite A by Cholesky. False (x untouched) when A is not
/// numerically positive definite.
bool solveSpd(const Matrix& A, const std::vector<Real>& b, std::vector<Real>& x);

/// Thin SVD of J (rows ≤ cols expected): J = Σᵢ σᵢ uᵢ vᵢᵀ, σ sorted decreasing.
struct Svd {
  std::vector<Real> sigma;            ///< singular values, decreasing, ≥ 0
  std::vector<std::vector<Real>> u;   ///< left singular vectors (J.rows entries each)
  std::vector<std::vector<Real>> v;   ///< right singular vectors (J.cols entries each); empty where σ ≈ 0
};
Svd svd(const Matrix& J);

Real dot(const std::vector<Real>& a, const std::vector<Real>& b);

}  // namespace pba::ik
