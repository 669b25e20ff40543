#pragma once
// Broad phase: the pairs of shapes whose fattened AABBs overlap, by one of three selectable methods
// that give the same pair set (tested): a dynamic AABB tree (Box2D's b2BroadPhase over b2DynamicTree),
// sweep and prune (Baraff 1992 §4; Ericson §7.5.2, "sort and sweep": sort on the axis of largest spread,
// insertion sort keeps it cheap from step to step) and brute force (every pair, the reference).
//
// Proxies keep a fat AABB, the tight one grown by `margin`, replaced only when the tight box leaves it;
// every method reports pairs of fat AABBs, so they agree exactly. Two static proxies never pair.
// Static proxies live in a tree of their own (as in Box2D v3): a huge static box such as a ground
// plane would otherwise be rotated into the moving bodies' subtrees and make every query visit them.
// The tree keeps its pair set from call to call (Box2D's move buffer): only proxies whose fat AABB
// changed since the last call query the trees, and only their pairs can end. A pair of two unmoved
// proxies overlapped last time exactly when it does now, so the set stays the one a full search gives.
#include <string>
#include <utility>
#include <vector>

#include "physics/collision/dynamic_tree.h"
#include "physics/core/enum_names.h"

namespace pba::collision {

enum class BroadPhaseKind { Tree, SweepAndPrune, BruteForce };
inline constexpr auto kBroadPhaseNames = enumNames<BroadPhaseKind>({{BroadPhaseKind::Tree, "tree"},
                                                                    {BroadPhaseKind::SweepAndPrune, "sap"},
                                                                    {BroadPhaseKind::BruteForce, "brute-force"}});
inline std::vector<std::string> broadPhaseNames() { return kBroadPhaseNames.names(); }

class BroadPhase {
 public:
  explicit BroadPhase(BroadPhaseKind kind = BroadPhaseKind::Tree, Real margin = 0.1);

  BroadPhaseKind kind() const { return kind_; }
  /// Adds a proxy for `aabb` (tight) that reports `userData` in pairs; returns the proxy id.
  int add(const Aabb& aabb, int userData, bool isStatic);
  void remove(int proxy);
  /// New tight AABB; the fat one changes only when the tight one leaves it.
  void move(int proxy, const Aabb& aabb);
  const Aabb& fatAabb(int proxy) const { return proxies_[proxy].fat; }
  int userData(int proxy) const { return proxies_[proxy].userData; }
  int size() const { return live_; }

  /// All pairs (userData a < b) of overlapping fat AABBs, sorted: the same set for every kind.
  void findPairs(std::vector<std::pair<int, int>>& pairs);
  /// Calls visit(userData) for every proxy whose fat AABB overlaps `box`.
  template <typename Visit>
  void query(const Aabb& box, Visit&& visit) const {
    for (const DynamicTree& t : trees_)
      t.query(box, [&](int leaf) {
        visit(proxies_[t.userData(leaf)].userData);
        return true;
      });
  }
  /// Ray cast through the tree: hit(userData, maxT) returns the new maxT (see DynamicTree::rayCast).
  template <typename Hit>
  void rayCast(const Vec3& origin, const Vec3& direction, Real maxT, Hit&& hit) const {
    for (const DynamicTree& t : trees_) {
      t.rayCast(origin, direction, maxT, [&](int leaf, Real tHit) {
        maxT = hit(proxies_[t.userData(leaf)].userData, tHit);
        return maxT;
      });
      if (maxT <= 0.0) return;
    }
  }
  /// The tree of moving proxies (0) or of static ones (1).
  const DynamicTree& tree(int which = 0) const { return trees_[which]; }

 private:
  struct Proxy {
    Aabb fat;
    int userData = -1;
    int leaf = -1;  // tree leaf
    bool isStatic = false;
    bool alive = false;
    bool moved = false;  // fat AABB new since the last findPairs (tree: in moveBuffer_)
  };
  void markMoved(int proxy);
  void pairsFromTree(std::vector<std::pair<int, int>>& pairs);
  void pairsFromSweep(std::vector<std::pair<int, int>>& pairs);
  void pairsBruteForce(std::vector<std::pair<int, int>>& pairs) const;

  BroadPhaseKind kind_;
  Real margin_;
  std::vector<Proxy> proxies_;
  std::vector<int> freeProxies_;
  int live_ = 0;
  DynamicTree trees_[2]{DynamicTree(0.0), DynamicTree(0.0)};  // moving, static; fat boxes as they are
  std::vector<int> sorted_;                                   // sweep and prune: live proxies by min along axis_
  std::vector<int> moveBuffer_;                               // tree: proxies with a new fat AABB
  std::vector<std::pair<int, int>> treePairs_;                // tree: overlapping proxy ids (a < b), sorted
  std::vector<std::pair<int, int>> freshPairs_;               // tree: scratch
  int axis_ = 0;
  std::vector<Aabb> sweepBoxes_;                 // sweep and prune: fat boxes by proxy id (COLL-3's input)
  std::vector<char> sweepStatic_;                // sweep and prune: static flags by proxy id
  std::vector<std::pair<int, int>> sweepPairs_;  // sweep and prune: overlapping proxy ids
};

}  // namespace pba::collision
