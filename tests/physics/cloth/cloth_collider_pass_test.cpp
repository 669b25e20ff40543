// The collider passes (collideAll, collideListed) against a reference loop of one-collider queries
// (collide()): each free particle meets its colliders in turn, in the same order, so the passes must agree
// with the loop to the bit, whatever order they run in internally. Not an exercise test: both sides call
// CLOTH-4's projection the same way, so they agree with the stub too.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "physics/cloth/colliders.h"

namespace pba::cloth {
namespace {

// Four overlapping colliders and 400 particles scattered through them (some pinned), for the passes below.
struct PassScene {
  std::vector<Collider> colliders;
  std::vector<Vec3> x, previous, v;
  std::vector<Real> w;
};
PassScene overlappingColliders() {
  PassScene s;
  const Collider plane = Collider::plane(Vec3(0.0, 0.1, 0.0), glm::angleAxis(0.3, Vec3(0.0, 0.0, 1.0)));
  const Collider sphere = Collider::sphere(Vec3(0.2, 0.3, 0.0), 0.35);
  Collider box = Collider::box(Vec3(-0.2, 0.25, 0.1), glm::angleAxis(0.7, glm::normalize(Vec3(1.0, 1.0, 0.0))),
                               Vec3(0.3, 0.2, 0.25));
  box.velocity = Vec3(0.4, 0.0, 0.0);
  const Collider capsule =
      Collider::capsule(Vec3(0.0, 0.35, -0.1), glm::angleAxis(1.1, Vec3(1.0, 0.0, 0.0)), 0.3, 0.15);
  s.colliders = {plane, sphere, box, capsule};
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> u(-0.6, 0.6);
  for (int i = 0; i < 400; ++i) {
    const Vec3 p(u(random), 0.3 + u(random), u(random));
    s.x.push_back(p);
    s.previous.push_back(p + 0.05 * Vec3(u(random), u(random), u(random)));
    s.v.push_back(Vec3(u(random), u(random), u(random)));
    s.w.push_back(i % 9 == 0 ? 0.0 : 1.0);
  }
  return s;
}

// The reference: the particles in `order`, each listing meeting `colliders` in turn through collide();
// with `withVelocities`, v += Δx/h as collideAll does. Returns the contacts and the deepest penetration.
CollisionPassStats referencePass(PassScene& s, std::span<const Collider> colliders,
                                 std::span<const std::uint32_t> order, Real margin, Real h, Real frictionScale,
                                 bool withVelocities) {
  CollisionPassStats stats;
  for (const std::uint32_t i : order) {
    if (s.w[i] == 0.0) continue;
    for (const Collider& c : colliders) {
      Real depth = 0.0;
      const Vec3 projected = collide(c, s.x[i], s.previous[i], margin, h, &depth, frictionScale);
      if (depth <= 0.0) continue;
      ++stats.contacts;
      stats.deepest = std::max(stats.deepest, depth);
      if (withVelocities) s.v[i] += (projected - s.x[i]) / h;
      s.x[i] = projected;
    }
  }
  return stats;
}

TEST(ClothColliderPasses, ThePassGivesEachFreeParticleItsCollidersInTurnAsTheOneColliderQueryDoes) {
  const Real margin = 0.005, h = 0.01, frictionScale = 0.7;
  PassScene pass = overlappingColliders();
  PassScene reference = pass;
  std::vector<std::uint32_t> everyParticle(pass.x.size());
  std::iota(everyParticle.begin(), everyParticle.end(), 0u);
  const CollisionPassStats expected =
      referencePass(reference, reference.colliders, everyParticle, margin, h, frictionScale, true);
  ASSERT_GT(expected.contacts, 100u);  // the scene does exercise the colliders, several per particle
  const CollisionPassStats stats =
      collideAll(pass.colliders, pass.x, pass.previous, pass.w, margin, h, pass.v, frictionScale);
  EXPECT_EQ(stats.contacts, expected.contacts);
  EXPECT_EQ(stats.deepest, expected.deepest);
  for (std::size_t i = 0; i < pass.x.size(); ++i) {
    EXPECT_EQ(pass.x[i], reference.x[i]) << "particle " << i;
    EXPECT_EQ(pass.v[i], reference.v[i]) << "particle " << i;
  }
}

TEST(ClothColliderPasses, TheListedPassVisitsAllCollidersForEachListingInListOrder) {
  // Repeats in the list: each listing of a particle meets all its colliders before the next listing.
  const Real margin = 0.005, h = 0.01;
  std::vector<std::uint32_t> listed;
  for (std::uint32_t i = 0; i < 400; i += 3) listed.insert(listed.end(), {i, i / 2, i});
  const std::vector<Collider> all = overlappingColliders().colliders;
  // All four colliders, then one alone (the loop that runs collider by collider).
  for (const std::span<const Collider> colliders :
       {std::span<const Collider>(all), std::span<const Collider>(all).subspan(1, 1)}) {
    PassScene pass = overlappingColliders();
    PassScene reference = pass;
    referencePass(reference, colliders, listed, margin, h, 0.0, false);
    collideListed(colliders, listed, pass.x, pass.previous, pass.w, margin, h);
    for (std::size_t i = 0; i < pass.x.size(); ++i)
      EXPECT_EQ(pass.x[i], reference.x[i]) << colliders.size() << " colliders, particle " << i;
  }
}

}  // namespace
}  // namespace pba::cloth
