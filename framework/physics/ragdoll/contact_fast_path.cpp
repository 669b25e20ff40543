#include "physics/ragdoll/contact_fast_path.h"

#include <array>
#include <cstdlib>

#include "physics/core/lanes.h"
#include "physics/exercises/not_implemented.h"  // the switch of the isolation build (student_release.sh)
#include "physics/ragdoll/exercises.h"

namespace pba::ragdoll {

void pushOutOfGroundScalar(std::span<const GroundContact> contacts, std::span<Vec3> x) {
  for (const GroundContact& c : contacts) {
    std::array<Vec3, 4> p{x[c.first], x[c.first + 1], x[c.first + 2], x[c.first + 3]};
    ContactSide bone{&p, c.weights, c.mass}, ground{};
    resolveDeepestContact(bone, ground, kUp, c.depth);  // RAG-4
    for (int k = 0; k < 4; ++k) x[c.first + k] = p[k];
  }
}

// Fast path of RAG-4 against the ground: two contacts of different bones (disjoint particles) commute, so
// they go together in the two lanes of a Pair: one packed division for both scales, the moves of two
// particles per instruction, and the bone's particles moved in place (the scalar route copies them out and
// back). Each lane does RAG-4's IEEE operations in its order (the push, A's whole share of it, the sum of
// the squared weights from 0, its reciprocal, each particle's weight times it times the share), and a lane
// whose weights sum to 0 writes nothing, as RAG-4 does; so the results are those of pushOutOfGroundScalar to
// the bit. A contact whose neighbour shares its bone goes alone (lane 1 repeats lane 0 and is dropped).
// flatten: the lambda below inlines into the loop.
[[gnu::flatten]] void pushOutOfGroundFast(std::span<const GroundContact> contacts, std::span<Vec3> x) {
  // BEGIN SOLUTION
  const auto push = [&](const GroundContact& p, const GroundContact& q, bool lane1) {
    const Pair depth{p.depth, q.depth};
    const Pair dx = 1.0 * (depth * kUp.x), dy = 1.0 * (depth * kUp.y), dz = 1.0 * (depth * kUp.z);
    Pair sum{0.0, 0.0};
    for (int k = 0; k < 4; ++k) {
      const Pair c{p.weights[k], q.weights[k]};
      sum = sum + c * c;
    }
    const bool move0 = sum[0] > 0.0, move1 = lane1 && sum[1] > 0.0;
    const Pair lambda = 1.0 / Pair{move0 ? sum[0] : 1.0, move1 ? sum[1] : 1.0};
    for (int k = 0; k < 4; ++k) {
      const Pair scale = Pair{p.weights[k], q.weights[k]} * lambda;
      const PairVec3 moved = gatherPair(x.data(), p.first + k, q.first + k);
      const Pair mx = moved.x + scale * dx, my = moved.y + scale * dy, mz = moved.z + scale * dz;
      if (move0) x[p.first + k] = Vec3(mx[0], my[0], mz[0]);
      if (move1) x[q.first + k] = Vec3(mx[1], my[1], mz[1]);
    }
  };
  const std::size_t n = contacts.size();
  std::size_t i = 0;
  for (; i + 1 < n; i += 2) {
    const GroundContact &p = contacts[i], &q = contacts[i + 1];
    if (std::abs(p.first - q.first) >= 4) {
      push(p, q, true);
    } else {
      push(p, p, false);
      push(q, q, false);
    }
  }
  if (i < n) push(contacts[i], contacts[i], false);
  // END SOLUTION
  // FAST PATH: RAG-4 (the hand-out runs your resolveDeepestContact for each bone)
  // STUB: pushOutOfGroundScalar(contacts, x);
}

}  // namespace pba::ragdoll
