// Model import (Assimp) and pose math: BVH skeleton + motion, glTF skin weights, bind-pose skinning
// identity, CPU linear blend skinning against a hand-written reference, and bad files. No window.
#include "graphics/model.h"
#include "graphics/skinning.h"
#include "model_file_check.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace gfx = pba::graphics;

namespace {

const std::string kBvh = pba::testing::models::kShippedModels + "mocap/01_01.bvh";
const std::string kSkin = pba::testing::models::kShippedModels + "simple_skin/simple_skin.gltf";

using pba::testing::models::loadOrFail;

float maxAbsDifference(const glm::mat4& a, const glm::mat4& b) {
  float d = 0.0f;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
  }
  return d;
}

}  // namespace

TEST(ModelImport, BvhHasAValidHierarchyAndAnAnimation) {
  const gfx::Model m = loadOrFail(kBvh);
  ASSERT_GT(m.nodes.size(), 0u);
  EXPECT_EQ(m.nodes[0].parent, -1);
  for (std::size_t i = 1; i < m.nodes.size(); ++i) {
    EXPECT_GE(m.nodes[i].parent, 0) << m.nodes[i].name;
    EXPECT_LT(m.nodes[i].parent, static_cast<int>(i)) << "parents must precede children: " << m.nodes[i].name;
  }
  ASSERT_FALSE(m.animations.empty());
  const gfx::Animation& a = m.animations[0];
  EXPECT_GT(a.duration, 0.0f);
  EXPECT_GT(a.channels.size(), 0u);
  for (const gfx::NodeChannel& c : a.channels) {
    EXPECT_GE(c.node, 0);
    EXPECT_FALSE(c.rotations.empty());
    for (std::size_t k = 1; k < c.rotations.size(); ++k) EXPECT_GE(c.rotations[k].time, c.rotations[k - 1].time);
  }
}

TEST(ModelImport, BvhAnimationSamplesToFiniteGlobalTransforms) {
  const gfx::Model m = loadOrFail(kBvh);
  ASSERT_FALSE(m.animations.empty());
  for (float t : {0.0f, 0.5f, 1.7f, m.animations[0].duration * 3.3f}) {
    const auto global = gfx::globalTransforms(m, gfx::sampleAnimation(m, m.animations[0], t));
    ASSERT_EQ(global.size(), m.nodes.size());
    for (const glm::mat4& g : global) {
      for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(glm::length(g[c])));
    }
  }
}

TEST(ModelImport, GltfSkinHasBonesAndNormalisedWeights) {
  const gfx::Model m = loadOrFail(kSkin);
  EXPECT_GT(m.bones.size(), 0u);
  bool anySkinned = false;
  for (const gfx::ModelMesh& mesh : m.meshes) {
    if (!mesh.skinned()) continue;
    anySkinned = true;
    ASSERT_EQ(mesh.boneWeights.size(), mesh.positions.size());
    for (std::size_t v = 0; v < mesh.boneWeights.size(); ++v) {
      const glm::vec4& w = mesh.boneWeights[v];
      EXPECT_NEAR(w.x + w.y + w.z + w.w, 1.0f, 1e-5f) << "vertex " << v;
      for (int k = 0; k < 4; ++k) {
        EXPECT_GE(w[k], 0.0f);
        EXPECT_LT(mesh.boneIds[v][k], static_cast<int>(m.bones.size()));
      }
    }
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
  }
  EXPECT_TRUE(anySkinned);
  for (const gfx::ModelBone& b : m.bones) EXPECT_GE(b.node, 0) << b.name;
}

TEST(Skinning, SkinningMatricesAreIdentityAtTheBindPose) {
  const gfx::Model m = loadOrFail(kSkin);
  const auto skin = gfx::skinningMatrices(m, gfx::bindPoseGlobals(m));
  ASSERT_EQ(skin.size(), m.bones.size());
  for (std::size_t b = 0; b < skin.size(); ++b) {
    EXPECT_LT(maxAbsDifference(skin[b], glm::mat4(1.0f)), 1e-4f) << m.bones[b].name;
  }
}

TEST(Skinning, RestPoseSkinningMatricesAreRigidMotions) {
  // simple_skin's rest pose is its bind pose shifted by 0.5 m: every skinning matrix is then a rigid
  // motion (orthonormal 3x3, last row 0 0 0 1).
  const gfx::Model m = loadOrFail(kSkin);
  for (const glm::mat4& s : gfx::skinningMatrices(m, gfx::globalTransforms(m, gfx::restPose(m)))) {
    const glm::mat3 r(s);
    EXPECT_LT(maxAbsDifference(glm::mat4(glm::transpose(r) * r), glm::mat4(1.0f)), 1e-5f);
    EXPECT_NEAR(s[0][3] + s[1][3] + s[2][3], 0.0f, 1e-6f);
    EXPECT_NEAR(s[3][3], 1.0f, 1e-6f);
  }
}

