// Animation sampling, global transforms and CPU linear blend skinning (see skinning.h).
#include "graphics/skinning.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <algorithm>
#include <cmath>

namespace pba::graphics {
namespace {

/// Index i of the key interval [keys[i], keys[i+1]] containing t and the blend factor in [0, 1].
template <typename T>
std::pair<std::size_t, float> bracket(const std::vector<Key<T>>& keys, float t) {
  if (keys.size() < 2 || t <= keys.front().time) return {0, 0.0f};
  if (t >= keys.back().time) return {keys.size() - 1, 0.0f};
  const auto upper =
      std::upper_bound(keys.begin(), keys.end(), t, [](float time, const Key<T>& key) { return time < key.time; });
  const std::size_t i = static_cast<std::size_t>(upper - keys.begin()) - 1;
  const float span = keys[i + 1].time - keys[i].time;
  return {i, span > 1e-9f ? (t - keys[i].time) / span : 0.0f};
}

glm::vec3 sampleVec(const std::vector<Key<glm::vec3>>& keys, float t, const glm::vec3& fallback) {
  if (keys.empty()) return fallback;
  const auto [i, s] = bracket(keys, t);
  if (i + 1 >= keys.size()) return keys[i].value;
  return glm::mix(keys[i].value, keys[i + 1].value, s);
}

glm::quat sampleQuat(const std::vector<Key<glm::quat>>& keys, float t, const glm::quat& fallback) {
  if (keys.empty()) return fallback;
  const auto [i, s] = bracket(keys, t);
  if (i + 1 >= keys.size()) return keys[i].value;
  glm::quat b = keys[i + 1].value;
  if (glm::dot(keys[i].value, b) < 0.0f) b = -b;  // shortest arc
  return glm::normalize(glm::slerp(keys[i].value, b, s));
}

}  // namespace

std::vector<glm::mat4> restPose(const Model& model) {
  std::vector<glm::mat4> local;
  local.reserve(model.nodes.size());
  for (const ModelNode& node : model.nodes) local.push_back(node.local);
  return local;
}

std::vector<glm::mat4> globalTransforms(const Model& model, const std::vector<glm::mat4>& local) {
  std::vector<glm::mat4> global(model.nodes.size(), glm::mat4(1.0f));
  for (std::size_t i = 0; i < model.nodes.size() && i < local.size(); ++i) {
    const int parent = model.nodes[i].parent;
    global[i] = parent >= 0 ? global[static_cast<std::size_t>(parent)] * local[i] : local[i];
  }
  return global;
}

std::vector<glm::mat4> bindPoseGlobals(const Model& model) {
  std::vector<glm::mat4> global = globalTransforms(model, restPose(model));
  std::vector<int> boneOfNode(model.nodes.size(), -1);
  for (std::size_t b = 0; b < model.bones.size(); ++b) {
    const int node = model.bones[b].node;
    if (node >= 0 && static_cast<std::size_t>(node) < boneOfNode.size())
      boneOfNode[static_cast<std::size_t>(node)] = static_cast<int>(b);
  }
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const int parent = model.nodes[i].parent;
    if (boneOfNode[i] >= 0) {
      global[i] = glm::inverse(model.bones[static_cast<std::size_t>(boneOfNode[i])].offset);
    } else if (parent >= 0) {
      global[i] = global[static_cast<std::size_t>(parent)] * model.nodes[i].local;
    }
  }
  return global;
}

std::vector<glm::mat4> sampleAnimation(const Model& model, const Animation& animation, float t, bool loop) {
  std::vector<glm::mat4> local = restPose(model);
  if (loop && animation.duration > 0.0f) {
    t = std::fmod(t, animation.duration);
    if (t < 0.0f) t += animation.duration;
  }
  for (const NodeChannel& channel : animation.channels) {
    if (channel.node < 0 || static_cast<std::size_t>(channel.node) >= local.size()) continue;
    glm::mat4& m = local[static_cast<std::size_t>(channel.node)];
    glm::vec3 scale(1.0f), translation(0.0f), skew(0.0f);
    glm::vec4 perspective(0.0f);
    glm::quat rotation(1.0f, 0.0f, 0.0f, 0.0f);
    glm::decompose(m, scale, rotation, translation, skew, perspective);  // rest values for missing keys
    translation = sampleVec(channel.positions, t, translation);
    rotation = sampleQuat(channel.rotations, t, rotation);
    scale = sampleVec(channel.scales, t, scale);
    m = glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), scale);
  }
  return local;
}

std::vector<glm::mat4> skinningMatrices(const Model& model, const std::vector<glm::mat4>& global) {
  std::vector<glm::mat4> skin(model.bones.size(), glm::mat4(1.0f));
  for (std::size_t b = 0; b < model.bones.size(); ++b) {
    const int node = model.bones[b].node;
    const glm::mat4 g = node >= 0 && static_cast<std::size_t>(node) < global.size()
                            ? global[static_cast<std::size_t>(node)]
                            : glm::mat4(1.0f);
    skin[b] = g * model.bones[b].offset;
  }
  return skin;
}

std::vector<glm::vec3> skinPositions(const ModelMesh& mesh, const std::vector<glm::mat4>& skinning) {
  if (!mesh.skinned()) return mesh.positions;
  std::vector<glm::vec3> out(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    glm::vec4 p(0.0f);
    for (int k = 0; k < kMaxBonesPerVertex; ++k) {
      const float w = mesh.boneWeights[v][k];
      const auto bone = static_cast<std::size_t>(mesh.boneIds[v][k]);
      if (w > 0.0f && bone < skinning.size()) p += w * (skinning[bone] * glm::vec4(mesh.positions[v], 1.0f));
    }
    out[v] = glm::vec3(p);
  }
  return out;
}

std::vector<glm::vec3> skinNormals(const ModelMesh& mesh, const std::vector<glm::mat4>& skinning) {
  if (!mesh.skinned()) return mesh.normals;
  std::vector<glm::vec3> out(mesh.normals.size());
  for (std::size_t v = 0; v < mesh.normals.size() && v < mesh.boneWeights.size(); ++v) {
    glm::vec3 n(0.0f);
    for (int k = 0; k < kMaxBonesPerVertex; ++k) {
      const float w = mesh.boneWeights[v][k];
      const auto bone = static_cast<std::size_t>(mesh.boneIds[v][k]);
      if (w > 0.0f && bone < skinning.size()) n += w * (glm::mat3(skinning[bone]) * mesh.normals[v]);
    }
    const float length = glm::length(n);
    out[v] = length > 1e-12f ? n / length : mesh.normals[v];
  }
  return out;
}

}  // namespace pba::graphics
