// ANIM-3: forward kinematics of the joint tree, checked without a second forward kinematics: on random
// trees, the defining property read backwards frame by frame (each joint's world frame, seen from its
// parent's world frame, is its local offset and rotation; the root's is its own); a planar two-link arm
// whose joint positions have a closed form; and an invariant (a root translation moves everything rigidly).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "physics/animation/skeleton.h"
#include "support/expect_helpers.h"
#include "support/random_rotation.h"

namespace {

using pba::Quat;
using pba::Real;
using pba::Vec3;
namespace an = pba::animation;

using pba::test::randomRotation;

TEST(ANIM_3_ForwardKinematics, RandomTreesGiveEveryJointItsLocalOffsetAndRotationInItsParentsFrame) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<Real> len(-0.5, 0.5);
  for (int trial = 0; trial < 10; ++trial) {
    SCOPED_TRACE(std::string("seed 3, trial ") + std::to_string(trial));
    an::Skeleton s;
    for (int j = 0; j < 25; ++j) {
      const int parent = j == 0 ? -1 : static_cast<int>(rng() % static_cast<unsigned>(j));
      s.add(std::string("j") + std::to_string(j), parent, Vec3(len(rng), len(rng), len(rng)), randomRotation(rng));
    }
    an::Pose pose = an::restPose(s);
    for (Quat& q : pose.rotations) q = randomRotation(rng);
    const std::vector<an::JointWorld> world = an::forwardKinematics(s, pose);
    ASSERT_EQ(world.size(), 25u);
    for (size_t j = 0; j < 25; ++j) {
      SCOPED_TRACE("joint " + std::to_string(j));
      // Tolerance: up to 25 products of unit rotations and sub-metre offsets, ~1e-15 each.
      EXPECT_NEAR(glm::length(world[j].rotation), 1.0, 1e-12);
      if (s.parents[j] < 0) {
        EXPECT_VEC3_NEAR(world[j].position, pose.translations[j], 1e-15);
        EXPECT_NEAR(std::abs(glm::dot(world[j].rotation, pose.rotations[j])), 1.0, 1e-15);
        continue;
      }
      const an::JointWorld& parent = world[static_cast<size_t>(s.parents[j])];
      const Quat toParent = glm::conjugate(parent.rotation);
      EXPECT_VEC3_NEAR(toParent * (world[j].position - parent.position), pose.translations[j], 1e-12);
      // q and −q are the same rotation.
      EXPECT_NEAR(std::abs(glm::dot(toParent * world[j].rotation, pose.rotations[j])), 1.0, 1e-12);
    }
  }
}

TEST(ANIM_3_ForwardKinematics, PlanarTwoLinkArmMatchesTheClosedForm) {
  // Shoulder at (0, 1, 0), upper arm 0.6 m and forearm 0.5 m along +x, both turning about z.
  an::Skeleton s;
  s.add("shoulder", -1, Vec3(0.0, 1.0, 0.0));
  s.add("elbow", 0, Vec3(0.6, 0.0, 0.0));
  s.add("wrist", 1, Vec3(0.5, 0.0, 0.0));
  const Real a = 0.7, b = -1.2;  // [rad]
  an::Pose pose = an::restPose(s);
  pose.rotations[0] = glm::angleAxis(a, Vec3(0, 0, 1));
  pose.rotations[1] = glm::angleAxis(b, Vec3(0, 0, 1));
  const std::vector<an::JointWorld> w = an::forwardKinematics(s, pose);
  EXPECT_VEC3_NEAR(w[1].position, Vec3(0.6 * std::cos(a), 1.0 + 0.6 * std::sin(a), 0.0), 1e-14);
  EXPECT_VEC3_NEAR(
      w[2].position,
      Vec3(0.6 * std::cos(a) + 0.5 * std::cos(a + b), 1.0 + 0.6 * std::sin(a) + 0.5 * std::sin(a + b), 0.0), 1e-14);
}

TEST(ANIM_3_ForwardKinematics, RootTranslationMovesTheWholeBodyRigidly) {
  an::Skeleton s;
  s.add("root", -1, Vec3(0.0, 1.0, 0.0));
  s.add("a", 0, Vec3(0.3, 0.0, 0.0));
  s.add("b", 1, Vec3(0.0, -0.4, 0.1));
  an::Pose pose = an::restPose(s);
  pose.rotations[1] = glm::angleAxis(0.5, glm::normalize(Vec3(1, 1, 0)));
  const std::vector<an::JointWorld> before = an::forwardKinematics(s, pose);
  pose.translations[0] += Vec3(2.0, 0.0, -1.0);
  const std::vector<an::JointWorld> after = an::forwardKinematics(s, pose);
  for (size_t j = 0; j < 3; ++j) EXPECT_VEC3_NEAR(after[j].position - before[j].position, Vec3(2.0, 0.0, -1.0), 1e-14);
}

}  // namespace
