// Assimp import into the plain Model structure (see model.h).
#include "graphics/model.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <filesystem>
#include <unordered_map>

namespace pba::graphics {
namespace {

glm::mat4 toGlm(const aiMatrix4x4& m) {
  // Assimp is row-major (a1..a4 is the first row); GLM is column-major.
  return glm::mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4, m.c4, m.d4);
}

void addNodes(const aiNode* node, int parent, Model& model, std::unordered_map<const aiNode*, int>& index) {
  const int self = static_cast<int>(model.nodes.size());
  model.nodes.push_back(ModelNode{node->mName.C_Str(), parent, toGlm(node->mTransformation)});
  index[node] = self;
  for (unsigned c = 0; c < node->mNumChildren; ++c) addNodes(node->mChildren[c], self, model, index);
}

void assignMeshNodes(const aiNode* node, const std::unordered_map<const aiNode*, int>& index, Model& model) {
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    const unsigned m = node->mMeshes[i];
    if (m < model.meshes.size() && model.meshes[m].node < 0) model.meshes[m].node = index.at(node);
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) assignMeshNodes(node->mChildren[c], index, model);
}

/// Keeps the 4 largest influences of each vertex and renormalises them to sum 1.
void addBoneWeight(ModelMesh& mesh, unsigned vertex, int bone, float weight) {
  glm::ivec4& ids = mesh.boneIds[vertex];
  glm::vec4& w = mesh.boneWeights[vertex];
  int smallest = 0;
  for (int k = 1; k < kMaxBonesPerVertex; ++k) {
    if (w[k] < w[smallest]) smallest = k;
  }
  if (weight > w[smallest]) {
    w[smallest] = weight;
    ids[smallest] = bone;
  }
}

ModelMesh convertMesh(const aiMesh* src, const aiScene* scene, Model& model) {
  ModelMesh mesh;
  mesh.name = src->mName.C_Str();
  mesh.positions.reserve(src->mNumVertices);
  for (unsigned v = 0; v < src->mNumVertices; ++v) {
    mesh.positions.emplace_back(src->mVertices[v].x, src->mVertices[v].y, src->mVertices[v].z);
    if (src->HasNormals()) {
      const glm::vec3 n(src->mNormals[v].x, src->mNormals[v].y, src->mNormals[v].z);
      const float len = glm::length(n);
      mesh.normals.push_back(len > 1e-12f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f));
    } else {
      mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  }
  for (unsigned f = 0; f < src->mNumFaces; ++f) {
    const aiFace& face = src->mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines left over by Triangulate
    mesh.indices.insert(mesh.indices.end(), {face.mIndices[0], face.mIndices[1], face.mIndices[2]});
  }
  if (src->mMaterialIndex < scene->mNumMaterials) {
    aiColor4D diffuse;
    if (scene->mMaterials[src->mMaterialIndex]->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS) {
      mesh.color = glm::vec4(diffuse.r, diffuse.g, diffuse.b, 1.0f);
    }
    // Assimp's SkeletonMeshBuilder gives joint-only files (BVH) a stand-in mesh with this material.
    aiString material;
    if (scene->mMaterials[src->mMaterialIndex]->Get(AI_MATKEY_NAME, material) == AI_SUCCESS)
      mesh.placeholder = std::string(material.C_Str()) == "SkeletonMaterial";
  }
  if (src->mNumBones == 0) return mesh;
  mesh.boneIds.assign(src->mNumVertices, glm::ivec4(0));
  mesh.boneWeights.assign(src->mNumVertices, glm::vec4(0.0f));
  for (unsigned b = 0; b < src->mNumBones; ++b) {
    const aiBone* bone = src->mBones[b];
    int id = model.findBone(bone->mName.C_Str());
    if (id < 0) {
      id = static_cast<int>(model.bones.size());
      model.bones.push_back(
          ModelBone{bone->mName.C_Str(), model.findNode(bone->mName.C_Str()), toGlm(bone->mOffsetMatrix)});
    }
    for (unsigned w = 0; w < bone->mNumWeights; ++w) {
      const aiVertexWeight& vw = bone->mWeights[w];
      if (vw.mVertexId < src->mNumVertices && vw.mWeight > 0.0f) addBoneWeight(mesh, vw.mVertexId, id, vw.mWeight);
    }
  }
  for (std::size_t v = 0; v < mesh.boneWeights.size(); ++v) {
    glm::vec4& w = mesh.boneWeights[v];
    const float sum = w.x + w.y + w.z + w.w;
    if (sum > 1e-8f) {
      w /= sum;
    } else {  // an unweighted vertex follows the first bone rigidly
      w = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
      mesh.boneIds[v] = glm::ivec4(0);
    }
  }
  return mesh;
}

