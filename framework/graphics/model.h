// Model: an Assimp import turned into plain CPU data (no GL needed to load, so headless code and tests
// use it too): meshes with up to 4 normalised bone weights per vertex, the node hierarchy (parents
// always before children), bones with their offset (inverse bind) matrices, and animations with key
// times in seconds. Pose math lives in skinning.h.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pba::graphics {

inline constexpr int kMaxBonesPerVertex = 4;
inline constexpr int kMaxSkinningBones = 128;  ///< size of the shader's bone array
/// Larger files are refused before Assimp reads them (it holds the whole file in memory, several times).
inline constexpr std::uintmax_t kMaxModelFileBytes = std::uintmax_t{512} << 20;  ///< 512 MiB
/// The model formats loadModel reads, by extension (lower case): the ones the labs use and the fuzz
/// target tests. Assimp's other readers are never offered a file (see loadModel).
inline constexpr std::array<std::string_view, 10> kModelExtensions = {".bvh", ".obj", ".gltf", ".glb", ".dae",
                                                                      ".fbx", ".x",   ".ply",  ".stl", ".off"};

struct ModelMesh {
  std::string name;
  std::vector<glm::vec3> positions;    ///< mesh space
  std::vector<glm::vec3> normals;      ///< unit
  std::vector<std::uint32_t> indices;  ///< triangles
  std::vector<glm::ivec4> boneIds;     ///< indices into Model::bones (0 where the weight is 0); empty if unskinned
  std::vector<glm::vec4> boneWeights;  ///< sum to 1 per vertex when skinned; empty if unskinned
  int node = -1;                       ///< node that instances the mesh (its global transform places it when unskinned)
  glm::vec4 color{0.8f, 0.8f, 0.8f, 1.0f};  ///< material diffuse colour (sRGB)
  bool placeholder = false;  ///< Assimp's stand-in for a file without meshes (BVH): boxes along the bones

  bool skinned() const { return !boneWeights.empty(); }
};

struct ModelNode {
  std::string name;
  int parent = -1;        ///< index in Model::nodes, -1 for the root; always < own index
  glm::mat4 local{1.0f};  ///< transform relative to the parent (bind / rest pose)
};

struct ModelBone {
  std::string name;
  int node = -1;           ///< node whose global transform drives the bone
  glm::mat4 offset{1.0f};  ///< inverse bind matrix: mesh space -> bone space at bind pose
};

template <typename T>
struct Key {
  float time = 0.0f;  ///< s
  T value{};
};

struct NodeChannel {
  int node = -1;
  std::vector<Key<glm::vec3>> positions;
  std::vector<Key<glm::quat>> rotations;
  std::vector<Key<glm::vec3>> scales;
};

struct Animation {
  std::string name;
  float duration = 0.0f;  ///< s
  std::vector<NodeChannel> channels;
};

struct Model {
  std::string path;
  std::vector<ModelMesh> meshes;
  std::vector<ModelNode> nodes;
  std::vector<ModelBone> bones;
  std::vector<Animation> animations;

  int findNode(const std::string& name) const;  ///< -1 when absent
  int findBone(const std::string& name) const;  ///< -1 when absent
};

/// Loads a file of one of kModelExtensions through the Assimp reader(s) of that extension only. On failure
/// returns nullopt and sets *error to "<path>: <reason>" on one line (Assimp's own message where it has
/// one). Refuses other extensions, directories, files over kMaxModelFileBytes, non-finite numbers and triangles that use a vertex the
/// mesh does not have (naming the node, mesh or animation). Never throws.
std::optional<Model> loadModel(const std::string& path, std::string* error);

}  // namespace pba::graphics
