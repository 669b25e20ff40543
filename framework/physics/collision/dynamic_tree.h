#pragma once
// Dynamic AABB tree (Box2D's b2DynamicTree, after Presson's bounding-volume tree in Bullet): a binary
// tree of fattened AABBs. Leaves store proxies; internal nodes their union. Insertion walks down by the
// surface-area cost of the enlargement (Catto, "Dynamic Bounding Volume Hierarchies", GDC 2019) and
// rebalances by rotations on the way up, so the tree stays shallow under incremental insert, remove and
// move. A leaf's AABB is the proxy's AABB grown by `margin`, so a proxy that moves a little keeps its
// leaf (moveProxy returns false) and the tree is untouched.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "physics/collision/aabb.h"

namespace pba::collision {

namespace detail {
// A query's traversal stack, on the caller's stack so that queries are re-entrant and may run on
// several threads at once (Box2D v3's b2DynamicTree_Query keeps its stack local the same way). A
// balanced tree needs at most its height + 1 entries, far below the inline capacity; a deeper one
// spills to the heap rather than fail.
class TraversalStack {
 public:
  bool empty() const { return size_ == 0; }
  void push(int id) {
    if (size_ < kInline)
      inline_[size_] = id;
    else
      spill_.push_back(id);
    ++size_;
  }
  int pop() {
    --size_;
    if (size_ < kInline) return inline_[size_];
    const int id = spill_.back();
    spill_.pop_back();
    return id;
  }

 private:
  static constexpr std::size_t kInline = 128;
  int inline_[kInline];
  std::size_t size_ = 0;
  std::vector<int> spill_;
};
}  // namespace detail

class DynamicTree {
 public:
  static constexpr int kNull = -1;

  /// margin [m]: how much leaf AABBs are fattened (0 for static data such as mesh triangles).
  explicit DynamicTree(Real margin = 0.1) : margin_(margin) {}

  /// Inserts a proxy for `aabb` (tight); returns its id. userData is handed back by queries.
  int createProxy(const Aabb& aabb, int userData);
  void destroyProxy(int proxy);
  /// Updates a proxy's tight AABB; re-inserts it (and returns true) only when it left its fat AABB.
  bool moveProxy(int proxy, const Aabb& aabb);
  /// Re-inserts a proxy with exactly this AABB (fattened by the margin), whatever its old one was.
  void resetProxy(int proxy, const Aabb& aabb);

  const Aabb& fatAabb(int proxy) const { return nodes_[proxy].box; }
  int userData(int proxy) const { return nodes_[proxy].userData; }
  int root() const { return root_; }
  int proxyCount() const { return leafCount_; }
  /// Height of the tree (a single leaf has height 0; empty −1).
  int height() const { return root_ == kNull ? -1 : nodes_[root_].height; }
  /// Σ internal node areas / root area: the quality measure of the surface area heuristic.
  Real areaRatio() const;
  /// Checks parent links, heights and enclosure (tests); false with the first broken invariant.
  bool validate() const;

  /// Calls visit(proxy) for every leaf whose fat AABB overlaps `box`; visit returns false to stop.
  template <typename Visit>
  void query(const Aabb& box, Visit&& visit) const {
    if (root_ == kNull) return;
    detail::TraversalStack stack;
    stack.push(root_);
    while (!stack.empty()) {
      const int id = stack.pop();
      const Node& n = nodes_[id];
      if (!overlaps(n.box, box)) continue;
      if (n.isLeaf()) {
        if (!visit(id)) return;
      } else {
        stack.push(n.child1);
        stack.push(n.child2);
      }
    }
  }

  /// Calls visit(box, height, isLeaf) for every node (debug drawing).
  template <typename Visit>
  void forEachNode(Visit&& visit) const {
    for (const Node& n : nodes_)
      if (n.height >= 0) visit(n.box, n.height, n.isLeaf());
  }

  /// Ray cast origin + t·direction, t ∈ [0, maxT]: calls hit(proxy, maxT) for every leaf whose fat AABB
  /// the current segment meets; hit returns the new maxT (the proxy's exact hit distance to clip the
  /// ray, maxT to go on unchanged, or 0 to stop).
  template <typename Hit>
  void rayCast(const Vec3& origin, const Vec3& direction, Real maxT, Hit&& hit) const {
    if (root_ == kNull) return;
    const Vec3 inv = safeInverse(direction);
    detail::TraversalStack stack;
    stack.push(root_);
    while (!stack.empty()) {
      const int id = stack.pop();
      const Node& n = nodes_[id];
      if (!raySegmentHitsAabb(origin, inv, maxT, n.box)) continue;
      if (n.isLeaf()) {
        maxT = hit(id, maxT);
        if (maxT <= 0.0) return;
      } else {
        stack.push(n.child1);
        stack.push(n.child2);
      }
    }
  }

 private:
  struct Node {
    Aabb box;
    int parent = kNull;  // also the free-list link
    int child1 = kNull, child2 = kNull;
    int height = 0;  // leaf 0, free −1
    int userData = -1;
    bool isLeaf() const { return child1 == kNull; }
  };
  int allocateNode();
  void freeNode(int id);
  void insertLeaf(int leaf);
  void removeLeaf(int leaf);
  int balance(int a);
  int computeHeight(int id) const;

  Real margin_;
  std::vector<Node> nodes_;
  int root_ = kNull;
  int freeList_ = kNull;
  int leafCount_ = 0;
};

}  // namespace pba::collision
