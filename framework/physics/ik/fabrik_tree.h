#pragma once
// FABRIK's tables of the tree a solve works on (internal, fabrik.cpp): each joint's active children and
// effectors, and the look-ahead nodes of the ball joints that sit above hinges.
#include <span>
#include <vector>

#include "physics/ik/solver_internal.h"

namespace pba::ik::detail {

class FabrikTree {
 public:
  /// Fills every table for the context's skeleton, its active joints and its effectors.
  void build(const Context& c);

  /// Joint j's active children, in index order.
  std::span<const int> kids(int j) const { return slice(kidStart_, kidList_, j); }
  /// The effectors on joint j, in index order.
  std::span<const int> effectorsOn(int j) const { return slice(effStart_, effList_, j); }
  /// The look-ahead nodes of ball or free joint j (joint n, or effector e as jointCount + e); empty
  /// where it has none (see build()).
  std::span<const int> deeper(int j) const {
    return deeper_.empty() ? std::span<const int>() : std::span<const int>(deeper_[static_cast<size_t>(j)]);
  }
  /// The weight of joint j's look-ahead points in its fit.
  Real lookaheadWeight(int j) const { return lookaheadWeight_[static_cast<size_t>(j)]; }

 private:
  static std::span<const int> slice(const std::vector<int>& start, const std::vector<int>& list, int j) {
    const auto first = static_cast<size_t>(start[static_cast<size_t>(j)]);
    return std::span<const int>(list).subspan(first, static_cast<size_t>(start[static_cast<size_t>(j) + 1]) - first);
  }
  void buildLookahead(const Context& c);

  static constexpr int kLookahead = 3;
  static constexpr Real kFarLookaheadWeight = 0.1;
  std::vector<int> kidStart_, kidList_;   // active children per joint: kidList_[kidStart_[j] .. kidStart_[j + 1])
  std::vector<int> effStart_, effList_;   // effectors per joint, the same way
  std::vector<Real> lookaheadWeight_;     // per joint: weight of its look-ahead points
  std::vector<std::vector<int>> deeper_;  // per joint: look-ahead nodes; or empty (no hinge anywhere)
};

}  // namespace pba::ik::detail
