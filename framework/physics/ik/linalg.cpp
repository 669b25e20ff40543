// Dense linear algebra of the Jacobian IK methods on Eigen 3.4 (linalg.h). The IK code keeps its
// row-major Matrix and std::vector; Eigen works on them in place through Map.
#include "physics/ik/linalg.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SVD>

namespace pba::ik {

namespace {
using RowMajor = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstMatrixMap = Eigen::Map<const RowMajor>;
using ConstVectorMap = Eigen::Map<const Eigen::VectorXd>;
using VectorMap = Eigen::Map<Eigen::VectorXd>;

ConstMatrixMap view(const Matrix& J) { return ConstMatrixMap(J.data.data(), J.rows, J.cols); }
ConstVectorMap view(const std::vector<Real>& x) {
  return ConstVectorMap(x.data(), static_cast<Eigen::Index>(x.size()));
}
}  // namespace

Real dot(const std::vector<Real>& a, const std::vector<Real>& b) { return view(a).dot(view(b)); }

std::vector<Real> multiply(const Matrix& J, const std::vector<Real>& x) {
  std::vector<Real> y(static_cast<size_t>(J.rows));
  VectorMap(y.data(), J.rows).noalias() = view(J) * view(x);
  return y;
}

std::vector<Real> multiplyTransposed(const Matrix& J, const std::vector<Real>& x) {
  std::vector<Real> y;
  multiplyTransposed(J, x, y);
  return y;
}

void multiplyTransposed(const Matrix& J, const std::vector<Real>& x, std::vector<Real>& y) {
  y.resize(static_cast<size_t>(J.cols));
  VectorMap(y.data(), J.cols).noalias() = view(J).transpose() * view(x);
}

Matrix gram(const Matrix& J) {
  Matrix A(J.rows, J.rows);
  Eigen::Map<RowMajor>(A.data.data(), J.rows, J.rows).noalias() = view(J) * view(J).transpose();
  return A;
}

bool solveSpd(const Matrix& A, const std::vector<Real>& b, std::vector<Real>& x) {
  const ConstMatrixMap a = view(A);
  if (A.rows == 0 || !a.allFinite()) return false;
  const Real scale = a.diagonal().maxCoeff();
  if (!(scale > 0.0)) return false;
  const Eigen::LLT<RowMajor> llt(a);
  if (llt.info() != Eigen::Success) return false;
  // LLT only fails on a pivot ≤ 0; a singular A in floating point usually leaves a tiny positive one.
  if (llt.matrixLLT().diagonal().cwiseAbs2().minCoeff() <= kSingularPivot * scale) return false;
  x.resize(static_cast<size_t>(A.rows));
  VectorMap(x.data(), A.rows) = llt.solve(view(b));
  return true;
}

// The SVD (linalg.h). A wide J (rows ≤ cols: every chain with more DOFs than effector rows) goes through
// one-sided Jacobi (Hestenes 1958): plane rotations of pairs of J's rows until the rows are mutually
// orthogonal, W = Uᵀ J with U the product of the rotations; then J = U W = Σᵢ |wᵢ| uᵢ (wᵢ/|wᵢ|)ᵀ.
// One-sided Jacobi gives the singular values to high relative accuracy (Demmel & Veselić 1992) and
// finds an exactly dependent row as an exactly zero one. Organised in rounds (orthogonaliseRows): the rows'
// dot products afresh in one pass over J (their Gram matrix G = W Wᵀ), Jacobi sweeps on the k × k matrix G
// (the two-sided step Rᵀ G R gives the dot products the rotated rows would have), then the round's product
// of rotations applied to the rows in one pass. Two or three rounds for IK's Jacobians, instead of a pass
// over two rows for every rotation. Eigen's JacobiSVD first QR-factorises Jᵀ with column pivoting, work a
// 3-row J does not need (docs/performance-ik-kdl.md compares the two). A tall J, or one of more than 64
// rows, goes to Eigen's JacobiSVD.
struct SvdWorkspace::Impl {
  Eigen::JacobiSVD<Eigen::MatrixXd> eigen;  // tall matrices and more than 64 rows
  std::vector<Real> w;                      // the rows being orthogonalised, column-major: W(p, i) at w[i·k + p]
  std::vector<Real> u;      // the accumulated rotation U (k × k), stored like W: U(i, p) at u[i·k + p]
  std::vector<Real> gram;   // G = W Wᵀ (k × k, symmetric, both triangles)
  std::vector<Real> sweep;  // the product of one round's rotations (k × k, like u)
  std::vector<int> order;   // rows by decreasing |wₚ|
};
SvdWorkspace::SvdWorkspace() : impl_(std::make_unique<Impl>()) {}
SvdWorkspace::~SvdWorkspace() = default;

namespace {
constexpr int kMaxJacobiSweeps = 60;  // in all rounds; IK's 3 × 30 Jacobians take about 5
constexpr int kMaxJacobiRows = 64;    // more rows (over 10 pose effectors) go to Eigen's JacobiSVD

size_t at(int row, int col, int k) {
  return static_cast<size_t>(col) * static_cast<size_t>(k) + static_cast<size_t>(row);
}

/// G = W Wᵀ from the rows as they are (W column-major, k × n). K is k when known at compile time (IK's 3
/// rows of a position effector, 6 of a pose), 0 otherwise; with K the loops unroll and the sums live in
/// registers.
template <int K>
void gramOfRows(const std::vector<Real>& w, std::vector<Real>& g, int k, int n) {
  g.assign(static_cast<size_t>(k) * static_cast<size_t>(k), 0.0);
  if constexpr (K > 0) {
    Real sum[K][K] = {};
    for (int i = 0; i < n; ++i) {
      const Real* x = w.data() + static_cast<size_t>(i) * K;
#pragma GCC unroll 8
      for (int p = 0; p < K; ++p)
#pragma GCC unroll 8
        for (int r = p; r < K; ++r) sum[p][r] += x[p] * x[r];
    }
    for (int p = 0; p < K; ++p)
      for (int r = p; r < K; ++r) g[at(p, r, K)] = g[at(r, p, K)] = sum[p][r];
  } else {
    for (int i = 0; i < n; ++i) {
      const Real* x = w.data() + static_cast<size_t>(i) * static_cast<size_t>(k);
      for (int p = 0; p < k; ++p)
        for (int r = p; r < k; ++r) g[at(p, r, k)] += x[p] * x[r];
    }
    for (int p = 0; p < k; ++p)
      for (int r = p + 1; r < k; ++r) g[at(r, p, k)] = g[at(p, r, k)];
  }
}

/// W ← Rᵀ W for the sweep's rotation R (k × k), one column of W at a time.
template <int K>
void rotateRows(std::vector<Real>& w, const std::vector<Real>& rotation, int k, int n) {
  if constexpr (K > 0) {
    Real R[K][K];  // R[p][j] = R(j, p), kept in registers
#pragma GCC unroll 8
    for (int p = 0; p < K; ++p)
#pragma GCC unroll 8
      for (int j = 0; j < K; ++j) R[p][j] = rotation[at(j, p, K)];
    for (int i = 0; i < n; ++i) {
      Real* x = w.data() + static_cast<size_t>(i) * K;
      Real in[K], out[K];
#pragma GCC unroll 8
      for (int j = 0; j < K; ++j) in[j] = x[j];
#pragma GCC unroll 8
      for (int p = 0; p < K; ++p) {
        out[p] = 0.0;
#pragma GCC unroll 8
        for (int j = 0; j < K; ++j) out[p] += R[p][j] * in[j];
      }
#pragma GCC unroll 8
      for (int p = 0; p < K; ++p) x[p] = out[p];
    }
  } else {
    Real column[kMaxJacobiRows];
    for (int i = 0; i < n; ++i) {
      Real* x = w.data() + static_cast<size_t>(i) * static_cast<size_t>(k);
      for (int p = 0; p < k; ++p) {
        Real sum = 0.0;
        for (int j = 0; j < k; ++j) sum += rotation[at(j, p, k)] * x[j];
        column[p] = sum;
      }
      for (int p = 0; p < k; ++p) x[p] = column[p];
    }
  }
}

/// B ← B R for the plane rotation R of (p, r): column p ← c·p − s·r, column r ← s·p + c·r.
template <int K>
[[gnu::always_inline]] inline void rotateColumns(std::vector<Real>& b, int k, int p, int r, Real c, Real s) {
  if constexpr (K > 0) k = K;
#pragma GCC unroll 8
  for (int i = 0; i < k; ++i) {
    const Real x = b[at(i, p, k)], y = b[at(i, r, k)];
    b[at(i, p, k)] = c * x - s * y;
    b[at(i, r, k)] = s * x + c * y;
  }
}

/// One cyclic sweep of rotations on G (G ← Rᵀ G R for each pair that is not yet orthogonal to working
/// precision: |G_pr| > √n ε √(G_pp G_rr), the rounding of a dot product of n terms, LAPACK dgesvj's
/// bound), their product accumulated into `rotation` (rotation ← rotation R). False when no pair needed one.
template <int K>
bool sweepGram(std::vector<Real>& g, std::vector<Real>& rotation, int k, int n) {
  if constexpr (K > 0) k = K;
  const Real tolerance = std::sqrt(Real(n)) * std::numeric_limits<Real>::epsilon();
  constexpr Real kEps2 = std::numeric_limits<Real>::epsilon() * std::numeric_limits<Real>::epsilon();
  bool rotated = false;
  for (int p = 0; p + 1 < k; ++p) {
    for (int r = p + 1; r < k; ++r) {
      const Real alpha = g[at(p, p, k)], beta = g[at(r, r, k)], gamma = g[at(p, r, k)];
      if (!(std::abs(gamma) > tolerance * std::sqrt(alpha * beta))) continue;
      // A row below ε of the other is numerically zero (its σ falls under the rank threshold): leave the
      // pair. This also bounds |ζ| below by ~1/ε², so ζ² cannot overflow.
      if (!(std::min(alpha, beta) > kEps2 * std::max(alpha, beta))) continue;
      rotated = true;
      // The rotation with (c wₚ − s w_r)·(s wₚ + c w_r) = 0: t = s/c is the smaller root of
      // t² + 2ζt − 1 = 0, ζ = (β − α)/(2γ) (Golub & Van Loan §8.5.2, the symmetric Schur step).
      const Real zeta = (beta - alpha) / (2.0 * gamma);
      const Real t = std::copysign(1.0, zeta) / (std::abs(zeta) + std::sqrt(1.0 + zeta * zeta));
      const Real c = 1.0 / std::sqrt(1.0 + t * t), s = c * t;
      rotateColumns<K>(g, k, p, r, c, s);  // G R
#pragma GCC unroll 8
      for (int j = 0; j < k; ++j) {  // Rᵀ (G R): the rows, through symmetry
        g[at(p, j, k)] = g[at(j, p, k)];
        g[at(r, j, k)] = g[at(j, r, k)];
      }
      // The 2 × 2 block's eigenvalues, ≥ 0 for a Gram matrix; rounding can take a tiny one below 0.
      g[at(p, p, k)] = std::max(alpha - t * gamma, 0.0);
      g[at(r, r, k)] = std::max(beta + t * gamma, 0.0);
      g[at(p, r, k)] = g[at(r, p, k)] = 0.0;
      rotateColumns<K>(rotation, k, p, r, c, s);
    }
  }
  return rotated;
}

/// Rotates the rows of W (column-major, k × n) until they are mutually orthogonal, accumulating the
/// rotations in u (J = U W throughout); g ends as the Gram matrix of the final rows. Each round takes the
/// rows' Gram matrix afresh, diagonalises it by Jacobi sweeps (k × k work only), and applies the product of
/// the rotations to the rows in one pass; the next round's fresh dot products then either confirm the
/// rows orthogonal to working precision or correct what the Gram matrix's rounding left (its small
/// eigenvalues carry an absolute error of about ε λ_max). Two or three rounds for random Jacobians.
template <int K>
void orthogonaliseRows(SvdWorkspace::Impl& m, int k, int n) {
  for (int sweep = 0; sweep < kMaxJacobiSweeps; ++sweep) {
    gramOfRows<K>(m.w, m.gram, k, n);
    m.sweep.assign(static_cast<size_t>(k) * static_cast<size_t>(k), 0.0);
    for (int p = 0; p < k; ++p) m.sweep[at(p, p, k)] = 1.0;
    if (!sweepGram<K>(m.gram, m.sweep, k, n)) return;
    while (++sweep < kMaxJacobiSweeps && sweepGram<K>(m.gram, m.sweep, k, n)) {}
    rotateRows<K>(m.w, m.sweep, k, n);
    rotateRows<K>(m.u, m.sweep, k, k);  // U ← U R: each row of U is rotated as a column of W is
  }
  gramOfRows<K>(m.w, m.gram, k, n);  // not converged in kMaxJacobiSweeps (not seen): report what we have
}

/// σ at or below this is numerically zero (Eigen's rank threshold, kept for both paths).
Real rankThreshold(const Matrix& J, Real sigmaMax) {
  return Real(std::max(J.rows, J.cols)) * std::numeric_limits<Real>::epsilon() * sigmaMax;
}

void eigenSvd(const Matrix& J, Svd& out, SvdWorkspace::Impl& m);

void wideSvd(const Matrix& J, Svd& out, SvdWorkspace::Impl& m) {
  const int k = J.rows, n = J.cols;
  if (k > kMaxJacobiRows) {
    eigenSvd(J, out, m);
    return;
  }
  m.w.resize(static_cast<size_t>(k) * static_cast<size_t>(n));
  const Real* j = J.data.data();  // row-major in, column-major out
  Real* w = m.w.data();
  for (int p = 0; p < k; ++p)
    for (int i = 0; i < n; ++i)
      w[at(p, i, k)] = j[static_cast<size_t>(p) * static_cast<size_t>(n) + static_cast<size_t>(i)];
  m.u.assign(static_cast<size_t>(k) * static_cast<size_t>(k), 0.0);
  for (int p = 0; p < k; ++p) m.u[at(p, p, k)] = 1.0;
  if (k == 3) {
    orthogonaliseRows<3>(m, k, n);
  } else if (k == 6) {
    orthogonaliseRows<6>(m, k, n);
  } else {
    orthogonaliseRows<0>(m, k, n);
  }
  const auto norm = [&](int p) { return std::sqrt(m.gram[at(p, p, k)]); };
  m.order.resize(static_cast<size_t>(k));
  for (int p = 0; p < k; ++p) m.order[static_cast<size_t>(p)] = p;
  for (int i = 1; i < k; ++i) {  // insertion sort by decreasing norm, stable (std::stable_sort allocates)
    const int p = m.order[static_cast<size_t>(i)];
    int slot = i;
    for (; slot > 0 && norm(m.order[static_cast<size_t>(slot - 1)]) < norm(p); --slot)
      m.order[static_cast<size_t>(slot)] = m.order[static_cast<size_t>(slot - 1)];
    m.order[static_cast<size_t>(slot)] = p;
  }
  const Real zero = rankThreshold(J, norm(m.order[0]));
  out.u.resize(static_cast<size_t>(k));
  out.v.resize(static_cast<size_t>(k));
  for (size_t i = 0; i < static_cast<size_t>(k); ++i) {
    const int p = m.order[i];
    const Real sigma = norm(p);
    const bool nonzero = sigma > zero && sigma > 0.0;
    out.sigma.push_back(nonzero ? sigma : 0.0);
    out.u[i].resize(static_cast<size_t>(k));
    for (int r = 0; r < k; ++r) out.u[i][static_cast<size_t>(r)] = m.u[at(p, r, k)];  // U(r, p)
    out.v[i].clear();
    if (!nonzero) continue;
    out.v[i].resize(static_cast<size_t>(n));
    for (int c = 0; c < n; ++c) out.v[i][static_cast<size_t>(c)] = m.w[at(p, c, k)] / sigma;
  }
}

void eigenSvd(const Matrix& J, Svd& out, SvdWorkspace::Impl& m) {
  Eigen::JacobiSVD<Eigen::MatrixXd>& d = m.eigen;
  d.compute(view(J), Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = d.singularValues();
  const Real zero = rankThreshold(J, s.size() ? s(0) : 0.0);
  const auto count = static_cast<size_t>(s.size());
  out.u.resize(count);
  out.v.resize(count);
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    const bool nonzero = s(i) > zero && s(i) > 0.0;
    const auto k = static_cast<size_t>(i);
    out.sigma.push_back(nonzero ? s(i) : 0.0);
    out.u[k].assign(d.matrixU().col(i).data(), d.matrixU().col(i).data() + J.rows);
    if (nonzero)
      out.v[k].assign(d.matrixV().col(i).data(), d.matrixV().col(i).data() + J.cols);
    else
      out.v[k].clear();
  }
}
}  // namespace

void svd(const Matrix& J, Svd& out, SvdWorkspace& workspace) {
  out.sigma.clear();
  if (J.rows == 0 || J.cols == 0) {
    out.u.clear();
    out.v.clear();
    return;
  }
  if (J.rows <= J.cols) {
    wideSvd(J, out, workspace.impl());
  } else {
    eigenSvd(J, out, workspace.impl());
  }
}

Svd svd(const Matrix& J) {
  Svd out;
  SvdWorkspace workspace;
  svd(J, out, workspace);
  return out;
}

}  // namespace pba::ik
