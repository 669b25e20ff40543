// Least-squares rotation between two point sets (Horn 1987, "Closed-form solution of absolute
// orientation using unit quaternions"): FABRIK's sub-bases and look-ahead (fabrik.cpp).
#include <cmath>

#include "physics/ik/solver_internal.h"

namespace pba::ik::detail {
namespace {

// Cyclic Jacobi on a symmetric 4 × 4 matrix: on return a's diagonal holds the eigenvalues and v's
// columns the eigenvectors.
void eigenSymmetric4(Real a[4][4], Real v[4][4]) {
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < 4; ++q) v[p][q] = p == q ? 1.0 : 0.0;
  for (int sweep = 0; sweep < 20; ++sweep) {
    Real off = 0.0, diag = 0.0;
    for (int p = 0; p < 4; ++p) {
      diag += a[p][p] * a[p][p];
      for (int q = p + 1; q < 4; ++q) off += a[p][q] * a[p][q];
    }
    if (off <= 1e-26 * diag || off == 0.0) break;  // off-diagonal below 1e-13 of the diagonal
    const Real small = 1e-15 * std::sqrt(diag);
    for (int p = 0; p < 4; ++p)
      for (int q = p + 1; q < 4; ++q) {
        if (std::abs(a[p][q]) <= small) continue;
        const Real theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const Real t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const Real cs = 1.0 / std::sqrt(t * t + 1.0), sn = t * cs;
        for (int k = 0; k < 4; ++k) {  // A ← A G (columns p, q)
          const Real akp = a[k][p], akq = a[k][q];
          a[k][p] = cs * akp - sn * akq;
          a[k][q] = sn * akp + cs * akq;
        }
        for (int k = 0; k < 4; ++k) {  // A ← Gᵀ A (rows p, q)
          const Real apk = a[p][k], aqk = a[q][k];
          a[p][k] = cs * apk - sn * aqk;
          a[q][k] = sn * apk + cs * aqk;
        }
        for (int k = 0; k < 4; ++k) {  // V ← V G
          const Real vkp = v[k][p], vkq = v[k][q];
          v[k][p] = cs * vkp - sn * vkq;
          v[k][q] = sn * vkp + cs * vkq;
        }
      }
  }
}

}  // namespace

Quat fitRotation(const std::vector<Vec3>& from, const std::vector<Vec3>& to, const std::vector<Real>& w, const Quat& reference) {
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
  const Real xx = S[0][0], xy = S[0][1], xz = S[0][2], yx = S[1][0], yy = S[1][1], yz = S[1][2], zx = S[2][0], zy = S[2][1],
             zz = S[2][2];
  Real N[4][4] = {{xx + yy + zz, yz - zy, zx - xz, xy - yx},
                  {yz - zy, xx - yy - zz, xy + yx, zx + xz},
                  {zx - xz, xy + yx, -xx + yy - zz, yz + zy},
                  {xy - yx, zx + xz, yz + zy, -xx - yy + zz}};
  Real V[4][4];
  eigenSymmetric4(N, V);
  Real top = N[0][0];
  int best = 0;
  for (int k = 1; k < 4; ++k)
    if (N[k][k] > top) top = N[k][k], best = k;
  const Real ref[4] = {reference.w, reference.x, reference.y, reference.z};
  Real q[4] = {0, 0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    if (N[k][k] < top - 1e-9 * scale) continue;
    Real along = 0.0;
    for (int i = 0; i < 4; ++i) along += V[i][k] * ref[i];
    for (int i = 0; i < 4; ++i) q[i] += along * V[i][k];
  }
  Real length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(length > 1e-6)) {  // the reference is (nearly) orthogonal to the optimal set: any optimum
    for (int i = 0; i < 4; ++i) q[i] = V[i][best];
    length = 1.0;
  }
  return Quat(q[0] / length, q[1] / length, q[2] / length, q[3] / length);
}

}  // namespace pba::ik::detail
