#include "physics/collision/dynamic_tree.h"

#include <algorithm>
#include <cassert>
#include <cstdlib>

namespace pba::collision {

int DynamicTree::allocateNode() {
  if (freeList_ == kNull) {
    nodes_.emplace_back();
    return static_cast<int>(nodes_.size()) - 1;
  }
  const int id = freeList_;
  freeList_ = nodes_[id].parent;
  nodes_[id] = Node{};
  return id;
}

void DynamicTree::freeNode(int id) {
  nodes_[id].parent = freeList_;
  nodes_[id].height = -1;
  freeList_ = id;
}

int DynamicTree::createProxy(const Aabb& aabb, int userData) {
  const int id = allocateNode();
  nodes_[id].box = aabb.fattened(margin_);
  nodes_[id].userData = userData;
  nodes_[id].height = 0;
  insertLeaf(id);
  ++leafCount_;
  return id;
}

void DynamicTree::destroyProxy(int proxy) {
  assert(nodes_[proxy].isLeaf());
  removeLeaf(proxy);
  freeNode(proxy);
  --leafCount_;
}

bool DynamicTree::moveProxy(int proxy, const Aabb& aabb) {
  if (nodes_[proxy].box.contains(aabb)) return false;
  removeLeaf(proxy);
  nodes_[proxy].box = aabb.fattened(margin_);
  insertLeaf(proxy);
  return true;
}

void DynamicTree::resetProxy(int proxy, const Aabb& aabb) {
  removeLeaf(proxy);
  nodes_[proxy].box = aabb.fattened(margin_);
  insertLeaf(proxy);
}

// Insertion (Box2D v2.4 b2DynamicTree::InsertLeaf): descend toward the child whose enlargement costs
// least, where a node's cost is its area and every ancestor pays the growth it must absorb; stop where
// making a new sibling here is cheaper than descending.
void DynamicTree::insertLeaf(int leaf) {
  if (root_ == kNull) {
    root_ = leaf;
    nodes_[leaf].parent = kNull;
    return;
  }
  const Aabb leafBox = nodes_[leaf].box;
  int index = root_;
  while (!nodes_[index].isLeaf()) {
    const Node& n = nodes_[index];
    const Real area = n.box.area();
    const Real combinedArea = merge(n.box, leafBox).area();
    const Real cost = 2.0 * combinedArea;                  // new parent of this node and the leaf
    const Real inheritance = 2.0 * (combinedArea - area);  // growth pushed onto the ancestors
    auto childCost = [&](int c) {
      const Aabb grown = merge(leafBox, nodes_[c].box);
      if (nodes_[c].isLeaf()) return grown.area() + inheritance;
      return grown.area() - nodes_[c].box.area() + inheritance;
    };
    const Real cost1 = childCost(n.child1);
    const Real cost2 = childCost(n.child2);
    if (cost < cost1 && cost < cost2) break;
    index = cost1 < cost2 ? n.child1 : n.child2;
  }
  const int sibling = index;
  const int oldParent = nodes_[sibling].parent;
  const int newParent = allocateNode();
  nodes_[newParent].parent = oldParent;
  nodes_[newParent].box = merge(leafBox, nodes_[sibling].box);
  nodes_[newParent].height = nodes_[sibling].height + 1;
  nodes_[newParent].child1 = sibling;
  nodes_[newParent].child2 = leaf;
  nodes_[sibling].parent = newParent;
  nodes_[leaf].parent = newParent;
  if (oldParent != kNull) {
    if (nodes_[oldParent].child1 == sibling)
      nodes_[oldParent].child1 = newParent;
    else
      nodes_[oldParent].child2 = newParent;
  } else {
    root_ = newParent;
  }
  // Walk back up: rebalance, refit heights and boxes.
  for (index = nodes_[leaf].parent; index != kNull; index = nodes_[index].parent) {
    index = balance(index);
    const Node& n = nodes_[index];
    nodes_[index].height = 1 + std::max(nodes_[n.child1].height, nodes_[n.child2].height);
    nodes_[index].box = merge(nodes_[n.child1].box, nodes_[n.child2].box);
  }
}

void DynamicTree::removeLeaf(int leaf) {
  if (leaf == root_) {
    root_ = kNull;
    return;
  }
  const int parent = nodes_[leaf].parent;
  const int grandParent = nodes_[parent].parent;
  const int sibling = nodes_[parent].child1 == leaf ? nodes_[parent].child2 : nodes_[parent].child1;
  if (grandParent == kNull) {
    root_ = sibling;
    nodes_[sibling].parent = kNull;
    freeNode(parent);
    return;
  }
  if (nodes_[grandParent].child1 == parent)
    nodes_[grandParent].child1 = sibling;
  else
    nodes_[grandParent].child2 = sibling;
  nodes_[sibling].parent = grandParent;
  freeNode(parent);
  for (int index = grandParent; index != kNull; index = nodes_[index].parent) {
    index = balance(index);
    const Node& n = nodes_[index];
    nodes_[index].box = merge(nodes_[n.child1].box, nodes_[n.child2].box);
    nodes_[index].height = 1 + std::max(nodes_[n.child1].height, nodes_[n.child2].height);
  }
}

// One rotation when the subtree at a is out of balance by more than 1 in height (Box2D v2.4
// b2DynamicTree::Balance, an AVL rotation): the taller child becomes the subtree's root and hands its
// shorter grandchild to a. Returns the new root of the subtree.
int DynamicTree::balance(int iA) {
  Node& A = nodes_[iA];
  if (A.isLeaf() || A.height < 2) return iA;
  const int iB = A.child1, iC = A.child2;
  const int delta = nodes_[iC].height - nodes_[iB].height;
  if (std::abs(delta) <= 1) return iA;
  // Rotate the taller child `up` (C when delta > 0, else B) above A.
  const int up = delta > 0 ? iC : iB;
  const int other = delta > 0 ? iB : iC;
  const int iF = nodes_[up].child1, iG = nodes_[up].child2;
  nodes_[up].child1 = iA;
  nodes_[up].parent = A.parent;
  A.parent = up;
  if (nodes_[up].parent != kNull) {
    Node& p = nodes_[nodes_[up].parent];
    if (p.child1 == iA)
      p.child1 = up;
    else
      p.child2 = up;
  } else {
    root_ = up;
  }
  // The taller grandchild stays under `up`; the shorter one goes to A in place of `up`.
  const bool fTaller = nodes_[iF].height > nodes_[iG].height;
  const int keep = fTaller ? iF : iG;
  const int give = fTaller ? iG : iF;
  nodes_[up].child2 = keep;
  if (delta > 0)
    A.child2 = give;
  else
    A.child1 = give;
  nodes_[give].parent = iA;
  A.box = merge(nodes_[other].box, nodes_[give].box);
  A.height = 1 + std::max(nodes_[other].height, nodes_[give].height);
  nodes_[up].box = merge(A.box, nodes_[keep].box);
  nodes_[up].height = 1 + std::max(A.height, nodes_[keep].height);
  return up;
}

Real DynamicTree::areaRatio() const {
  if (root_ == kNull) return 0.0;
  const Real rootArea = nodes_[root_].box.area();
  Real total = 0.0;
  for (const Node& n : nodes_)
    if (n.height > 0) total += n.box.area();
  return rootArea > 0.0 ? total / rootArea : 0.0;
}

int DynamicTree::computeHeight(int id) const {
  const Node& n = nodes_[id];
  if (n.isLeaf()) return 0;
  return 1 + std::max(computeHeight(n.child1), computeHeight(n.child2));
}

bool DynamicTree::validate() const {
  if (root_ == kNull) return leafCount_ == 0;
  if (nodes_[root_].parent != kNull) return false;
  int leaves = 0;
  std::vector<int> stack{root_};
  while (!stack.empty()) {
    const int id = stack.back();
    stack.pop_back();
    const Node& n = nodes_[id];
    if (n.isLeaf()) {
      ++leaves;
      if (n.height != 0) return false;
      continue;
    }
    for (int c : {n.child1, n.child2}) {
      if (c == kNull || nodes_[c].parent != id || !n.box.contains(nodes_[c].box)) return false;
      stack.push_back(c);
    }
    if (n.height != 1 + std::max(nodes_[n.child1].height, nodes_[n.child2].height)) return false;
    if (std::abs(nodes_[n.child1].height - nodes_[n.child2].height) > 1) return false;
  }
  return leaves == leafCount_ && computeHeight(root_) == nodes_[root_].height;
}

}  // namespace pba::collision
