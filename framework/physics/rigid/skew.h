#pragma once
// The cross-product matrix [v]× and products with it that skip the multiplications by its zero diagonal.
// Each entry is the sum of the same nonzero products, in the same order, as glm's general product with
// skew(v) (a product with an exact zero adds ±0, which changes nothing), so the results have the same
// bits (only an exact zero may differ in sign).
#include "physics/core/types.h"

namespace pba::rigid {

/// [v]× with [v]× u = v × u (glm is column-major).
inline Mat3 skew(const Vec3& v) { return Mat3(0.0, v.z, -v.y, -v.z, 0.0, v.x, v.y, -v.x, 0.0); }

/// skew(r) · m: column c is r × (column c of m). 27 flops instead of 45.
inline Mat3 skewTimes(const Vec3& r, const Mat3& m) {
  Mat3 t;
  for (int c = 0; c < 3; ++c) {
    t[c][0] = -r.z * m[c][1] + r.y * m[c][2];
    t[c][1] = r.z * m[c][0] + -r.x * m[c][2];
    t[c][2] = -r.y * m[c][0] + r.x * m[c][1];
  }
  return t;
}

/// (skew(r) · m) · skew(r) = [r]× m [r]×. 54 flops instead of 90.
inline Mat3 skewSandwich(const Vec3& r, const Mat3& m) {
  const Mat3 t = skewTimes(r, m);
  Mat3 u;
  for (int i = 0; i < 3; ++i) {  // u = t [r]×, row i at a time
    u[0][i] = t[1][i] * r.z + t[2][i] * -r.y;
    u[1][i] = t[0][i] * -r.z + t[2][i] * r.x;
    u[2][i] = t[0][i] * r.y + t[1][i] * -r.x;
  }
  return u;
}

}  // namespace pba::rigid
