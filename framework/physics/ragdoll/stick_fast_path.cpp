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
// square roots and divisions; the next bone's six touch other particles. Runs of six consecutive sticks
// whose particles are disjoint commute exactly in a Gauss–Seidel sweep (neither reads what the other
// writes), so stick s of one run and stick s of another go together in the two lanes of a Pair, in the
// sticks' order within each run. Each lane does RAG-1's IEEE operations in its order and a skipped stick
// (both ends pinned, coincident ends) writes nothing, as RAG-1 does, so the results are those of
// relaxSticksScalar to the bit.
//  * Bones: two runs over four particles each (first .. first + 3) with the same pattern of ends keep
//    their eight particles in lanes for the six sticks (one gather and one scatter per run and sweep
//    instead of one per stick), and kBonePairs such pairs go at once, so that their chains overlap in
//    the processor (one chain is bound by the latency of its square roots and divisions).
//  * Other runs of six with disjoint particles go two at a time through memory, and what is left one
//    stick at a time (lane 1 repeats lane 0 and is dropped).
// flatten: the lambdas below inline into the loop (GCC kept them calls).
[[gnu::flatten]] void relaxSticksFast(std::span<const Stick> sticks, std::span<Vec3> x, std::span<const Real> w,
                                      int sweeps) {
  // BEGIN SOLUTION
  constexpr std::size_t kRun = 6;        // a tetrahedron's sticks
  constexpr std::size_t kBonePairs = 4;  // pairs of bones in flight
  const auto particleRange = [&](std::size_t first) {
    int low = sticks[first].a, high = low;
    for (std::size_t k = first; k < first + kRun; ++k) {
      low = std::min({low, sticks[k].a, sticks[k].b});
      high = std::max({high, sticks[k].a, sticks[k].b});
    }
    return std::array<int, 2>{low, high};
  };
  // One stick in each lane: the ends' coordinates and inverse masses in; the moves of both ends out,
  // and whether each lane moves (RAG-1's two early returns).
  struct Moves {
    Pair ax, ay, az, bx, by, bz;
    bool lane0, lane1;
  };
  const auto solve = [](const PairVec3& a, const PairVec3& b, Pair wa, Pair wb, Pair rest, bool lane1) {
    const Pair dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
    const Pair xx = dx * dx, yy = dy * dy, zz = dz * dz;  // glm::dot's order, unfused
    const Pair squared = xx + yy + zz;
    const Pair root = sqrtPair(squared);
    const Real l0 = root[0], l1 = root[1];
    const Pair wSum = wa + wb;
    const bool move0 = wSum[0] > 0.0 && l0 > 1e-12, move1 = lane1 && wSum[1] > 0.0 && l1 > 1e-12;
    const Pair length{move0 ? l0 : 1.0, move1 ? l1 : 1.0};  // a dropped lane divides by 1, not 0
    const Pair weight{move0 ? wSum[0] : 1.0, move1 ? wSum[1] : 1.0};
    const Pair s = (length - rest) / (length * weight);
    const Pair cx = s * dx, cy = s * dy, cz = s * dz;
    return Moves{wa * cx, wa * cy, wa * cz, wb * cx, wb * cy, wb * cz, move0, move1};
  };
  // Sticks p (lane 0) and q (lane 1) through memory; q == p runs p alone.
  const auto project = [&](const Stick& p, const Stick& q) {
    const Moves m = solve(gatherPair(x.data(), p.a, q.a), gatherPair(x.data(), p.b, q.b), Pair{w[p.a], w[q.a]},
                          Pair{w[p.b], w[q.b]}, Pair{p.rest, q.rest}, &p != &q);
    if (m.lane0) {
      x[p.a] += Vec3(m.ax[0], m.ay[0], m.az[0]);
      x[p.b] -= Vec3(m.bx[0], m.by[0], m.bz[0]);
    }
    if (m.lane1) {
      x[q.a] += Vec3(m.ax[1], m.ay[1], m.az[1]);
      x[q.b] -= Vec3(m.bx[1], m.by[1], m.bz[1]);
    }
  };
  // The group of 2 kBonePairs runs from `first` as bone pairs in lanes: the first run is a bone (four
  // particles low .. low + 3) and every other run is it shifted by at least four more particles than the
  // one before (the same ends at the same places, the ranges ascending, so pairwise disjoint).
  std::array<int, 2 * kBonePairs> low{};
  const auto boneGroup = [&](std::size_t first) {
    const std::array<int, 2> range = particleRange(first);
    if (range[1] - range[0] != 3) return false;
    low[0] = range[0];
    for (std::size_t r = 1; r < 2 * kBonePairs; ++r) {
      const int shift = sticks[first + r * kRun].a - sticks[first].a;
      for (std::size_t s = 0; s < kRun; ++s) {
        const Stick &base = sticks[first + s], &run = sticks[first + r * kRun + s];
        if (run.a != base.a + shift || run.b != base.b + shift) return false;
      }
      low[r] = range[0] + shift;
      if (low[r] < low[r - 1] + 4) return false;
    }
    return true;
  };
  const auto relaxBoneGroup = [&](std::size_t first) {
    std::array<std::array<PairVec3, 4>, kBonePairs> p;  // [bone pair][particle]: the two bones in lanes
    std::array<std::array<Pair, 4>, kBonePairs> inverseMass;
    for (std::size_t g = 0; g < kBonePairs; ++g)
      for (int i = 0; i < 4; ++i) {
        p[g][i] = gatherPair(x.data(), low[2 * g] + i, low[2 * g + 1] + i);
        inverseMass[g][i] = Pair{w[low[2 * g] + i], w[low[2 * g + 1] + i]};
      }
    for (std::size_t s = 0; s < kRun; ++s)
      for (std::size_t g = 0; g < kBonePairs; ++g) {
        const Stick& st = sticks[first + 2 * g * kRun + s];
        const Stick& twin = sticks[first + (2 * g + 1) * kRun + s];
        const int a = st.a - low[2 * g], b = st.b - low[2 * g];
        PairVec3& pa = p[g][a];
        PairVec3& pb = p[g][b];
        const Moves m = solve(pa, pb, inverseMass[g][a], inverseMass[g][b], Pair{st.rest, twin.rest}, true);
        if (m.lane0 && m.lane1) {
          pa.x += m.ax, pa.y += m.ay, pa.z += m.az;
          pb.x -= m.bx, pb.y -= m.by, pb.z -= m.bz;
          continue;
        }
        const auto keep = [](Pair moved, Pair old, bool lane0, bool lane1) {
          return Pair{lane0 ? moved[0] : old[0], lane1 ? moved[1] : old[1]};
        };
        pa = {keep(pa.x + m.ax, pa.x, m.lane0, m.lane1), keep(pa.y + m.ay, pa.y, m.lane0, m.lane1),
              keep(pa.z + m.az, pa.z, m.lane0, m.lane1)};
        pb = {keep(pb.x - m.bx, pb.x, m.lane0, m.lane1), keep(pb.y - m.by, pb.y, m.lane0, m.lane1),
              keep(pb.z - m.bz, pb.z, m.lane0, m.lane1)};
      }
    for (std::size_t g = 0; g < kBonePairs; ++g)
      for (int i = 0; i < 4; ++i) {
        x[low[2 * g] + i] = lane(p[g][i], 0);
        x[low[2 * g + 1] + i] = lane(p[g][i], 1);
      }
  };
  const std::size_t n = sticks.size();
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    std::size_t k = 0;
    while (k < n) {
      if (k + 2 * kBonePairs * kRun <= n && boneGroup(k)) {
        relaxBoneGroup(k);
        k += 2 * kBonePairs * kRun;
        continue;
      }
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
