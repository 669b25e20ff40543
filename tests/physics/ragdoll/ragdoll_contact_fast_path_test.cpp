// RAG-4's fast path against the ground (framework/physics/ragdoll/contact_fast_path.h) against the scalar
// route it replaces, on random contacts and on the contacts of a crowd of humans lying on the ground. The
// fast kernel does RAG-4's IEEE operations in the same order, two bones at a time, so the positions must
// agree to the bit. In the hand-out the fast path runs the scalar route and this holds trivially.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "physics/ragdoll/builders.h"
#include "physics/ragdoll/contact_fast_path.h"
#include "physics/ragdoll/particle_ragdoll.h"
#include "support/same_bits.h"

namespace pba::ragdoll {
namespace {

void expectSamePushes(const std::vector<GroundContact>& contacts, const std::vector<Vec3>& x) {
  std::vector<Vec3> scalar = x, fast = x;
  pushOutOfGroundScalar(contacts, scalar);
  pushOutOfGroundFast(contacts, fast);
  EXPECT_TRUE(test::sameBits(scalar, fast));
}

TEST(GroundContactFastPath, MatchesTheScalarPushesToTheBitOnRandomContacts) {
  // Bones of four particles; contacts in random order with repeats (the same bone twice in a row goes one
  // at a time), weights of box corners (outside the tetrahedron: some negative), all-zero weights (RAG-4
  // moves nothing) and odd counts (the last contact alone).
  std::mt19937 rng(36);
  std::uniform_real_distribution<Real> coordinate(-1.0, 1.0), weight(-0.6, 1.4), depth(0.0, 0.05), mass(0.5, 20.0);
  for (int trial = 0; trial < 40; ++trial) {
    const int bones = 1 + trial % 9;
    std::vector<Vec3> x;
    for (int p = 0; p < 4 * bones; ++p) x.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
    std::uniform_int_distribution<int> pick(0, bones - 1);
    std::vector<GroundContact> contacts(static_cast<std::size_t>(1 + trial));
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      GroundContact& c = contacts[k];
      c.first = 4 * pick(rng);
      for (Real& w : c.weights) w = k % 7 == 3 ? 0.0 : weight(rng);
      c.depth = depth(rng);
      c.mass = mass(rng);
    }
    SCOPED_TRACE("trial " + std::to_string(trial));
    expectSamePushes(contacts, x);
  }
}

TEST(GroundContactFastPath, MatchesTheScalarPushesToTheBitForACrowdOnTheGround) {
  // Nine humans lying just below the ground: every bone's contact as the ragdoll finds it (its deepest
  // corner, equally deep corners averaged), pushed twice in a row as its rounds do.
  RagdollDesc d;
  for (int k = 0; k < 9; ++k) {
    HumanDesc h;
    h.position = Vec3(2.2 * k, 0.05, 0.0);
    h.orientation = glm::angleAxis(degToRad(85.0 + k), Vec3(1.0, 0.0, 0.0));
    append(d, buildHumanRagdoll(h));
  }
  const ParticleRagdoll r = ParticleRagdoll::build(d).value();
  const std::vector<Vec3>& x = r.positions();
  std::vector<GroundContact> contacts;
  for (int b = 0; b < r.boneCount(); ++b) {
    GroundContact c;
    c.first = 4 * b;
    const collision::Transform t = r.boneFrame(b);
    const Vec3 low = t.apply(Vec3(0.0, -r.halfExtents(b).y, 0.0));  // a point of the box, its weights
    c.weights = barycentric({x[c.first], x[c.first + 1], x[c.first + 2], x[c.first + 3]}, low);
    c.depth = std::max(0.0, -low.y) + 1e-3;
    c.mass = r.boneMass(b);
    contacts.push_back(c);
  }
  const std::vector<GroundContact> once = contacts;
  contacts.insert(contacts.end(), once.begin(), once.end());
  expectSamePushes(contacts, x);
}

}  // namespace
}  // namespace pba::ragdoll
