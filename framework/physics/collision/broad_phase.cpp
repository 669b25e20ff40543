#include "physics/collision/broad_phase.h"

#include <algorithm>

#include "physics/collision/exercises.h"

namespace pba::collision {

BroadPhase::BroadPhase(BroadPhaseKind kind, Real margin) : kind_(kind), margin_(margin) {}

int BroadPhase::add(const Aabb& aabb, int userData, bool isStatic) {
  int id;
  if (!freeProxies_.empty()) {
    id = freeProxies_.back();
    freeProxies_.pop_back();
  } else {
    id = static_cast<int>(proxies_.size());
    proxies_.emplace_back();
  }
  Proxy& p = proxies_[id];
  p.fat = isStatic ? aabb : aabb.fattened(margin_);
  p.userData = userData;
  p.isStatic = isStatic;
  p.alive = true;
  p.leaf = trees_[isStatic ? 1 : 0].createProxy(p.fat, id);
  p.moved = false;
  markMoved(id);
  sorted_.push_back(id);
  ++live_;
  return id;
}

void BroadPhase::remove(int proxy) {
  Proxy& p = proxies_[proxy];
  trees_[p.isStatic ? 1 : 0].destroyProxy(p.leaf);
  p.alive = false;
  std::erase_if(treePairs_, [&](const auto& pair) { return pair.first == proxy || pair.second == proxy; });
  sorted_.erase(std::find(sorted_.begin(), sorted_.end(), proxy));
  freeProxies_.push_back(proxy);
  --live_;
}

void BroadPhase::move(int proxy, const Aabb& aabb) {
  Proxy& p = proxies_[proxy];
  if (p.fat.contains(aabb)) return;
  p.fat = aabb.fattened(margin_);
  trees_[p.isStatic ? 1 : 0].resetProxy(p.leaf, p.fat);
  markMoved(proxy);
}

void BroadPhase::markMoved(int proxy) {
  if (kind_ != BroadPhaseKind::Tree || proxies_[proxy].moved) return;
  proxies_[proxy].moved = true;
  moveBuffer_.push_back(proxy);
}

void BroadPhase::findPairs(std::vector<std::pair<int, int>>& pairs) {
  pairs.clear();
  switch (kind_) {
    case BroadPhaseKind::Tree:
      pairsFromTree(pairs);
      break;
    case BroadPhaseKind::SweepAndPrune:
      pairsFromSweep(pairs);
      break;
    case BroadPhaseKind::BruteForce:
      pairsBruteForce(pairs);
      break;
  }
  for (auto& [a, b] : pairs)
    if (a > b) std::swap(a, b);
  // The tree's set comes out sorted when user data grow with proxy ids (a world's bodies do).
  if (!std::is_sorted(pairs.begin(), pairs.end())) std::sort(pairs.begin(), pairs.end());
}

void BroadPhase::pairsFromTree(std::vector<std::pair<int, int>>& pairs) {
  // Pairs with a moved proxy may have ended; the others hold.
  std::erase_if(treePairs_, [&](const auto& pair) {
    const Proxy &a = proxies_[pair.first], &b = proxies_[pair.second];
    return (a.moved || b.moved) && !overlaps(a.fat, b.fat);
  });
  // Each moved proxy queries the moving tree and, if it moves itself, the static tree. Two moved
  // proxies find each other twice: the one with the smaller id keeps the pair.
  freshPairs_.clear();
  for (int id : moveBuffer_) {
    const Proxy& p = proxies_[id];
    if (!p.alive) continue;
    auto keep = [&](int leaf, const DynamicTree& t) {
      const int other = t.userData(leaf);
      if (other == id || (proxies_[other].moved && other < id)) return true;
      freshPairs_.emplace_back(std::min(id, other), std::max(id, other));
      return true;
    };
    trees_[0].query(p.fat, [&](int leaf) { return keep(leaf, trees_[0]); });
    if (!p.isStatic) trees_[1].query(p.fat, [&](int leaf) { return keep(leaf, trees_[1]); });
  }
  for (int id : moveBuffer_) proxies_[id].moved = false;
  moveBuffer_.clear();
  // Merge: a fresh pair may already be in the set (it overlapped before and still does).
  std::sort(freshPairs_.begin(), freshPairs_.end());
  const std::size_t kept = treePairs_.size();
  treePairs_.insert(treePairs_.end(), freshPairs_.begin(), freshPairs_.end());
  std::inplace_merge(treePairs_.begin(), treePairs_.begin() + static_cast<std::ptrdiff_t>(kept), treePairs_.end());
  treePairs_.erase(std::unique(treePairs_.begin(), treePairs_.end()), treePairs_.end());
  pairs.reserve(treePairs_.size());
  for (const auto& [a, b] : treePairs_) pairs.emplace_back(proxies_[a].userData, proxies_[b].userData);
}

void BroadPhase::pairsFromSweep(std::vector<std::pair<int, int>>& pairs) {
  // Axis of largest spread of the box centres (Ericson §7.5.2), re-chosen every call.
  Vec3 sum(0.0), sum2(0.0);
  int dynamicCount = 0;
  for (int id : sorted_) {
    if (proxies_[id].isStatic) continue;
    const Vec3 c = proxies_[id].fat.center();
    sum += c, sum2 += c * c, ++dynamicCount;
  }
  if (dynamicCount > 0) {
    const Vec3 variance =
        sum2 / static_cast<Real>(dynamicCount) - (sum * sum) / static_cast<Real>(dynamicCount * dynamicCount);
    axis_ = variance.x >= variance.y ? (variance.x >= variance.z ? 0 : 2) : (variance.y >= variance.z ? 1 : 2);
  }
  // The sort and the sweep are the exercise COLL-3, on the fat boxes indexed by proxy id.
  sweepBoxes_.resize(proxies_.size());
  sweepStatic_.resize(proxies_.size());
  for (int id : sorted_) {
    sweepBoxes_[id] = proxies_[id].fat;
    sweepStatic_[id] = proxies_[id].isStatic ? 1 : 0;
  }
  sweepPairs_.clear();
  sortAndSweep(sweepBoxes_, sweepStatic_, axis_, sorted_, sweepPairs_);
  for (const auto& [a, b] : sweepPairs_) pairs.emplace_back(proxies_[a].userData, proxies_[b].userData);
}

void BroadPhase::pairsBruteForce(std::vector<std::pair<int, int>>& pairs) const {
  for (std::size_t i = 0; i < proxies_.size(); ++i) {
    if (!proxies_[i].alive) continue;
    for (std::size_t j = i + 1; j < proxies_.size(); ++j) {
      if (!proxies_[j].alive || (proxies_[i].isStatic && proxies_[j].isStatic)) continue;
      if (overlaps(proxies_[i].fat, proxies_[j].fat)) pairs.emplace_back(proxies_[i].userData, proxies_[j].userData);
    }
  }
}

}  // namespace pba::collision
