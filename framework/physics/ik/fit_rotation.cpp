// Least-squares rotation between two point sets (Horn 1987, "Closed-form solution of absolute
// orientation using unit quaternions"): FABRIK's sub-bases and look-ahead (fabrik.cpp).
#include <cmath>

#include <Eigen/Eigenvalues>

#include "physics/ik/solver_internal.h"

namespace pba::ik::detail {

Quat fitRotation(const std::vector<Vec3>& from, const std::vector<Vec3>& to, const std::vector<Real>& w,
                 const Quat& reference) {
  // Horn 1987: Σ wᵢ toᵢ · (R fromᵢ) = qᵀ N q over unit quaternions q, with N built from
  // S = Σ wᵢ fromᵢ toᵢᵀ; the maximum is N's top eigenvector. When the top eigenvalue is (nearly)
  // repeated, every unit q in its eigenspace is optimal: take the one nearest the reference (its
  // projection onto the eigenspace).
  Real S[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  Real scale = 0.0;
  for (size_t i = 0; i < from.size(); ++i) {
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) S[r][k] += w[i] * from[i][r] * to[i][k];
    scale += w[i] * glm::length(from[i]) * glm::length(to[i]);
  }
  if (!(scale > 0.0)) return reference;
  const Real xx = S[0][0], xy = S[0][1], xz = S[0][2], yx = S[1][0], yy = S[1][1], yz = S[1][2], zx = S[2][0],
             zy = S[2][1], zz = S[2][2];
  Eigen::Matrix4d N;
  N << xx + yy + zz, yz - zy, zx - xz, xy - yx,  //
      yz - zy, xx - yy - zz, xy + yx, zx + xz,   //
      zx - xz, xy + yx, -xx + yy - zz, yz + zy,  //
      xy - yx, zx + xz, yz + zy, -xx - yy + zz;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(N);  // eigenvalues ascending
  const Eigen::Vector4d& values = eigen.eigenvalues();
  const Eigen::Matrix4d& V = eigen.eigenvectors();
  const Real top = values(3);
  const Eigen::Vector4d ref(reference.w, reference.x, reference.y, reference.z);
  Eigen::Vector4d q = Eigen::Vector4d::Zero();
  for (int k = 0; k < 4; ++k)
    if (values(k) >= top - 1e-9 * scale) q += V.col(k).dot(ref) * V.col(k);
  if (!(q.norm() > 1e-6)) q = V.col(3);  // the reference is (nearly) orthogonal to the optimal set: any optimum
  q.normalize();
  return Quat(q(0), q(1), q(2), q(3));
}

}  // namespace pba::ik::detail
