#pragma once
// Cloth self-collision between particles (Ten Minute Physics #15, "Self-collision": a dense spatial hash
// with cell size = spacing built by counting sort, neighbour lists built once per frame, particle–particle
// separation by the thickness). Two particles i, j are kept at least
//   d_min = min(thickness, |x̄_i − x̄_j|)
// apart: the rest distance caps it for particles that are closer than the thickness in the flat cloth
// (mesh neighbours), which would otherwise be pushed apart forever. Each violated pair is separated along
// its axis in proportion to the inverse masses, then friction moves both towards their mean displacement
// over the step (TMP #15's velocity averaging, a fraction in [0, 1]).
//
// The pair list is a Verlet list (particles::NeighbourList: pairs closer than d + skin when built, rebuilt
// only when some particle has moved more than skin/2), queried through the Teschner hash of
// particles/spatial_hash.h — TMP's "query once per frame" with a guarantee: no pair can come within the
// thickness unseen, however fast the cloth moves.
#include <span>
#include <vector>

#include "physics/particles/spatial_hash.h"

namespace pba::cloth {

struct SelfCollisionStats {
  std::size_t contacts = 0;  ///< pairs separated
  Real deepest = 0.0;        ///< [m] deepest overlap before separation
};

class SelfCollision {
 public:
  /// Makes the pair list complete for positions x (call once per substep; cheap when nothing moved far).
  /// thickness [m] > 0; skin [m] > 0 the extra reach (TMP: the distance the cloth travels in a frame).
  void update(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness, Real skin);
  /// One Gauss–Seidel sweep over the pairs. xPrev: positions at the start of the substep (for friction).
  SelfCollisionStats solve(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> inverseMass,
                           Real friction);
  /// Forgets the pair list (after tearing, a reset or a teleport).
  void invalidate() { list_.invalidate(); }
  std::size_t builds() const { return list_.builds(); }
  std::size_t pairs() const { return list_.pairs().size(); }

 private:
  particles::SpatialHash hash_;
  particles::NeighbourList list_;
  std::vector<Real> minDistance_;  ///< d_min of each pair of the list
  Real thickness_ = 0.0;
};

/// Pairs of particles closer than half their d_min (see above): the self_intersections metric. 0 means no
/// layer of the cloth passed through another by more than half the thickness.
std::size_t countSelfIntersections(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness,
                                   particles::SpatialHash& hash);

}  // namespace pba::cloth
