// World stages around the solver: narrow phase with contact persistence, islands and sleeping,
// continuous collision.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "physics/collision/narrow_phase.h"
#include "physics/collision/toi.h"
#include "physics/rigid/world.h"

namespace pba::rigid {

bool World::jointConnected(int a, int b) const {
  return std::binary_search(jointedPairs_.begin(), jointedPairs_.end(), std::pair<int, int>(std::minmax(a, b)));
}

void World::collectJointedPairs() {
  // Rebuilt every step (a joint's collideConnected may be edited between steps): sorted, so a pair costs a
  // binary search rather than a scan of every joint (136 ragdolls have 2,040 joints).
  jointedPairs_.clear();
  for (const Joint& j : joints_)
    if (!j.desc.collideConnected && j.desc.bodyA >= 0)
      jointedPairs_.emplace_back(std::minmax(j.desc.bodyA, j.desc.bodyB));
  std::sort(jointedPairs_.begin(), jointedPairs_.end());
}

namespace {

bool movingKinematic(const Body& b) {
  return b.type == BodyType::Kinematic &&
         (glm::dot(b.linearVelocity, b.linearVelocity) > 0.0 || glm::dot(b.angularVelocity, b.angularVelocity) > 0.0);
}

// Carries last step's impulses over to points with the same feature id; friction goes through its world
// vector, since the tangent basis may have turned with the normal.
void carryImpulses(ContactConstraint& next, const ContactConstraint& old) {
  for (int i = 0; i < next.manifold.count; ++i) {
    ContactPoint& p = next.points[i];
    p = ContactPoint{};
    p.id = next.manifold.points[i].id;
    for (int k = 0; k < old.count; ++k) {
      const ContactPoint& o = old.points[k];
      if (o.id != p.id) continue;
      p.normalImpulse = o.normalImpulse;
      const Vec3 friction = o.tangentImpulse[0] * old.tangent[0] + o.tangentImpulse[1] * old.tangent[1];
      p.tangentImpulse[0] = glm::dot(friction, next.tangent[0]);
      p.tangentImpulse[1] = glm::dot(friction, next.tangent[1]);
      break;
    }
  }
}

bool keyLess(const ContactConstraint& c, int a, int b, std::uint32_t key) {
  if (c.bodyA != a) return c.bodyA < a;
  if (c.bodyB != b) return c.bodyB < b;
  return c.key < key;
}

}  // namespace

// The contact cache: when B has moved relative to A by less than the cache tolerances since the pair's
// manifolds were made, the manifolds are reused: the normal turns with A, each point's surface points move
// with their bodies, and the separation is measured between them along the normal (Bullet refreshes its
// persistent manifolds the same way; Jolt caches body pairs under the same kind of tolerance).
bool World::reuseContacts(int a, int b, std::size_t cursor, const collision::Transform& relative,
                          std::vector<ContactConstraint>& next) const {
  if (settings_.contactCacheDistance <= 0.0) return false;
  if (cursor >= contacts_.size() || contacts_[cursor].bodyA != a || contacts_[cursor].bodyB != b) return false;
  const ContactConstraint& first = contacts_[cursor];
  if (glm::length(relative.position - first.relativePose.position) > settings_.contactCacheDistance) return false;
  const Real cosHalf = std::abs(glm::dot(relative.rotation, first.relativePose.rotation));
  if (cosHalf < std::cos(0.5 * settings_.contactCacheAngle)) return false;
  const collision::Transform poseA = bodies_[a].pose(), poseB = bodies_[b].pose();
  for (std::size_t k = cursor; k < contacts_.size() && contacts_[k].bodyA == a && contacts_[k].bodyB == b; ++k) {
    ContactConstraint& c = next.emplace_back(contacts_[k]);  // one copy: a constraint is ~2 KB
    c.manifold.normal = c.normal = poseA.rotate(c.localNormal);
    // The tangent basis may turn (even swap axes) with the normal: friction goes through its world vector.
    tangentBasis(c.normal, c.tangent[0], c.tangent[1]);
    for (int i = 0; i < c.count; ++i) {
      ContactPoint& p = c.points[i];
      const Vec3 friction =
          p.tangentImpulse[0] * contacts_[k].tangent[0] + p.tangentImpulse[1] * contacts_[k].tangent[1];
      p.tangentImpulse[0] = glm::dot(friction, c.tangent[0]);
      p.tangentImpulse[1] = glm::dot(friction, c.tangent[1]);
    }
    for (int i = 0; i < c.manifold.count; ++i) {
      const Vec3 sa = poseA.apply(c.surfaceA[i]), sb = poseB.apply(c.surfaceB[i]);
      c.manifold.points[i].point = 0.5 * (sa + sb);
      c.manifold.points[i].separation = glm::dot(c.normal, sb - sa);
    }
  }
  return true;
}

void World::collide() {
  broadPhase_.findPairs(pairs_);
  collectJointedPairs();
  std::vector<ContactConstraint>& next = nextContacts_;  // kept between steps: no allocation once warm
  next.clear();
  // Grow geometrically: a pile gains contacts every step, and an exact reserve would move every ~2 KB
  // constraint (and fault in fresh pages) each time.
  const std::size_t needed = std::max(contacts_.size(), pairs_.size()) + 16;
  if (next.capacity() < needed) next.reserve(needed + needed / 2);
  std::vector<collision::Manifold>& manifolds = pairManifolds_;
  std::size_t cursor = 0;  // into the old, sorted contacts
  for (const auto& [a, b] : pairs_) {
    const Body& A = bodies_[a];
    const Body& B = bodies_[b];
    if (!A.isDynamic() && !B.isDynamic()) continue;
    if (jointConnected(a, b)) continue;
    while (cursor < contacts_.size() && keyLess(contacts_[cursor], a, b, 0)) ++cursor;
    const bool awake =
        (A.isDynamic() && !A.sleeping) || (B.isDynamic() && !B.sleeping) || movingKinematic(A) || movingKinematic(B);
    if (!awake) {
      // Both asleep (or asleep against something static): keep the old contacts as they are.
      for (std::size_t k = cursor; k < contacts_.size() && contacts_[k].bodyA == a && contacts_[k].bodyB == b; ++k)
        next.push_back(contacts_[k]);
      continue;
    }
    const collision::Transform relative = collision::relative(A.pose(), B.pose());
    if (reuseContacts(a, b, cursor, relative, next)) continue;
    manifolds.clear();
    collision::collide(A.shape, A.pose(), B.shape, B.pose(), settings_.speculativeDistance, manifolds, narrowScratch_);
    std::sort(manifolds.begin(), manifolds.end(), [](const auto& x, const auto& y) { return x.key < y.key; });
    for (const collision::Manifold& m : manifolds) {
      ContactConstraint& c = next.emplace_back();  // built in place
      c.bodyA = a;
      c.bodyB = b;
      c.key = m.key;
      c.manifold = m;
      c.count = m.count;
      c.normal = m.normal;
      tangentBasis(c.normal, c.tangent[0], c.tangent[1]);
      c.friction = std::sqrt(A.friction * B.friction);
      c.restitution = std::max(A.restitution, B.restitution);
      c.relativePose = relative;
      c.localNormal = A.pose().rotateInverse(m.normal);
      for (int i = 0; i < m.count; ++i) {
        // The point is midway: the surfaces are half the separation either side along the normal.
        const Vec3 half = 0.5 * m.points[i].separation * m.normal;
        c.surfaceA[i] = A.pose().applyInverse(m.points[i].point - half);
        c.surfaceB[i] = B.pose().applyInverse(m.points[i].point + half);
      }
      std::size_t k = cursor;
      while (k < contacts_.size() && keyLess(contacts_[k], a, b, m.key)) ++k;
      // Impulses are always carried; prepareContact alone decides whether the solver starts from them.
      if (k < contacts_.size() && contacts_[k].bodyA == a && contacts_[k].bodyB == b && contacts_[k].key == m.key) {
        carryImpulses(c, contacts_[k]);
      } else {
        for (int i = 0; i < m.count; ++i) c.points[i].id = m.points[i].id;
      }
    }
  }
  contacts_.swap(next);
}

void World::updateIslandsAndSleep() {
  const int n = bodyCount();
  islandOf_.assign(n, -1);
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  auto link = [&](int a, int b) {
    if (a < 0 || b < 0 || !bodies_[a].isDynamic() || !bodies_[b].isDynamic()) return;
    parent[find(a)] = find(b);
  };
  for (const ContactConstraint& c : contacts_) {
    if (c.manifold.count == 0) continue;
    link(c.bodyA, c.bodyB);
    // A moving kinematic body wakes what it touches.
    if (movingKinematic(bodies_[c.bodyA]) && bodies_[c.bodyB].isDynamic()) wake(c.bodyB);
    if (movingKinematic(bodies_[c.bodyB]) && bodies_[c.bodyA].isDynamic()) wake(c.bodyA);
  }
  for (const Joint& j : joints_) link(j.desc.bodyA, j.desc.bodyB);
  std::vector<char> islandAwake(n, 0);
  for (int i = 0; i < n; ++i) {
    if (!bodies_[i].isDynamic()) continue;
    islandOf_[i] = find(i);
    if (!bodies_[i].sleeping) islandAwake[islandOf_[i]] = 1;
  }
  for (int i = 0; i < n; ++i)
    if (islandOf_[i] >= 0 && islandAwake[islandOf_[i]] && bodies_[i].sleeping) wake(i);
}

void World::updateSleepTimers(Real dt) {
  const int n = bodyCount();
  const WorldSettings& s = settings_;
  std::vector<Real> islandMin(n, 1e30);
  for (int i = 0; i < n; ++i) {
    Body& b = bodies_[i];
    if (!b.isDynamic() || b.sleeping) continue;
    const bool slow =
        glm::length(b.linearVelocity) < s.sleepLinearSpeed && glm::length(b.angularVelocity) < s.sleepAngularSpeed;
    b.sleepTime = slow && b.allowSleep && i != drag_ ? b.sleepTime + dt : 0.0;
    if (islandOf_[i] >= 0) islandMin[islandOf_[i]] = std::min(islandMin[islandOf_[i]], b.sleepTime);
  }
  if (!s.sleeping) return;
  for (int i = 0; i < n; ++i) {
    Body& b = bodies_[i];
    if (!b.isDynamic() || b.sleeping || islandOf_[i] < 0) continue;
    if (islandMin[islandOf_[i]] >= s.timeToSleep) {
      b.sleeping = true;
      b.linearVelocity = b.angularVelocity = Vec3(0.0);
    }
  }
}

void World::solveContinuous(Real /*dt*/) {
  ccdHits_ = 0;
  if (!settings_.continuous) return;
  const Real target = settings_.linearSlop;
  for (int i = 0; i < bodyCount(); ++i) {
    Body& b = bodies_[i];
    if (!b.isDynamic() || b.sleeping || !(b.continuous || b.bullet)) continue;
    const collision::Sweep& sweep = sweeps_[i];
    // Slow bodies: the speculative margin catches every contact. Fast ones moved more than half their
    // smallest extent (Box2D v3's safety factor); bullets always.
    const Real travel = glm::length(sweep.c1 - sweep.c0);
    if (!b.bullet && travel < 0.5 * collision::minimumExtent(b.shape)) continue;
    collision::Aabb box = collision::computeAabb(b.shape, {sweep.c0, sweep.q0});
    box = collision::merge(box, collision::computeAabb(b.shape, {sweep.c1, sweep.q1}));
    Real tMin = 1.0;
    broadPhase_.query(box, [&](int other) {
      const Body& o = bodies_[other];
      if (other == i || o.type != BodyType::Static || o.shape.kind == collision::ShapeKind::Mesh) return;
      const collision::Sweep still{o.position, o.position, o.orientation, o.orientation};
      const collision::ToiResult r = collision::timeOfImpact(b.shape, sweep, o.shape, still, target, 0.25 * target);
      // A hit at t = 0 is a body that starts the step at the target distance: its contact, made before the
      // solve within the speculative margin, holds it. Rewinding it to t = 0 would undo the whole step and
      // restore the velocity it started with; the next step would start at the target distance again, so a
      // fast-spinning thin box (a ragdoll's hand or shin: 5 cm thick, over the threshold at 1.5 m/s) froze
      // in mid-tumble for good, its kinetic energy never falling and its joints pulled open. Box2D v3
      // (b2ContinuousQueryCallback) also accepts only fractions above 0.
      if (r.state == collision::ToiResult::State::Hit && r.t > 0.0 && r.t < tMin) tMin = r.t;
    });
    if (tMin < 1.0) {
      const collision::Transform at = sweep.at(tMin);
      b.position = at.position;
      b.orientation = at.rotation;
      // The velocity it had at that moment (exact under constant gravity); Box2D keeps the end-of-step
      // velocity, which makes a bounce start a little too fast.
      b.linearVelocity = startVelocity_[i] + tMin * (b.linearVelocity - startVelocity_[i]);
      b.angularVelocity = startAngularVelocity_[i] + tMin * (b.angularVelocity - startAngularVelocity_[i]);
      ++ccdHits_;
    }
  }
}

}  // namespace pba::rigid
