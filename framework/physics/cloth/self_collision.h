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
//
// F, the frame's pairs i < j, is swept in the order of TMP's query: by i, then the 27 cells around i in
// turn, each cell's particles by index. Sweeping F costs: on the piled-up ribbon F holds ~240,000 pairs, of which ~10,000 are within 1.5
// thicknesses. So a sweep visits a near list instead, a subsequence of F (same order) that provably gives
// the same result as sweeping all of F — a Verlet list (Verlet 1967) with a skin s, checked at run time:
//   - the near list holds the pairs of F closer than thickness + s when it is built (found in cells of that
//     size and put in F's order; F itself is listed only if a sweep needs all of it);
//   - a pair left out can then only touch after its particles moved more than s between them. Each sweep
//     checks, for every particle, how far it is from where it was at the build plus everything the sweep
//     moves it, against s/2. When many went further before the sweep, the list is rebuilt; a particle
//     that went further (before the sweep, or during it: then the sweep is undone and run again) is
//     "untracked" for the rest of the frame: all its pairs of F join the list, in order.
// A pair left out would have been skipped by the full sweep (it is farther than the thickness whenever the
// sweep reaches it), so the positions are bit for bit those of sweeping F; only the cost differs.
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "physics/cloth/dense_grid.h"
#include "physics/cloth/sorted_grid.h"
#include "physics/particles/spatial_hash.h"

namespace pba::cloth {

/// Rest distance [in thicknesses] below which two particles are neighbours, not candidates.
inline constexpr Real kSelfNeighbourFactor = 1.5;
/// The near list's skin s [in thicknesses]: a shorter list against more rebuilds (0.35–1.25 measured on the
/// ribbon: 0.75 fastest).
inline constexpr Real kSelfSkinFactor = 0.75;
/// When more than this share of the particles went too far before a sweep, the near list is rebuilt;
/// fewer are untracked instead.
inline constexpr Real kSelfRebuildShare = 0.05;

struct SelfCollisionStats {
  std::size_t contacts = 0;  ///< pairs separated
  Real deepest = 0.0;        ///< [m] deepest overlap before separation
};

class SelfCollision {
 public:
  /// Collects every candidate pair closer than `reach` [m] (≥ thickness) at positions x: once per frame.
  /// nearList false: every sweep visits all of them (the reference the tests compare with).
  void buildPairs(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness, Real reach,
                  bool nearList = true);
  /// One Gauss–Seidel sweep over the pairs. xPrev: positions at the start of the substep (for friction).
  SelfCollisionStats solve(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> inverseMass,
                           Real thickness, Real friction);
  std::size_t framePairs() const { return pairs_.size(); }   ///< F, once listed (0 until a sweep needs it)
  std::size_t nearPairs() const { return near_.size(); }     ///< the near list now
  std::size_t nearBuilds() const { return nearBuilds_; }     ///< near lists built this frame
  std::size_t fullSweeps() const { return fullSweeps_; }     ///< sweeps over all of F this frame
  std::size_t untracked() const { return untrackedCount_; }  ///< particles untracked this frame

 private:
  struct Undo {
    std::uint32_t particle;
    Vec3 position;
  };
  /// One sweep over `pairs` (keys); with `track`, records what it changes (undo_) and how far it moves
  /// each particle.
  SelfCollisionStats sweep(std::span<const std::uint64_t> pairs, std::span<Vec3> x, std::span<const Vec3> xPrev,
                           std::span<const Real> w, Real thickness, Real friction, bool track);
  /// The pairs of F closer than thickness + s at x and those of untracked particles, in order;
  /// remembers x.
  void buildNearList(std::span<const Vec3> x);
  /// Lists all of F (pairs_), in order.
  void buildFramePairs();
  /// The particles stop being tracked: all their pairs of F join the near list.
  void untrack(std::span<const std::uint32_t> particles);
  /// Appends the key of every pair of F of particle k.
  void framePairsOf(std::uint32_t k, std::vector<std::uint64_t>& out) const;
  /// Sorts keys, without repeats.
  void sortKeys(std::vector<std::uint64_t>& keys);
  /// A pair's place in F's order (i < j): by i, then by the rank of j's cell among the 27 cells of i's query
  /// (TMP's order: the cells in turn, each cell's particles by index), then by j.
  std::uint64_t key(std::uint32_t i, std::uint32_t j) const;
  /// The pair (i, j) is in F: not neighbours at rest and closer than the reach at the start of the frame.
  bool inFrame(std::uint32_t i, std::uint32_t j) const;
  void undo(std::span<Vec3> x);

  SortedGrid wide_;                                    ///< cells of the reach at the frame's start: TMP's query
  DenseGrid narrow_;                                   ///< cells of thickness + s: the near list's search
  std::vector<std::array<std::int64_t, 3>> cell_;      ///< per particle: its cell in wide_
  std::vector<std::uint32_t> bucket_;                  ///< per particle: its bucket in wide_
  std::vector<std::uint8_t> shared_;                   ///< per particle: two of its query's 27 cells share a bucket
  std::vector<std::uint64_t> pairs_;                   ///< F as keys (listed only when a sweep needs all of it)
  std::vector<std::uint64_t> near_;                    ///< the near list as keys, a subsequence of F
  std::vector<std::uint64_t> untrackedPairs_;          ///< the pairs of F of the untracked particles
  std::vector<std::uint64_t> added_, merged_, byRow_;  ///< scratch
  std::vector<std::uint32_t> rowEnd_, far_;            ///< scratch
  std::vector<std::uint8_t> untracked_;                ///< per particle: all its pairs of F are in the near list
  std::vector<Vec3> start_, rest_;                     ///< [m] positions at the frame's start, rest positions
  std::vector<Vec3> builtAt_;                          ///< [m] positions at the near list's build
  std::vector<Real> away_;                             ///< [m] per particle: distance from builtAt_ before the sweep
  std::vector<Real> moved_;                            ///< [m] per particle: bound of what the sweep moved it
  std::vector<Undo> undo_;                             ///< positions before each contact of the sweep
  std::size_t undone_ = 0;                             ///< entries of undo_ in use
  Real thickness_ = 0.0, reach_ = 0.0;                 ///< [m] of the frame
  Real nearThickness_ = 0.0;                           ///< [m] thickness of the near list's build (0: none)
  Real skin_ = 0.0;                                    ///< [m] the near list's skin s
  bool nearList_ = true, framePairsBuilt_ = false;
  std::size_t nearBuilds_ = 0, fullSweeps_ = 0, untrackedCount_ = 0;
};

/// Pairs of non-neighbouring particles (rest distance ≥ 1.5 thickness) closer than half the thickness:
/// the self_intersections metric. 0 means no layer passed through another by more than half the thickness.
std::size_t countSelfIntersections(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness,
                                   particles::SpatialHash& hash);

}  // namespace pba::cloth
