#include "physics/ik/linalg.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pba::ik {

Real dot(const std::vector<Real>& a, const std::vector<Real>& b) {
  Real s = 0.0;
  for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

std::vector<Real> multiply(const Matrix& J, const std::vector<Real>& x) {
  std::vector<Real> y(static_cast<size_t>(J.rows), 0.0);
  for (int r = 0; r < J.rows; ++r) {
    const Real* row = J.data.data() + static_cast<size_t>(r) * static_cast<size_t>(J.cols);
    Real s = 0.0;
    for (int c = 0; c < J.cols; ++c) s += row[c] * x[static_cast<size_t>(c)];
    y[static_cast<size_t>(r)] = s;
  }
  return y;
}

std::vector<Real> multiplyTransposed(const Matrix& J, const std::vector<Real>& x) {
  std::vector<Real> y(static_cast<size_t>(J.cols), 0.0);
  for (int r = 0; r < J.rows; ++r) {
    const Real* row = J.data.data() + static_cast<size_t>(r) * static_cast<size_t>(J.cols);
    const Real xr = x[static_cast<size_t>(r)];
    if (xr == 0.0) continue;
    for (int c = 0; c < J.cols; ++c) y[static_cast<size_t>(c)] += row[c] * xr;
  }
  return y;
}

Matrix gram(const Matrix& J) {
  Matrix A(J.rows, J.rows);
  for (int i = 0; i < J.rows; ++i) {
    const Real* ri = J.data.data() + static_cast<size_t>(i) * static_cast<size_t>(J.cols);
    for (int k = i; k < J.rows; ++k) {
      const Real* rk = J.data.data() + static_cast<size_t>(k) * static_cast<size_t>(J.cols);
      Real s = 0.0;
      for (int c = 0; c < J.cols; ++c) s += ri[c] * rk[c];
      A(i, k) = s;
      A(k, i) = s;
    }
  }
  return A;
}

bool solveSpd(const Matrix& A, const std::vector<Real>& b, std::vector<Real>& x) {
  const int n = A.rows;
  Matrix L(n, n);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k <= i; ++k) {
      Real s = A(i, k);
      for (int p = 0; p < k; ++p) s -= L(i, p) * L(k, p);
      if (i == k) {
        if (!(s > 1e-300)) return false;
        L(i, i) = std::sqrt(s);
      } else {
        L(i, k) = s / L(k, k);
      }
    }
  }
  std::vector<Real> y(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    Real s = b[static_cast<size_t>(i)];
    for (int p = 0; p < i; ++p) s -= L(i, p) * y[static_cast<size_t>(p)];
    y[static_cast<size_t>(i)] = s / L(i, i);
  }
  x.assign(static_cast<size_t>(n), 0.0);
  for (int i = n - 1; i >= 0; --i) {
    Real s = y[static_cast<size_t>(i)];
    for (int p = i + 1; p < n; ++p) s -= L(p, i) * x[static_cast<size_t>(p)];
    x[static_cast<size_t>(i)] = s / L(i, i);
  }
  return true;
}

namespace {
// Cyclic Jacobi eigen-decomposition of a symmetric matrix (Golub & Van Loan §8.5): A = Q D Qᵀ.
void symmetricEigen(Matrix A, std::vector<Real>& values, Matrix& Q) {
  const int n = A.rows;
  Q = Matrix(n, n);
  for (int i = 0; i < n; ++i) Q(i, i) = 1.0;
  for (int sweep = 0; sweep < 60; ++sweep) {
    Real off = 0.0, diag = 0.0;
    for (int i = 0; i < n; ++i) {
      diag += A(i, i) * A(i, i);
      for (int k = i + 1; k < n; ++k) off += A(i, k) * A(i, k);
    }
    if (off <= 1e-30 * diag || off == 0.0) break;
    for (int p = 0; p < n; ++p) {
      for (int q = p + 1; q < n; ++q) {
        const Real apq = A(p, q);
        // Negligible relative to the diagonal: treat as zero (this also keeps τ² far from overflow).
        if (std::abs(apq) <= 1e-300 || std::abs(apq) < 1e-20 * (std::abs(A(p, p)) + std::abs(A(q, q)))) continue;
        // Rotation angle that zeroes A(p, q): tan 2φ = 2 apq / (aqq − app), in the stable form.
        const Real tau = (A(q, q) - A(p, p)) / (2.0 * apq);
        const Real t = (tau >= 0.0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1.0 + tau * tau));
        const Real c = 1.0 / std::sqrt(1.0 + t * t), s = t * c;
        for (int k = 0; k < n; ++k) {
          const Real akp = A(k, p), akq = A(k, q);
          A(k, p) = c * akp - s * akq;
          A(k, q) = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {
          const Real apk = A(p, k), aqk = A(q, k);
          A(p, k) = c * apk - s * aqk;
          A(q, k) = s * apk + c * aqk;
        }
        for (int k = 0; k < n; ++k) {
          const Real qkp = Q(k, p), qkq = Q(k, q);
          Q(k, p) = c * qkp - s * qkq;
          Q(k, q) = s * qkp + c * qkq;
        }
      }
    }
  }
  values.resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) values[static_cast<size_t>(i)] = A(i, i);
}
}  // namespace

Svd svd(const Matrix& J) {
  std::vector<Real> lambda;
  Matrix Q;
  symmetricEigen(gram(J), lambda, Q);
  const int m = J.rows;
  std::vector<int> order(static_cast<size_t>(m));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lambda[static_cast<size_t>(a)] > lambda[static_cast<size_t>(b)]; });
  Svd out;
  const Real sigmaMax = std::sqrt(std::max(0.0, m > 0 ? lambda[static_cast<size_t>(order[0])] : 0.0));
  for (int idx : order) {
    const Real s = std::sqrt(std::max(0.0, lambda[static_cast<size_t>(idx)]));
    std::vector<Real> u(static_cast<size_t>(m));
    for (int r = 0; r < m; ++r) u[static_cast<size_t>(r)] = Q(r, idx);
    out.sigma.push_back(s);
    if (s > 1e-7 * sigmaMax && s > 1e-150) {
      std::vector<Real> v = multiplyTransposed(J, u);
      for (Real& x : v) x /= s;
      out.v.push_back(std::move(v));
    } else {
      out.sigma.back() = 0.0;
      out.v.emplace_back();
    }
    out.u.push_back(std::move(u));
  }
  return out;
}

}  // namespace pba::ik
