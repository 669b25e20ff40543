#pragma once
// RAG-4's fast path (docs/architecture.md §5, "Fast paths"): the particle ragdoll's bones pushed out of the
// ground, once as the student's scalar route (RAG-4 per bone) and once as the reference build's faster
// kernel. Both give the same results to the bit (tests/physics/ragdoll/ragdoll_contact_fast_path_test.cpp);
// in the hand-out the fast one runs the scalar one.
#include <span>

#include "physics/core/types.h"
#include "physics/ragdoll/tetrahedron.h"

namespace pba::ragdoll {

/// One bone below the ground plane: its particles first .. first + 3, the contact point's barycentric
/// weights, how deep the point is [m] (≥ 0) and the bone's mass [kg].
struct GroundContact {
  int first = 0;
  Weights weights{0.25, 0.25, 0.25, 0.25};
  Real depth = 0.0;
  Real mass = 1.0;
};

/// RAG-4 (resolveDeepestContact) for each contact in order, the ground as side B and the normal +y.
void pushOutOfGroundScalar(std::span<const GroundContact> contacts, std::span<Vec3> x);
/// The same pushes with the same results, faster (two bones per instruction). Contacts of one bone may
/// repeat; the hand-out runs pushOutOfGroundScalar here.
void pushOutOfGroundFast(std::span<const GroundContact> contacts, std::span<Vec3> x);

}  // namespace pba::ragdoll
