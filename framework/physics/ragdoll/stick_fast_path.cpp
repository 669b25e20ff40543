#include "physics/ragdoll/stick_fast_path.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "physics/core/lanes.h"
#include "physics/exercises/not_implemented.h"  // the switch of the isolation build (student_release.sh)
#include "physics/ragdoll/exercises.h"

namespace pba::ragdoll {

void relaxSticksScalar(std::span<const Stick> sticks, std::span<Vec3> x, std::span<const Real> w, int sweeps) {
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (const Stick& s : sticks) projectStick(x[s.a], x[s.b], w[s.a], w[s.b], s.rest);  // RAG-1
}

// Fast path of RAG-1: a bone's six sticks share its four particles, so they form a chain of dependent
// square roots and divisions; the next bone's six touch other particles. Two runs of six consecutive sticks
// whose particles are disjoint commute exactly in a Gauss–Seidel sweep (neither reads what the other
// writes), so stick s of the first and stick s of the second run together in the two lanes of a Pair, in
// the sticks' order within each run. Each lane does RAG-1's IEEE operations in its order and a skipped
// stick (both ends pinned, coincident ends) writes nothing, as RAG-1 does, so the results are those of
// relaxSticksScalar to the bit. Sticks that do not fall into such runs go one at a time (lane 1 repeats
// lane 0 and is dropped).
// flatten: the two lambdas below inline into the loop (GCC kept `project` a call).
[[gnu::flatten]] void relaxSticksFast(std::span<const Stick> sticks, std::span<Vec3> x, std::span<const Real> w,
                                      int sweeps) {
  // BEGIN SOLUTION
  constexpr std::size_t kRun = 6;  // a tetrahedron's sticks
  const auto particleRange = [&](std::size_t first) {
    int low = sticks[first].a, high = low;
    for (std::size_t k = first; k < first + kRun; ++k) {
      low = std::min({low, sticks[k].a, sticks[k].b});
      high = std::max({high, sticks[k].a, sticks[k].b});
    }
    return std::array<int, 2>{low, high};
  };
  // Sticks p (lane 0) and q (lane 1); q == p runs p alone.
  const auto project = [&](const Stick& p, const Stick& q) {
    const Pair dx = Pair{x[p.b].x, x[q.b].x} - Pair{x[p.a].x, x[q.a].x};
    const Pair dy = Pair{x[p.b].y, x[q.b].y} - Pair{x[p.a].y, x[q.a].y};
    const Pair dz = Pair{x[p.b].z, x[q.b].z} - Pair{x[p.a].z, x[q.a].z};
    const Pair xx = dx * dx, yy = dy * dy, zz = dz * dz;  // glm::dot's order, unfused
    const Pair squared = xx + yy + zz;
    const Pair root = sqrtPair(squared);
    const Real lp = root[0], lq = root[1];
    const Pair wa{w[p.a], w[q.a]}, wb{w[p.b], w[q.b]};
    const Pair wSum = wa + wb;
    const bool moveP = wSum[0] > 0.0 && lp > 1e-12, moveQ = &p != &q && wSum[1] > 0.0 && lq > 1e-12;
    const Pair length{moveP ? lp : 1.0, moveQ ? lq : 1.0};  // a dropped lane divides by 1, not 0
    const Pair weight{moveP ? wSum[0] : 1.0, moveQ ? wSum[1] : 1.0};
    const Pair s = (length - Pair{p.rest, q.rest}) / (length * weight);
    const Pair cx = s * dx, cy = s * dy, cz = s * dz;
    const Pair ax = wa * cx, ay = wa * cy, az = wa * cz, bx = wb * cx, by = wb * cy, bz = wb * cz;
    if (moveP) {
      x[p.a] += Vec3(ax[0], ay[0], az[0]);
      x[p.b] -= Vec3(bx[0], by[0], bz[0]);
    }
    if (moveQ) {
      x[q.a] += Vec3(ax[1], ay[1], az[1]);
      x[q.b] -= Vec3(bx[1], by[1], bz[1]);
    }
  };
  const std::size_t n = sticks.size();
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    std::size_t k = 0;
    while (k < n) {
      if (k + 2 * kRun <= n) {
        const std::array<int, 2> first = particleRange(k), second = particleRange(k + kRun);
        if (first[1] < second[0] || second[1] < first[0]) {
          for (std::size_t s = 0; s < kRun; ++s) project(sticks[k + s], sticks[k + kRun + s]);
          k += 2 * kRun;
          continue;
        }
      }
      project(sticks[k], sticks[k]);
      ++k;
    }
  }
  // END SOLUTION
  // FAST PATH: RAG-1 (the hand-out runs your projectStick over the sticks)
  // STUB: relaxSticksScalar(sticks, x, w, sweeps);
}

}  // namespace pba::ragdoll
