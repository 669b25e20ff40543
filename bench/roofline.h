#pragma once
// A roofline measured in the running benchmark process (Williams, Waterman & Patterson 2009): the
// memory bandwidth at a given footprint (a STREAM-like triad) and the double-precision arithmetic rate
// (independent multiply-adds in registers), each the best of many short passes. A kernel that moves B bytes and
// does F flops per item cannot take less than max(B / bandwidth, F / arithmetic rate) per item; the
// ratio of the measured time to that floor says how far the code is from what the core allows.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

#include <benchmark/benchmark.h>

namespace pba::bench {

struct Roofline {
  double bytesPerNs = 0.0;  ///< triad bandwidth at the footprint [B/ns = GB/s]
  double flopsPerNs = 0.0;  ///< double-precision multiply-adds [flop/ns = GFLOP/s]

  /// The floor on one item that moves `bytes` and does `flops` [ns].
  double floorNs(double bytes, double flops) const { return std::max(bytes / bytesPerNs, flops / flopsPerNs); }
  /// Whether that floor is the memory's (else the arithmetic's).
  bool memoryBound(double bytes, double flops) const { return bytes / bytesPerNs >= flops / flopsPerNs; }
};

/// a = b + s·c (STREAM's triad): 24 bytes moved per element (two reads, one write).
inline void triad(std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c, double s) {
  double* __restrict pa = a.data();
  const double* __restrict pb = b.data();
  const double* __restrict pc = c.data();
  for (std::size_t i = 0; i < a.size(); ++i) pa[i] = pb[i] + s * pc[i];
  benchmark::DoNotOptimize(a.data());
  benchmark::ClobberMemory();
}

namespace detail {
template <typename Kernel>
double bestSeconds(int passes, Kernel&& kernel) {
  double best = 1e300;
  for (int pass = 0; pass < passes; ++pass) {
    const auto start = std::chrono::steady_clock::now();
    kernel();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}
}  // namespace detail

/// Measures the roofline with triad arrays of `doublesPerArray` each (three arrays: pick the footprint
/// of the kernel being judged, so that the bandwidth is that of the cache level it lives in).
inline Roofline measureRoofline(std::size_t doublesPerArray) {
  Roofline r;
  std::vector<double> a(doublesPerArray, 0.0), b(doublesPerArray, 1.0), c(doublesPerArray, 2.0);
  const double triadSeconds = detail::bestSeconds(100, [&] { triad(a, b, c, 3.0); });
  r.bytesPerNs = 24.0 * static_cast<double>(doublesPerArray) / (triadSeconds * 1e9);
  // acc ← acc·m + k on 32 independent accumulators kept in registers: no memory traffic, and enough
  // independent chains to cover the multiply and add latencies (16 were latency-bound at half the rate
  // here). 2 flops per accumulator and round. Short passes, many of them: the best one ran unpreempted.
  constexpr int kChains = 32, kRounds = 5000;
  double m = 0.999999, k = 1e-7;
  benchmark::DoNotOptimize(m);
  benchmark::DoNotOptimize(k);
  const double arithmetic = detail::bestSeconds(300, [&] {
    double acc[kChains];
    for (int j = 0; j < kChains; ++j) acc[j] = 1.0 + j;
    for (int round = 0; round < kRounds; ++round) {
      for (int j = 0; j < kChains; ++j) acc[j] = acc[j] * m + k;
    }
    for (int j = 0; j < kChains; ++j) benchmark::DoNotOptimize(acc[j]);
  });
  r.flopsPerNs = 2.0 * kChains * kRounds / (arithmetic * 1e9);
  return r;
}

}  // namespace pba::bench
