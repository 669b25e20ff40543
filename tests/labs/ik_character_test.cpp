// The IK lab's character import (labs/ik/character_rig.cpp): the file's skinned mesh drawn over the
// solved skeleton. Checked against invariants, not stored results: a vertex bound to one bone moves
// rigidly with that joint's frame, whatever the pose; at rest the mesh surrounds the skeleton.
#include <algorithm>
#include <filesystem>
#include <random>

#include <gtest/gtest.h>

#include "app/assets/character_rig.h"

namespace pba::app {
namespace {

using namespace pba::ik;

// Debian's assimp-testmodels (installed by ./pba): the Wuson, a skinned creature with 40 nodes.
constexpr const char* kWuson = PBA_TEST_RESOURCE_DIR "/models/Testwuson.X";

TEST(IkCharacterSkin, VerticesBoundToOneBoneMoveRigidlyWithItsJoint) {
  ASSERT_TRUE(std::filesystem::exists(kWuson)) << "install assimp-testmodels (./pba does)";
  CharacterDesc desc;
  desc.skeleton = kWuson;
  CharacterSkin skin;
  const Result<Rig> rig = loadCharacterRig(desc, &skin);
  ASSERT_TRUE(rig) << rig.error();
  ASSERT_TRUE(skin.model);
  const Skeleton& s = rig.value().skeleton;
  const std::vector<Frame> rest = forwardKinematics(s, s.restPose());
  const std::vector<SkinSurface> atRest = poseSkin(skin, rest);
  std::mt19937_64 rng(7);
  const std::vector<Frame> moved = forwardKinematics(s, randomPose(s, rng));
  const std::vector<SkinSurface> posed = poseSkin(skin, moved);
  ASSERT_GE(atRest.size(), 1u);
  ASSERT_EQ(posed.size(), atRest.size());
  int checked = 0;
  for (size_t m = 0; m < posed.size(); ++m) {
    const graphics::ModelMesh& mesh = skin.model->meshes[posed[m].mesh];
    ASSERT_EQ(posed[m].positions.size(), mesh.positions.size());
    if (!mesh.skinned()) continue;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      const int k = static_cast<int>(std::max_element(&mesh.boneWeights[v][0], &mesh.boneWeights[v][0] + 4) -
                                     &mesh.boneWeights[v][0]);
      if (mesh.boneWeights[v][k] < 0.9999f) continue;
      const auto node = static_cast<size_t>(skin.model->bones[static_cast<size_t>(mesh.boneIds[v][k])].node);
      // Coordinates in the joint's frame are the same in both poses.
      const Vec3 a = glm::inverse(rest[node].rotation) * (atRest[m].positions[v] - rest[node].position);
      const Vec3 b = glm::inverse(moved[node].rotation) * (posed[m].positions[v] - moved[node].position);
      EXPECT_LT(glm::length(a - b), 1e-4) << "mesh " << m << " vertex " << v;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(IkCharacterSkin, AtRestTheMeshSurroundsTheSkeleton) {
  CharacterDesc desc;
  desc.skeleton = kWuson;
  CharacterSkin skin;
  const Result<Rig> rig = loadCharacterRig(desc, &skin);
  ASSERT_TRUE(rig) << rig.error();
  const Skeleton& s = rig.value().skeleton;
  const std::vector<Frame> rest = forwardKinematics(s, s.restPose());
  Vec3 lo(1e30), hi(-1e30);
  for (const SkinSurface& surface : poseSkin(skin, rest))
    for (const Vec3& p : surface.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  int inside = 0;
  const Vec3 margin(0.02 * desc.height);
  for (const Frame& f : rest)
    inside += glm::all(glm::greaterThanEqual(f.position, lo - margin)) &&
              glm::all(glm::lessThanEqual(f.position, hi + margin));
  EXPECT_GE(inside, static_cast<int>(0.9 * static_cast<double>(rest.size()))) << "of " << rest.size() << " joints";
}

TEST(IkCharacterSkin, ASkeletonWithoutMeshesHasNoSkin) {
  CharacterDesc desc;  // the project's humanoid.bvh: joints only (Assimp's stand-in mesh is not a skin)
  CharacterSkin skin;
  const Result<Rig> rig = loadCharacterRig(desc, &skin);
  ASSERT_TRUE(rig) << rig.error();
  EXPECT_FALSE(skin.model);
  EXPECT_TRUE(poseSkin(skin, forwardKinematics(rig.value().skeleton, rig.value().skeleton.restPose())).empty());
}

}  // namespace
}  // namespace pba::app
