// FABRIK's tables of the tree a solve works on (fabrik_tree.h).
#include "physics/ik/fabrik_tree.h"

namespace pba::ik::detail {

void FabrikTree::build(const Context& c) {
  const int J = c.skeleton.jointCount(), E = static_cast<int>(c.effectors.size());
  // Active children per joint in index order, as kidList_[kidStart_[j] .. kidStart_[j + 1]) (two
  // allocations, not one per joint).
  bucketLists(
      static_cast<size_t>(J),
      [&](auto visit) {
        for (int j = 0; j < J; ++j) {
          const int parent = c.skeleton.joint(j).parent;
          if (c.active[static_cast<size_t>(j)] && parent >= 0) visit(static_cast<size_t>(parent), j);
        }
      },
      kidStart_, kidList_);
  // Effectors per joint, the same way: effList_[effStart_[j] .. effStart_[j + 1]).
  bucketLists(
      static_cast<size_t>(J),
      [&](auto visit) {
        for (int e = 0; e < E; ++e) visit(static_cast<size_t>(c.effectors[static_cast<size_t>(e)].joint), e);
      },
      effStart_, effList_);
  buildLookahead(c);
}

// The look-ahead of forward(): a ball or free joint with hinges or prismatic joints within
// kLookahead levels below it also aims its deeper descendants (joints and effectors; node J + e is
// effector e). With weight 1 when such a joint is its child (a finger's ball knuckle: it alone
// sets the plane the hinges bend in), else kFarLookaheadWeight (a wrist: the points only break
// the tie of its twist; at full weight the fit would turn the whole hand to lay straight fingers
// onto bent goals).
void FabrikTree::buildLookahead(const Context& c) {
  const int J = c.skeleton.jointCount();
  deeper_.clear();
  // No active hinge or prismatic joint (a chain of ball joints): no look-ahead anywhere, and no
  // per-joint lists to build (they cost more than a pass on a long chain); deeper_ stays empty.
  bool anyOneDof = false;
  for (int j = 0; j < J && !anyOneDof; ++j) {
    const JointType t = c.skeleton.joint(j).type;
    anyOneDof = c.active[static_cast<size_t>(j)] && (t == JointType::Hinge || t == JointType::Prismatic);
  }
  if (!anyOneDof) return;
  deeper_.assign(static_cast<size_t>(J), {});
  lookaheadWeight_.assign(static_cast<size_t>(J), kFarLookaheadWeight);
  for (int j = 0; j < J; ++j) {
    const JointType type = c.skeleton.joint(j).type;
    if (!c.active[static_cast<size_t>(j)] || (type != JointType::Ball && type != JointType::Free)) continue;
    std::vector<int> level(kids(j).begin(), kids(j).end()), found;
    bool hinged = false;
    for (int depth = 2; depth <= kLookahead; ++depth) {
      std::vector<int> next;
      for (int n : level) {
        const JointType t = c.skeleton.joint(n).type;
        const bool oneDof = t == JointType::Hinge || t == JointType::Prismatic;
        hinged = hinged || oneDof;
        if (depth == 2 && oneDof) lookaheadWeight_[static_cast<size_t>(j)] = 1.0;  // a child
        for (int e : effectorsOn(n)) found.push_back(J + e);
        for (int k : kids(n)) next.push_back(k);
      }
      found.insert(found.end(), next.begin(), next.end());
      level = std::move(next);
    }
    if (hinged) deeper_[static_cast<size_t>(j)] = std::move(found);
  }
}

}  // namespace pba::ik::detail
