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

struct SvdWorkspace::Impl {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd;
};
SvdWorkspace::SvdWorkspace() : impl_(std::make_unique<Impl>()) {}
SvdWorkspace::~SvdWorkspace() = default;

void svd(const Matrix& J, Svd& out, SvdWorkspace& workspace) {
  out.sigma.clear();
  if (J.rows == 0 || J.cols == 0) {
    out.u.clear();
    out.v.clear();
    return;
  }
  Eigen::JacobiSVD<Eigen::MatrixXd>& d = workspace.impl().svd;
  d.compute(view(J), Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = d.singularValues();
  const Real zero = Real(std::max(J.rows, J.cols)) * std::numeric_limits<Real>::epsilon() * (s.size() ? s(0) : 0.0);
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

Svd svd(const Matrix& J) {
  Svd out;
  SvdWorkspace workspace;
  svd(J, out, workspace);
  return out;
}

}  // namespace pba::ik
