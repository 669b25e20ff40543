#pragma once
// Tearing by vertex splitting. A mesh edge a–b strained beyond the threshold opens a crack through its
// more strained end a, perpendicular to the pull: the triangles around a whose centroids lie on the far
// side of the plane through a with normal (x_b − x_a) keep a; the others get a new particle a' at the same
// place with the same velocity (mass splits with the rest areas, so mass and momentum are conserved).
// The copy of a pinned particle is free: a cloth torn at a pin leaves the pinned part behind.
// Cracks so run across the direction of tension, as in real fabric. Every triangle still names valid
// particles; edges, springs, constraints and bending are rebuilt from the triangles (Mesh layout from
// then on), so the solvers and the renderer see one consistent mesh. A split whose one side would be
// empty (a vertex with all its triangles on one side) is not made.
// (Tearing of cloth meshes in the same spirit: O'Brien & Hodgins 1999 split nodes along a fracture plane;
// Müller et al. 2007's PBD tears by duplicating vertices of overstretched edges.)
#include <cstddef>

#include "physics/cloth/cloth.h"

namespace pba::cloth {

struct TearSettings {
  bool enabled = false;
  Real threshold = 0.5;      ///< strain (l − L)/L of a mesh edge above which the cloth tears; typical 0.3–1
  int maxSplitsPerStep = 8;  ///< bounds the work of one step (the most strained edges go first)
};

/// Splits up to maxSplitsPerStep vertices at the most strained edges beyond the threshold; rebuilds the
/// topology when it split any. Returns the number of splits (Cloth::torn counts them all).
std::size_t tearOverstretched(Cloth& cloth, const TearSettings& settings);

/// Checks the mesh invariants tearing must keep: every triangle names three distinct existing particles,
/// every edge and constraint joins existing particles of a common triangle, every particle array has the
/// same length. Empty when valid, else what is wrong.
std::string checkMeshConsistency(const Cloth& cloth);

}  // namespace pba::cloth
