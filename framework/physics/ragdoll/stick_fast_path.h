#pragma once
// RAG-1's fast path (docs/architecture.md §5, "Fast paths"): the particle ragdoll's stick relaxation, once
// as the student's scalar route (RAG-1 per stick) and once as the reference build's faster kernel. Both
// give the same results to the bit (tests/physics/ragdoll/ragdoll_stick_fast_path_test.cpp); in the
// hand-out the fast one runs the scalar one.
#include <span>

#include "physics/core/types.h"

namespace pba::ragdoll {

/// A stick of the particle ragdoll: particles a and b held `rest` [m] apart (RAG-1).
struct Stick {
  int a = 0, b = 0;
  Real rest = 0.0;
};

/// `sweeps` Gauss–Seidel sweeps of RAG-1 (projectStick) over `sticks` in their order; w: inverse masses.
void relaxSticksScalar(std::span<const Stick> sticks, std::span<Vec3> x, std::span<const Real> w, int sweeps);
/// The same sweeps with the same results, faster (two bones' sticks per instruction). The hand-out runs
/// relaxSticksScalar here.
void relaxSticksFast(std::span<const Stick> sticks, std::span<Vec3> x, std::span<const Real> w, int sweeps);

}  // namespace pba::ragdoll
