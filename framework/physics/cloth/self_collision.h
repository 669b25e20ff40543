#pragma once
// Cloth self-collision between particles (Ten Minute Physics #15, "Self-collision"): a dense spatial hash
// (cells of the query distance, filled by counting sort: particles/spatial_hash.h, Teschner et al. 2003),
// the set of nearby pairs fixed once per frame, and in every substep each pair closer than the thickness
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
// The frame's pairs F = {i < j, not neighbours, |x_i − x_j| < reach at the start of the frame}, swept in
// the order of (i, j). Most of them never come close: on the piled-up ribbon F holds ~240,000 pairs and
// ~10,000 are within 1.5 thicknesses. So each sweep visits only a sub-list that provably gives the same
// result as sweeping all of F (a Verlet list with a skin s, Verlet 1967, checked at run time):
//   - every particle starts "tracked": it is expected to follow its straight path x₀ + v₀ τ over the frame
//     (τ the time since the frame's start) within s; the sub-list holds the pairs of F whose straight
//     paths come closer than thickness + 2 s during the frame (and every pair of F of an untracked one);
//   - a pair left out can then only touch after one of its particles strayed more than s from its path.
//     Every sweep checks that bound for every tracked particle — its distance from its path before the
//     sweep plus everything the sweep moves it — and a particle that strays further is untracked (its
//     pairs of F join the list, in order) and the sweep is undone and run again.
// A pair left out would have been skipped by the full sweep (it is farther than the thickness whenever the
// sweep reaches it), so the positions are bit for bit those of sweeping F in order; only the cost differs.
// The pairs are found in a grid sorted by cell (positions copied in cell order, each pair visited once):
// pairs of two slow particles (|v₀| dt ≤ s) in cells of thickness + 4 s, pairs of a fast one in cells of
// the reach.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "physics/cloth/sorted_grid.h"
#include "physics/core/types.h"
#include "physics/particles/spatial_hash.h"

namespace pba::cloth {

/// Rest distance [in thicknesses] below which two particles are neighbours, not candidates.
inline constexpr Real kSelfNeighbourFactor = 1.5;
/// The skin s of the sub-list [in thicknesses] (see above): smaller lists against more untracked particles.
inline constexpr Real kSelfSkinFactor = 0.25;

struct SelfCollisionStats {
  std::size_t contacts = 0;  ///< pairs separated
  Real deepest = 0.0;        ///< [m] deepest overlap before separation
};

class SelfCollision {
 public:
  /// Fixes the frame's pairs: those closer than `reach` [m] (≥ thickness) at positions x. Once per frame.
  /// v: the velocities at the start of the frame [m/s] and dt the frame [s], which give the straight paths
  /// (they only decide how short the sub-list starts, never the result); v empty: every particle is
  /// untracked and the sub-list is the whole of F.
  void buildPairs(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness, Real reach,
                  std::span<const Vec3> v = {}, Real dt = 0.0);
  /// One Gauss–Seidel sweep over the frame's pairs (in the order of (i, j)). xPrev: positions at the start
  /// of the substep (for friction). time: since the start of the frame [s], within [0, dt]. thickness: as
  /// given to buildPairs.
  SelfCollisionStats solve(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> inverseMass,
                           Real thickness, Real friction, Real time = 0.0);
  /// Pairs a sweep visits now (the sub-list), and the particles untracked during this frame.
  std::size_t pairs() const { return pairs_.size(); }
  std::size_t promotions() const { return promotions_; }

 private:
  using Pair = std::pair<std::uint32_t, std::uint32_t>;
  struct Undo {
    std::uint32_t particle;
    Vec3 position;
  };
  /// One sweep over pairs_; with `track`, records what it changes (undo_) and how far it moves each particle.
  SelfCollisionStats sweep(std::span<Vec3> x, std::span<const Vec3> xPrev, std::span<const Real> w, Real friction,
                           bool track);
  /// Untracks the given particles: their pairs of F join the sub-list in order.
  void promote(std::span<const std::uint32_t> particles);
  /// Orders pairs by (i, j) (counting sort on i, then each row by j).
  void sortPairs(std::vector<Pair>& pairs);
  /// The pair (i, j) is in F: not neighbours at rest and closer than the reach at the start of the frame.
  bool inFrame(std::uint32_t i, std::uint32_t j) const;
  /// Both tracked, the straight paths of i and j come closer than thickness + 2 s during the frame.
  bool pathsMeet(std::uint32_t i, std::uint32_t j) const;
  void collectSlowPairs(std::span<const std::uint32_t> slow);
  void collectFastPairs(std::span<const std::uint32_t> fast);
  void buildWideGrid();

  SortedGrid wide_;                                     ///< cells of the reach at the start positions, every particle
  SortedGrid narrow_;                                   ///< cells of thickness + 4 s, slow particles
  std::vector<Pair> pairs_;                             ///< the sub-list, ordered by (i, j), i < j
  std::vector<Vec3> start_, velocity_;                  ///< [m], [m/s] at the start of the frame
  std::vector<Vec3> rest_;                              ///< [m] rest positions (the neighbour test)
  std::vector<std::uint8_t> tracked_, fast_;            ///< per particle
  std::vector<Real> strayed_;                           ///< [m] per particle: distance from its path before the sweep
  std::vector<Real> moved_;                             ///< [m] per particle: bound of what the sweep moved it
  std::vector<Undo> undo_;                              ///< positions before each contact of the sweep
  std::vector<std::uint32_t> stray_, slow_, fastList_;  ///< scratch
  std::vector<Pair> scratch_, merged_;
  std::vector<std::uint32_t> rowCount_;
  Real thickness_ = 0.0, reach_ = 0.0, skin_ = 0.0, dt_ = 0.0;
  bool wideBuilt_ = false, anyTracked_ = false;
  std::size_t promotions_ = 0;
};

/// Pairs of non-neighbouring particles (rest distance ≥ 1.5 thickness) closer than half the thickness:
/// the self_intersections metric. 0 means no layer passed through another by more than half the thickness.
std::size_t countSelfIntersections(std::span<const Vec3> x, std::span<const Vec3> rest, Real thickness,
                                   particles::SpatialHash& hash);

}  // namespace pba::cloth
