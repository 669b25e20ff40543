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
// Which pairs are swept, two ways (ClothSolverSettings::selfCollisionNearList):
//   - TMP's, the published form (nearList false): F, the pairs closer than the reach at the start of the
//     frame, swept in every substep in the order of TMP's query (by i, then the 27 cells around i in turn,
//     each cell's particles by index). TMP bounds each particle's speed by 0.2 thickness per substep
//     (ClothSolverSettings::selfCollisionMaxTravel) and queries the pairs closer than the farthest a
//     particle can travel in the frame (0.2 n thickness for n substeps); we query one thickness farther
//     (TMP's distance alone can let a pair pass within half the thickness; docs/performance-cloth.md).
//     A heuristic, not a guarantee: two particles rushing at each other could meet unseen. Piled up, F
//     holds far more pairs than touch, and every substep checks them all.
//   - A Verlet list (Verlet 1967; Allen & Tildesley, "Computer Simulation of Liquids", §5.3), the default:
//     the pairs closer than thickness + s (the skin) when the list was built, kept across substeps and
//     frames. Before each sweep every particle's distance from where it was at the build is checked; when
//     one has gone more than s/2, the list is built again. A pair left out was at least thickness + s apart
//     and each of its particles has moved at most s/2 since, so it is not touching when the sweep starts:
//     every pair in contact at the start of a sweep is swept (TMP's reach has no such guarantee). Pairs
//     that a sweep's own pushes bring into contact are met at the next sweep, as in TMP.
//     The sweep visits the list in grid order, so its Gauss–Seidel order, and with it the rounding and
//     the trajectory, differs from TMP's; the projection of each pair is the same.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "physics/cloth/dense_grid.h"
#include "physics/cloth/sorted_grid.h"
#include "physics/particles/spatial_hash.h"

namespace pba::cloth {

/// Rest distance [in thicknesses] below which two particles are neighbours, not candidates.
inline constexpr Real kSelfNeighbourFactor = 1.5;
/// The Verlet list's skin s [in thicknesses]: a longer list against fewer builds.
inline constexpr Real kSelfSkinFactor = 0.75;

struct SelfCollisionStats {
  std::size_t contacts = 0;  ///< pairs separated
  Real deepest = 0.0;        ///< [m] deepest overlap before separation
};

class SelfCollision {
 public:
  /// Once per frame, at positions x. nearList false: collects F, every candidate pair closer than `reach`
  /// [m] (≥ thickness), for TMP's sweep. nearList true: keeps the Verlet list unless the rest shape or the
  /// thickness changed (reach is not used).
  void buildPairs(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness, Real reach,
                  bool nearList = true);
  /// One Gauss–Seidel sweep over the pairs. xPrev: positions at the start of the substep (for friction).
  /// again: a further sweep in the same substep, over the pairs the last full sweep found in contact only.
  SelfCollisionStats solve(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> inverseMass,
                           Real thickness, Real friction, bool again = false);
  std::size_t framePairs() const { return pairs_.size(); }  ///< F (TMP's sweep; 0 with the Verlet list)
  std::size_t nearPairs() const { return near_.size(); }    ///< the Verlet list now
  std::size_t nearBuilds() const { return nearBuilds_; }    ///< Verlet lists built since the frame began
  /// The particles of the pairs the last full sweep found in contact (repeats possible).
  std::span<const std::uint32_t> contactParticles() const {
    static_assert(sizeof(std::array<std::uint32_t, 2>) == 2 * sizeof(std::uint32_t));
    return {contacts_.empty() ? nullptr : contacts_.front().data(), 2 * contacts_.size()};
  }
  /// The Verlet list's pairs (i, j), i < j, in sweep order.
  std::span<const std::array<std::uint32_t, 2>> nearList() const { return near_; }

 private:
  /// One sweep over `pairs` (i, j); with `record`, the pairs in contact go to contacts_.
  template <typename Pairs>
  SelfCollisionStats sweep(const Pairs& pairs, std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> w,
                           Real thickness, Real friction, bool record);
  /// The pairs closer than thickness + s at x, not neighbours at rest; remembers x.
  void buildNearList(std::span<const Vec3> x);
  /// Some particle's displacement since the list's build, less the displacement common to all (the
  /// centre of their bounding box), is longer than s/2.
  bool movedPastHalfTheSkin(std::span<const Vec3> x) const;
  /// Lists all of F (pairs_), in TMP's order.
  void buildFramePairs();
  /// A pair's place in F's order (i < j): by i, then by the rank of j's cell among the 27 cells of i's query
  /// (TMP's order: the cells in turn, each cell's particles by index), then by j.
  std::uint64_t key(std::uint32_t i, std::uint32_t j) const;

  SortedGrid wide_;                                ///< TMP's sweep: cells of the reach at the frame's start
  std::vector<std::array<std::int64_t, 3>> cell_;  ///< TMP's sweep, per particle: its cell in wide_
  std::vector<std::uint32_t> bucket_;              ///< TMP's sweep, per particle: its bucket in wide_
  std::vector<std::uint8_t> shared_;  ///< TMP's sweep, per particle: two of its query's 27 cells share a bucket
  std::vector<std::uint64_t> pairs_;  ///< F as keys (i, rank, j)
  std::vector<Vec3> start_;           ///< [m] TMP's sweep: positions at the frame's start
  DenseGrid narrow_;                  ///< the Verlet list's search: cells of thickness + s
  std::vector<std::array<std::uint32_t, 2>> near_;        ///< the Verlet list
  std::vector<Vec3> rest_;                                ///< [m] rest positions
  std::vector<Vec3> builtAt_;                             ///< [m] positions at the Verlet list's build
  std::array<std::vector<Real>, 6> byCoordinate_;         ///< [m] x, y, z, rest x, y, z in narrow_'s order (+ padding)
  std::vector<std::uint32_t> particleOf_;                 ///< narrow_'s entry → particle (+ padding)
  std::vector<std::array<std::uint32_t, 2>> candidates_;  ///< scratch of the Verlet list's build
  std::vector<std::array<std::uint32_t, 2>> contacts_;    ///< pairs in contact in the last full sweep
  Real thickness_ = 0.0, reach_ = 0.0;                    ///< [m] of the frame
  Real skin_ = 0.0;                                       ///< [m] the Verlet list's skin s
  bool nearList_ = true, nearBuilt_ = false;
  std::size_t nearBuilds_ = 0;
};

/// Pairs of non-neighbouring particles (rest distance ≥ 1.5 thickness) closer than half the thickness:
/// the self_intersections metric. 0 means no layer passed through another by more than half the thickness.
std::size_t countSelfIntersections(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness,
                                   particles::SpatialHash& hash);

}  // namespace pba::cloth
