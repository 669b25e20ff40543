// glTF 2.0 import against the file: the test reads the JSON itself (nlohmann-json) and takes the
// skin's joints (skins[].joints) with their node transforms (matrix, or translation/rotation/scale,
// glTF 2.0 specification §5.25 "node"). The model must hold those joints under their file parents
// with the same transforms, and one bone per joint.
#include "graphics/model.h"
#include "model_file_check.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <map>
#include <set>

namespace {

namespace gfx = pba::graphics;
using namespace pba::testing::models;
using nlohmann::json;

const std::string kSkinnedGltf = kAssimpModels + "glTF2/simple_skin/simple_skin.gltf";

/// Assimp names a glTF node after its "name", or "nodes[<index>]" when the node has none.
std::string gltfNodeName(const json& nodes, std::size_t i) {
  const json& node = nodes.at(i);
  return node.contains("name") ? node["name"].get<std::string>() : "nodes[" + std::to_string(i) + "]";
}

/// Local transform of a node: "matrix" (16 numbers, column-major) or T·R·S from "translation",
/// "rotation" (quaternion x, y, z, w) and "scale", each defaulting to the identity.
glm::dmat4 gltfLocal(const json& node) {
  glm::dmat4 m(1.0);
  if (node.contains("matrix")) {
    for (int k = 0; k < 16; ++k) m[k / 4][k % 4] = node["matrix"].at(static_cast<std::size_t>(k)).get<double>();
    return m;
  }
  glm::dvec3 t(0.0), s(1.0);
  glm::dquat r(1.0, 0.0, 0.0, 0.0);
  const auto vec3 = [](const json& v) {
    return glm::dvec3(v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>());
  };
  if (node.contains("translation")) t = vec3(node["translation"]);
  if (node.contains("scale")) s = vec3(node["scale"]);
  if (node.contains("rotation")) {
    const json& q = node["rotation"];
    r = glm::dquat(q[3].get<double>(), q[0].get<double>(), q[1].get<double>(), q[2].get<double>());
  }
  return glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(r) * glm::scale(glm::dmat4(1.0), s);
}

struct GltfSkeleton {
  std::vector<FileJoint> joints;  ///< every node listed in skins[].joints, once
};

GltfSkeleton readGltfSkeleton(const std::string& path) {
  const json doc = json::parse(readBytes(path));
  const json& nodes = doc.at("nodes");
  std::map<std::size_t, std::size_t> parentOf;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].contains("children"))
      for (const json& c : nodes[i]["children"]) parentOf[c.get<std::size_t>()] = i;
  GltfSkeleton g;
  std::set<std::size_t> seen;
  for (const json& skin : doc.value("skins", json::array())) {
    for (const json& j : skin.at("joints")) {
      const std::size_t i = j.get<std::size_t>();
      if (!seen.insert(i).second) continue;
      FileJoint joint;
      joint.name = gltfNodeName(nodes, i);
      if (parentOf.count(i)) joint.parent = gltfNodeName(nodes, parentOf[i]);
      joint.local = gltfLocal(nodes[i]);
      g.joints.push_back(joint);
    }
  }
  return g;
}

}  // namespace

TEST(ModelImportGltf, SkinJointsAreNodesUnderTheirFileParentsWithTheirTransforms) {
  const gfx::Model m = loadOrFail(kSkinnedGltf);
  if (m.nodes.empty()) return;
  const GltfSkeleton g = readGltfSkeleton(kSkinnedGltf);
  ASSERT_GT(g.joints.size(), 1u);
  EXPECT_EQ(countNodesNamedLike(m, g.joints), static_cast<int>(g.joints.size()));
  expectJointsMatchTheFile(m, g.joints);
  ::testing::Test::RecordProperty("joints simple_skin", static_cast<int>(g.joints.size()));
}

TEST(ModelImportGltf, EverySkinJointIsABoneDrivenByItsNode) {
  const gfx::Model m = loadOrFail(kSkinnedGltf);
  if (m.nodes.empty()) return;
  const GltfSkeleton g = readGltfSkeleton(kSkinnedGltf);
  EXPECT_EQ(m.bones.size(), g.joints.size());
  for (const FileJoint& j : g.joints) {
    const int b = m.findBone(j.name);
    ASSERT_GE(b, 0) << j.name;
    EXPECT_EQ(m.bones[static_cast<std::size_t>(b)].node, m.findNode(j.name)) << j.name;
  }
}

TEST(ModelImportGltf, NamedJointRestTranslationIsTheFiles) {
  const gfx::Model m = loadOrFail(kSkinnedGltf);
  if (m.nodes.empty()) return;
  const GltfSkeleton g = readGltfSkeleton(kSkinnedGltf);
  // The skin's first joint: simple_skin's only joint with a non-zero translation.
  ASSERT_FALSE(g.joints.empty());
  const FileJoint& joint = g.joints.front();
  const glm::dvec3 file(joint.local[3]);
  ASSERT_GT(glm::length(file), 0.1) << "a translated joint makes the comparison meaningful";
  expectLocalTranslationNear(m, joint.name, file);
}

TEST(ModelImportGltf, TruncatedFileGivesAnErrorNamingThePath) { expectTruncatedCopyFails(kSkinnedGltf); }