Animation convertAnimation(const aiAnimation* src, const Model& model) {
  Animation anim;
  anim.name = src->mName.C_Str();
  // Assimp's convention: 0 ticks per second means "unspecified", conventionally 25.
  const double ticksPerSecond = src->mTicksPerSecond > 0.0 ? src->mTicksPerSecond : 25.0;
  anim.duration = static_cast<float>(src->mDuration / ticksPerSecond);
  auto seconds = [&](double ticks) { return static_cast<float>(ticks / ticksPerSecond); };
  for (unsigned c = 0; c < src->mNumChannels; ++c) {
    const aiNodeAnim* ch = src->mChannels[c];
    NodeChannel channel;
    channel.node = model.findNode(ch->mNodeName.C_Str());
    if (channel.node < 0) continue;
    for (unsigned k = 0; k < ch->mNumPositionKeys; ++k) {
      const aiVectorKey& key = ch->mPositionKeys[k];
      channel.positions.push_back({seconds(key.mTime), glm::vec3(key.mValue.x, key.mValue.y, key.mValue.z)});
    }
    for (unsigned k = 0; k < ch->mNumRotationKeys; ++k) {
      const aiQuatKey& key = ch->mRotationKeys[k];
      channel.rotations.push_back(
          {seconds(key.mTime), glm::quat(key.mValue.w, key.mValue.x, key.mValue.y, key.mValue.z)});
    }
    for (unsigned k = 0; k < ch->mNumScalingKeys; ++k) {
      const aiVectorKey& key = ch->mScalingKeys[k];
      channel.scales.push_back({seconds(key.mTime), glm::vec3(key.mValue.x, key.mValue.y, key.mValue.z)});
    }
    anim.channels.push_back(std::move(channel));
  }
  return anim;
}

}  // namespace

int Model::findNode(const std::string& name) const {
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int Model::findBone(const std::string& name) const {
  for (std::size_t i = 0; i < bones.size(); ++i) {
    if (bones[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::optional<Model> loadModel(const std::string& path, std::string* error) {
  auto fail = [&](const std::string& why) -> std::optional<Model> {
    if (error) *error = path + ": " + why;
    return std::nullopt;
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return fail("no such file");
  Assimp::Importer importer;
  const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals |
                         aiProcess_LimitBoneWeights | aiProcess_SortByPType;
  const aiScene* scene = nullptr;
  try {
    scene = importer.ReadFile(path, flags);
  } catch (const std::exception& e) {  // Assimp reports through the return value; be safe anyway
    return fail(e.what());
  }
  if (!scene || !scene->mRootNode) {
    const std::string message = importer.GetErrorString();
    return fail(message.empty() ? "Assimp could not read the file" : message);
  }
  if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) {
    const bool onlyAnimation = scene->mNumAnimations > 0;  // BVH files carry a skeleton and motion only
    if (!onlyAnimation) return fail("incomplete scene (Assimp flagged it AI_SCENE_FLAGS_INCOMPLETE)");
  }
  Model model;
  model.path = path;
  std::unordered_map<const aiNode*, int> nodeIndex;
  addNodes(scene->mRootNode, -1, model, nodeIndex);
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    if (!(scene->mMeshes[m]->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) {
      model.meshes.push_back(ModelMesh{});  // keep mesh indices aligned with Assimp's
      continue;
    }
    model.meshes.push_back(convertMesh(scene->mMeshes[m], scene, model));
  }
  assignMeshNodes(scene->mRootNode, nodeIndex, model);
  for (unsigned a = 0; a < scene->mNumAnimations; ++a)
    model.animations.push_back(convertAnimation(scene->mAnimations[a], model));
  if (model.bones.size() > static_cast<std::size_t>(kMaxSkinningBones)) {
    return fail("has " + std::to_string(model.bones.size()) + " bones; the skinning shader supports " +
                std::to_string(kMaxSkinningBones));
  }
  return model;
}

}  // namespace pba::graphics
