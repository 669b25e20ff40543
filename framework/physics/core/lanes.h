#pragma once
// Two doubles in one register (GCC's vector extension, which Clang shares): SSE2's packed doubles on
// x86-64, plain scalar code on targets without them. The kernels that use it (the cloth's Verlet list
// search, the fountain's motion) run two particles per instruction with the scalar code's operations in
// its order, so their results are bit for bit those of the scalar code; a division becomes one divpd for
// two particles.
#include <cstddef>
#include <cstring>

#include "physics/core/types.h"

namespace pba {

using Pair [[gnu::vector_size(2 * sizeof(Real))]] = Real;

/// Two consecutive doubles from memory (no alignment needed).
inline Pair loadPair(const Real* from) {
  Pair v;
  std::memcpy(&v, from, sizeof v);
  return v;
}
inline Pair splat(Real a) { return Pair{a, a}; }
/// What comparing two Pairs gives: per lane all bits set (true) or none (false).
using PairMask = decltype(Pair{} < Pair{});

/// One coordinate of two points a[i] and a[j] (j may equal i).
struct PairVec3 {
  Pair x, y, z;
};
inline PairVec3 gatherPair(const Vec3* a, std::size_t i, std::size_t j) {
  return {Pair{a[i].x, a[j].x}, Pair{a[i].y, a[j].y}, Pair{a[i].z, a[j].z}};
}
/// Lane `lane` (0 or 1) of p as a point.
inline Vec3 lane(const PairVec3& p, int lane) { return Vec3(p.x[lane], p.y[lane], p.z[lane]); }

}  // namespace pba
