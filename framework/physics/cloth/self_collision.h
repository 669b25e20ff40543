#pragma once
// Cloth self-collision between particles (Ten Minute Physics #15, "Self-collision"): a dense spatial hash
// (cells of the query distance, filled by counting sort: particles/spatial_hash.h, Teschner et al. 2003),
// the list of nearby pairs built once per frame, and in every substep each pair closer than the thickness
// pushed apart along its axis in proportion to the inverse masses; friction then moves both towards their
// mean displacement over the substep (TMP's velocity averaging, a fraction in [0, 1]).
//
// Which pairs: particles whose rest distance |x̄_i − x̄_j| is below 1.5 × thickness are the cloth's own
// neighbours (the edges and quad diagonals of a mesh whose spacing is the thickness, as in TMP): the
// distance and bending constraints keep those apart, and including them would push compressed neighbours
// apart forever. Every other pair is kept at least the thickness apart.
//
// Why once per frame: TMP bounds each particle's speed by 0.2 thickness per substep
// (ClothSolverSettings::selfCollisionMaxTravel) and queries, once per frame, the pairs closer than the
// farthest a particle can travel in the frame (0.2 n thickness for n substeps). We query one thickness
// farther (measured on the 30 × 200 ribbon: TMP's distance alone let 5 pairs pass within half the
// thickness, this one none). A heuristic, not a guarantee: two particles rushing at each other could meet
// unseen; the self_intersections metric checks what actually happens.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "physics/particles/spatial_hash.h"

namespace pba::cloth {

/// Rest distance [in thicknesses] below which two particles are neighbours, not candidates.
inline constexpr Real kSelfNeighbourFactor = 1.5;

struct SelfCollisionStats {
  std::size_t contacts = 0;  ///< pairs separated
  Real deepest = 0.0;        ///< [m] deepest overlap before separation
};

class SelfCollision {
 public:
  /// Collects every candidate pair closer than `reach` [m] (≥ thickness) at positions x: once per frame.
  void buildPairs(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness, Real reach);
  /// One Gauss–Seidel sweep over the pairs. xPrev: positions at the start of the substep (for friction).
  SelfCollisionStats solve(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> inverseMass,
                           Real thickness, Real friction) const;
  std::size_t pairs() const { return pairs_.size(); }

 private:
  particles::SpatialHash hash_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
};

/// Pairs of non-neighbouring particles (rest distance ≥ 1.5 thickness) closer than half the thickness:
/// the self_intersections metric. 0 means no layer passed through another by more than half the thickness.
std::size_t countSelfIntersections(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness,
                                   particles::SpatialHash& hash);

}  // namespace pba::cloth
