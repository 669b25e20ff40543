#pragma once
// Two doubles in one register (GCC's vector extension, which Clang shares): SSE2's packed doubles on
// x86-64, plain scalar code on targets without them. The kernels that use it (the cloth's Verlet list
// search, the fountain's motion) run two particles per instruction with the scalar code's operations in
// its order, so their results are bit for bit those of the scalar code; a division becomes one divpd for
// two particles.
//
// Compilers without the extension (MSVC) get a plain two-element struct with the same operators, lane
// by lane: the same IEEE operations in the same order, so the same bits, only without the packing.
// PBA_PORTABLE_LANES forces that path on GCC and Clang too (the libc++ preset tests it).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "physics/core/types.h"

#if (defined(__GNUC__) || defined(__clang__)) && !defined(PBA_PORTABLE_LANES)
#define PBA_VECTOR_EXTENSION_LANES 1
#endif
#if defined(PBA_VECTOR_EXTENSION_LANES) && defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pba {

#if defined(PBA_VECTOR_EXTENSION_LANES)
using Pair [[gnu::vector_size(2 * sizeof(Real))]] = Real;
#else
/// Per lane all bits set (true, -1) or none (false, 0), as the vector extension's comparisons give.
struct PairMask {
  std::int64_t lane[2];
  std::int64_t operator[](int i) const { return lane[i]; }
};
inline PairMask operator&(PairMask a, PairMask b) { return {{a.lane[0] & b.lane[0], a.lane[1] & b.lane[1]}}; }
inline PairMask& operator|=(PairMask& a, PairMask b) {
  a.lane[0] |= b.lane[0];
  a.lane[1] |= b.lane[1];
  return a;
}

struct Pair {
  Real lane[2];
  Real operator[](int i) const { return lane[i]; }
};
// Each operator applies the scalar operation to lane 0, then lane 1; a scalar operand counts for both.
#define PBA_PAIR_ARITHMETIC(op)                                                                          \
  inline Pair operator op(Pair a, Pair b) { return {{a.lane[0] op b.lane[0], a.lane[1] op b.lane[1]}}; } \
  inline Pair operator op(Pair a, Real b) { return {{a.lane[0] op b, a.lane[1] op b}}; }                 \
  inline Pair operator op(Real a, Pair b) { return {{a op b.lane[0], a op b.lane[1]}}; }                 \
  inline Pair& operator op##=(Pair& a, Pair b) { return a = a op b; }                                    \
  inline Pair& operator op##=(Pair& a, Real b) { return a = a op b; }
PBA_PAIR_ARITHMETIC(+)
PBA_PAIR_ARITHMETIC(-)
PBA_PAIR_ARITHMETIC(*)
PBA_PAIR_ARITHMETIC(/)
#undef PBA_PAIR_ARITHMETIC
inline Pair operator-(Pair a) { return {{-a.lane[0], -a.lane[1]}}; }
#define PBA_PAIR_COMPARISON(op)                                                                              \
  inline PairMask operator op(Pair a, Pair b) {                                                              \
    return {{a.lane[0] op b.lane[0] ? std::int64_t{-1} : 0, a.lane[1] op b.lane[1] ? std::int64_t{-1} : 0}}; \
  }                                                                                                          \
  inline PairMask operator op(Pair a, Real b) { return a op Pair{{b, b}}; }
PBA_PAIR_COMPARISON(<)
PBA_PAIR_COMPARISON(<=)
PBA_PAIR_COMPARISON(>)
PBA_PAIR_COMPARISON(>=)
#undef PBA_PAIR_COMPARISON
#endif

/// Two consecutive doubles from memory (no alignment needed).
inline Pair loadPair(const Real* from) {
  Pair v;
  std::memcpy(&v, from, sizeof v);
  return v;
}
inline Pair splat(Real a) { return Pair{a, a}; }
#if defined(PBA_VECTOR_EXTENSION_LANES)
/// What comparing two Pairs gives: per lane all bits set (true) or none (false).
using PairMask = decltype(Pair{} < Pair{});
#endif

/// The square roots of both lanes: sqrtpd where SSE2 and the vector extension are there, else one
/// std::sqrt per lane. Both are IEEE's correctly rounded square root, so the same bits; a negative lane
/// gives NaN either way (sqrtpd sets no errno).
inline Pair sqrtPair(Pair a) {
#if defined(PBA_VECTOR_EXTENSION_LANES) && defined(__SSE2__)
  return reinterpret_cast<Pair>(_mm_sqrt_pd(reinterpret_cast<__m128d>(a)));
#else
  return Pair{std::sqrt(a[0]), std::sqrt(a[1])};
#endif
}

/// Lane by lane a where `mask` is set, else b: both are computed, nothing branches (andpd/andnpd/orpd under
/// SSE2). The bits of the chosen lane are kept as they are (−0 stays −0).
inline Pair selectPair(PairMask mask, Pair a, Pair b) {
#if defined(PBA_VECTOR_EXTENSION_LANES) && defined(__SSE2__)
  const __m128d m = reinterpret_cast<__m128d>(mask);
  return reinterpret_cast<Pair>(
      _mm_or_pd(_mm_and_pd(m, reinterpret_cast<__m128d>(a)), _mm_andnot_pd(m, reinterpret_cast<__m128d>(b))));
#else
  return Pair{mask[0] ? a[0] : b[0], mask[1] ? a[1] : b[1]};
#endif
}
/// Whether some lane of `mask` is set.
inline bool anyLane(PairMask mask) { return (mask[0] | mask[1]) != 0; }

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
