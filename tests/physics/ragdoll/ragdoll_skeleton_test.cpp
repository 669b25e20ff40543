// A ragdoll from a skeleton (physics/ragdoll/skeleton_ragdoll.h): one box per joint with children, joint
// kinds from the names, masses summing to the total; the particle ragdoll built from it lands and rests.
#include <gtest/gtest.h>

#include "physics/ragdoll/builders.h"
#include "physics/ragdoll/particle_ragdoll.h"
#include "physics/ragdoll/skeleton_ragdoll.h"

namespace pba::ragdoll {
namespace {

// A BVH-style humanoid (names as in resources/models/humanoid.bvh), positions [m], facing +z.
std::vector<SkeletonJoint> humanoid() {
  std::vector<SkeletonJoint> j;
  const auto add = [&j](const char* name, int parent, Vec3 offset) {
    j.push_back({name, parent, (parent >= 0 ? j[parent].position : Vec3(0.0)) + offset});
    return static_cast<int>(j.size()) - 1;
  };
  const int hips = add("Hips", -1, {0.0, 0.95, 0.0});
  const int spine = add("Spine", hips, {0.0, 0.1, 0.0});
  const int chest = add("Chest", spine, {0.0, 0.15, 0.0});
  const int neck = add("Neck", chest, {0.0, 0.22, 0.0});
  const int head = add("Head", neck, {0.0, 0.1, 0.0});
  add("Head_End", head, {0.0, 0.18, 0.0});
  for (int side = 0; side < 2; ++side) {
    const Real x = side == 0 ? 1.0 : -1.0;
    const std::string s = side == 0 ? "Left" : "Right";
    const int shoulder = add((s + "Shoulder").c_str(), chest, {0.03 * x, 0.18, 0.0});
    const int arm = add((s + "Arm").c_str(), shoulder, {0.14 * x, 0.0, 0.0});
    const int fore = add((s + "ForeArm").c_str(), arm, {0.28 * x, 0.0, 0.0});
    const int hand = add((s + "Hand").c_str(), fore, {0.25 * x, 0.0, 0.0});
    add((s + "Hand_End").c_str(), hand, {0.1 * x, 0.0, 0.0});
    const int up = add((s + "UpLeg").c_str(), hips, {0.09 * x, 0.0, 0.0});
    const int leg = add((s + "Leg").c_str(), up, {0.0, -0.43, 0.0});
    const int foot = add((s + "Foot").c_str(), leg, {0.0, -0.42, 0.0});
    add((s + "Foot_End").c_str(), foot, {0.0, -0.05, 0.15});
  }
  return j;
}

TEST(RagdollSkeleton, BuildsOneBonePerJointWithChildrenAndHingesAtKneesAndElbows) {
  const std::vector<SkeletonJoint> joints = humanoid();
  Result<RagdollDesc> r = buildSkeletonRagdoll(joints);
  ASSERT_TRUE(r.ok()) << r.error();
  const RagdollDesc& d = r.value();
  int withChildren = 0;
  for (std::size_t i = 0; i < joints.size(); ++i)
    for (const SkeletonJoint& c : joints)
      if (c.parent == static_cast<int>(i)) {
        ++withChildren;
        break;
      }
  EXPECT_EQ(static_cast<int>(d.bones.size()), withChildren);
  EXPECT_EQ(d.joints.size(), d.bones.size() - 1);
  EXPECT_NEAR(totalMass(d), 70.0, 1e-9);
  int hinges = 0;
  for (const JointDesc& j : d.joints) {
    const std::string& b = d.bones[j.boneB].name;
    const bool limb = b.find("ForeArm") != std::string::npos || b == "LeftLeg" || b == "RightLeg";
    EXPECT_EQ(j.kind == JointKind::Hinge, limb) << b;
    hinges += j.kind == JointKind::Hinge;
  }
  EXPECT_EQ(hinges, 4);
  EXPECT_FALSE(buildSkeletonRagdoll({}).ok());
}

TEST(RagdollSkeleton, TheParticleRagdollOfASkeletonLandsAndComesToRest) {
  RagdollDesc d = buildSkeletonRagdoll(humanoid()).value();
  d = rotated(translated(d, Vec3(0.0, 0.5, 0.0)), glm::angleAxis(degToRad(70.0), Vec3(1.0, 0.0, 0.0)),
              Vec3(0.0, 0.5, 0.0));
  ParticleRagdoll r = ParticleRagdoll::build(d).value();
  const Real bound = 0.5 * totalMass(d) * 0.05 * 0.05;  // [J] RMS speed 5 cm/s
  Real quiet = 0.0;
  for (int i = 0; i < 600 && quiet < 1.0; ++i) {
    r.step(1.0 / 60.0);
    quiet = r.stats().kineticEnergy < bound ? quiet + 1.0 / 60.0 : 0.0;
  }
  EXPECT_GE(quiet, 1.0) << "not at rest within 10 s";
  EXPECT_LT(r.stats().maxPenetration, 0.01);
  EXPECT_LT(r.stats().maxJointError, 0.01);
}

}  // namespace
}  // namespace pba::ragdoll