TEST(Skinning, CpuLinearBlendSkinningMatchesAHandWrittenReference) {
  const gfx::Model m = loadOrFail(kSkin);
  ASSERT_FALSE(m.animations.empty());
  const auto skin = gfx::skinningMatrices(m, gfx::globalTransforms(m, gfx::sampleAnimation(m, m.animations[0], 0.5f)));
  for (const gfx::ModelMesh& mesh : m.meshes) {
    if (!mesh.skinned()) continue;
    const auto skinned = gfx::skinPositions(mesh, skin);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      // Reference: blend the matrices first, then transform (algebraically equal to blending points).
      glm::mat4 blended(0.0f);
      for (int k = 0; k < 4; ++k)
        blended += mesh.boneWeights[v][k] * skin[static_cast<std::size_t>(mesh.boneIds[v][k])];
      const glm::vec3 expected = glm::vec3(blended * glm::vec4(mesh.positions[v], 1.0f));
      EXPECT_LT(glm::distance(skinned[v], expected), 1e-5f) << "vertex " << v;
    }
    // At the bind pose the skinned mesh equals the input mesh.
    const auto bind = gfx::skinPositions(mesh, gfx::skinningMatrices(m, gfx::bindPoseGlobals(m)));
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) EXPECT_LT(glm::distance(bind[v], mesh.positions[v]), 1e-4f);
  }
}

TEST(Skinning, AnimationSamplingInterpolatesBetweenKeys) {
  // A hand-made one-node model: translation keys 0 s -> (0,0,0), 2 s -> (2,4,0); rotation 0 -> 90 deg about z.
  gfx::Model m;
  m.nodes.push_back({"root", -1, glm::mat4(1.0f)});
  gfx::Animation a;
  a.duration = 2.0f;
  gfx::NodeChannel c;
  c.node = 0;
  c.positions = {{0.0f, glm::vec3(0.0f)}, {2.0f, glm::vec3(2.0f, 4.0f, 0.0f)}};
  c.rotations = {{0.0f, glm::quat(1, 0, 0, 0)}, {2.0f, glm::angleAxis(1.5707963f, glm::vec3(0, 0, 1))}};
  a.channels.push_back(c);
  const glm::mat4 mid = gfx::sampleAnimation(m, a, 1.0f, false)[0];
  EXPECT_NEAR(mid[3].x, 1.0f, 1e-5f);
  EXPECT_NEAR(mid[3].y, 2.0f, 1e-5f);
  const glm::vec3 x = glm::vec3(mid * glm::vec4(1, 0, 0, 0));  // rotated by 45 degrees
  EXPECT_NEAR(x.x, std::sqrt(0.5f), 1e-5f);
  EXPECT_NEAR(x.y, std::sqrt(0.5f), 1e-5f);
  const glm::mat4 after = gfx::sampleAnimation(m, a, 5.0f, false)[0];  // clamps to the last key
  EXPECT_NEAR(after[3].y, 4.0f, 1e-5f);
}

TEST(ModelImport, MissingFileGivesAnErrorNamingThePath) {
  std::string error;
  const std::string path = "/nonexistent/dir/robot.gltf";
  EXPECT_FALSE(gfx::loadModel(path, &error).has_value());
  EXPECT_NE(error.find(path), std::string::npos) << error;
}

TEST(ModelImport, GarbageFileGivesAnErrorNamingThePathAndDoesNotCrash) {
  for (const char* ext : {".gltf", ".obj", ".fbx", ".bvh", ".dae", ".xyz"}) {
    const std::string path =
        (std::filesystem::temp_directory_path() / (std::string("pba_garbage_model") + ext)).string();
    {
      std::ofstream out(path, std::ios::binary);
      for (int i = 0; i < 997; ++i) out.put(static_cast<char>((i * 7919 + 13) % 251));
    }
    std::string error;
    const auto model = gfx::loadModel(path, &error);
    if (!model) {
      EXPECT_NE(error.find(path), std::string::npos) << error;
      EXPECT_GT(error.size(), path.size() + 2) << "the reason must follow the path";
    }  // else: some format accepted the bytes; not crashing is what this test is about
    std::remove(path.c_str());
  }
}
