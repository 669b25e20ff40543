// Assimp import into the plain Model structure (see model.h).
#include "graphics/model.h"

#include <assimp/BaseImporter.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <new>
#include <set>
#include <sstream>
#include <unordered_map>

namespace pba::graphics {
namespace {

/// Names to indices, first occurrence (as Model::findNode/findBone): a lookup per bone and channel in
/// constant time, so a skeleton of thousands of joints converts in linear time.
struct NameIndex {
  std::unordered_map<std::string, int> nodes, bones;
  int node(const std::string& name) const {
    const auto it = nodes.find(name);
    return it == nodes.end() ? -1 : it->second;
  }
};

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

ModelMesh convertMesh(const aiMesh* src, const aiScene* scene, Model& model, NameIndex& names) {
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
    const auto [found, added] = names.bones.emplace(bone->mName.C_Str(), static_cast<int>(model.bones.size()));
    const int id = found->second;
    if (added)
      model.bones.push_back(
          ModelBone{bone->mName.C_Str(), names.node(bone->mName.C_Str()), toGlm(bone->mOffsetMatrix)});
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

Animation convertAnimation(const aiAnimation* src, const NameIndex& names) {
  Animation anim;
  anim.name = src->mName.C_Str();
  // Assimp's convention: 0 ticks per second means "unspecified", conventionally 25.
  const double ticksPerSecond = src->mTicksPerSecond > 0.0 ? src->mTicksPerSecond : 25.0;
  anim.duration = static_cast<float>(src->mDuration / ticksPerSecond);
  auto seconds = [&](double ticks) { return static_cast<float>(ticks / ticksPerSecond); };
  for (unsigned c = 0; c < src->mNumChannels; ++c) {
    const aiNodeAnim* ch = src->mChannels[c];
    NodeChannel channel;
    channel.node = names.node(ch->mNodeName.C_Str());
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

/// Assimp's messages may span lines; an error is one line (docs/architecture.md §4).
std::string oneLine(std::string text) {
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::quat& q) { return std::isfinite(q.w) && finite(glm::vec3(q.x, q.y, q.z)); }
bool finite(const glm::mat4& m) {
  return finite(glm::vec3(m[0])) && finite(glm::vec3(m[1])) && finite(glm::vec3(m[2])) && finite(glm::vec3(m[3]));
}

std::string named(const std::string& kind, const std::string& name, std::size_t index) {
  // Appended piece by piece: GCC 12 at -O3 reports a false -Wrestrict for "'" + std::string&&.
  std::string text = kind;
  text += ' ';
  if (name.empty()) {
    text += '#';
    text += std::to_string(index);
  } else {
    text += '\'';
    text += oneLine(name);
    text += '\'';
  }
  return text;
}

template <typename T>
bool keysFinite(const std::vector<Key<T>>& keys) {
  return std::all_of(keys.begin(), keys.end(),
                     [](const Key<T>& k) { return std::isfinite(k.time) && finite(k.value); });
}

/// What Assimp's BVH reader trusts: its joints nest by recursion (a file of 100,000 nested joints
/// overflows the stack), and it reserves room for "Frames: N" frames before reading them (a typo of
/// 2000000000 asks for gigabytes). Joints nest at most kMaxBvhDepth deep, and N frames must fit in the
/// bytes after the count. Empty when the file passes, else the reason with its line.
constexpr int kMaxBvhDepth = 256;

std::string checkBvhText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::uintmax_t lineNumber = 0, offset = 0;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  int depth = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    offset += line.size() + 1;
    for (const char c : line) {
      depth += c == '{' ? 1 : c == '}' ? -1 : 0;
      if (depth > kMaxBvhDepth)
        return "line " + std::to_string(lineNumber) + ": joints nested deeper than " + std::to_string(kMaxBvhDepth);
    }
    const std::size_t at = line.find("Frames:");
    if (at == std::string::npos) continue;
    std::istringstream number(line.substr(at + 7));
    long long frames = 0;
    if (!(number >> frames) || frames < 0)
      return "line " + std::to_string(lineNumber) + ": Frames: must be a whole number >= 0";
    // A frame takes at least two bytes ("0\n"); what is left of the file bounds the count.
    const std::uintmax_t left = size > offset ? size - offset : 0;
    if (static_cast<std::uintmax_t>(frames) > left / 2 + 1)
      return "line " + std::to_string(lineNumber) + ": Frames: " + std::to_string(frames) +
             " frames cannot fit in the " + std::to_string(left) + " bytes after it";
    return {};
  }
  return {};
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string modelExtensionList() {
  std::string list;
  for (const std::string_view ext : kModelExtensions) list += (list.empty() ? "" : ", ") + std::string(ext);
  return list;
}

bool isBvh(const std::string& path) { return lowerExtension(path) == ".bvh"; }

/// Leaves in `importer` only the readers that claim the file's extension, one of kModelExtensions; false
/// for any other extension. When two readers claim it (.gltf, .glb) and neither recognises the contents,
/// Assimp 5.2 falls back to offering the file to every reader it has, and readers of formats we never
/// asked for parse it: a 31-byte .glb went to the OpenGEX reader, which read past its buffer (found by
/// fuzz_model_import). A model file is read by the reader its extension names, or refused.
bool keepOnlyReadersOfExtension(Assimp::Importer& importer, const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (std::find(kModelExtensions.begin(), kModelExtensions.end(), ext) == kModelExtensions.end()) return false;
  std::vector<Assimp::BaseImporter*> others;
  for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
    Assimp::BaseImporter* reader = importer.GetImporter(i);
    // The reader's extensions from its description ("gltf glb"): a plain C string, so this also links
    // where Assimp was built against another C++ standard library (the libcxx preset).
    const aiImporterDesc* info = reader->GetInfo();
    std::istringstream words(info && info->mFileExtensions ? info->mFileExtensions : "");
    bool claims = false;
    for (std::string word; words >> word;) claims = claims || word == ext.substr(1);
    if (!claims) others.push_back(reader);
  }
  for (Assimp::BaseImporter* reader : others) {
    importer.UnregisterLoader(reader);  // the importer no longer owns it
    delete reader;
  }
  return true;
}

/// What the importers let through and the code downstream must not see: non-finite numbers, triangles
/// pointing past their mesh's vertices. Empty when the model is sound, else the reason.
std::string checkModel(const Model& model) {
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    if (!finite(model.nodes[n].local)) return named("node", model.nodes[n].name, n) + ": transform is not finite";
  for (std::size_t m = 0; m < model.meshes.size(); ++m) {
    const ModelMesh& mesh = model.meshes[m];
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      if (!finite(mesh.positions[v]))
        return named("mesh", mesh.name, m) + ": vertex " + std::to_string(v) + " is not finite";
    for (std::size_t i = 0; i < mesh.indices.size(); ++i)
      if (mesh.indices[i] >= mesh.positions.size())
        return named("mesh", mesh.name, m) + ": triangle " + std::to_string(i / 3) + " uses vertex " +
               std::to_string(mesh.indices[i]) + " of " + std::to_string(mesh.positions.size());
  }
  for (const Animation& a : model.animations)
    for (const NodeChannel& c : a.channels)
      if (c.node < 0 || c.node >= static_cast<int>(model.nodes.size()))
        return "animation '" + oneLine(a.name) + "': a channel drives no node of the file";
  for (const Animation& a : model.animations)
    for (const NodeChannel& c : a.channels)
      if (!keysFinite(c.positions) || !keysFinite(c.rotations) || !keysFinite(c.scales))
        return "animation '" + oneLine(a.name) + "': a key of " + named("node", model.nodes[c.node].name, c.node) +
               " is not finite";
  return {};
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
  if (std::filesystem::is_directory(path, ec)) return fail("is a directory, not a model file");
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    return fail("is not a regular file (a device or a pipe?)");
  if (!std::filesystem::is_regular_file(path, ec)) return fail("no such file");
  if (const auto size = std::filesystem::file_size(path, ec); !ec && size > kMaxModelFileBytes)
    return fail("is " + std::to_string(size) + " bytes; model files are read up to " +
                std::to_string(kMaxModelFileBytes) + " bytes");
  Assimp::Importer importer;
  if (!keepOnlyReadersOfExtension(importer, path)) {
    const std::string ext = oneLine(std::filesystem::path(path).extension().string());
    return fail(
        (ext.empty() ? std::string("the name has no extension") : "'" + ext + "' is not a model format read here") +
        " (" + modelExtensionList() + ")");
  }
  const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals |
                         aiProcess_LimitBoneWeights | aiProcess_SortByPType;
  const aiScene* scene = nullptr;
  if (isBvh(path)) {
    if (const std::string bad = checkBvhText(path); !bad.empty()) return fail(bad);
  }
  try {
    scene = importer.ReadFile(path, flags);
  } catch (const std::bad_alloc&) {
    return fail("out of memory while Assimp read it (a count in the file larger than its data?)");
  } catch (const std::exception& e) {  // Assimp reports through the return value; be safe anyway
    return fail(oneLine(e.what()));
  }
  if (!scene || !scene->mRootNode) {
    std::string message = oneLine(importer.GetErrorString());
    // Text readers say "<path>:<line> - <what>"; the path is already in front of the message.
    if (message.rfind(path + ":", 0) == 0) {
      const std::size_t dash = message.find(" - ", path.size());
      const std::string line = message.substr(path.size() + 1, dash == std::string::npos ? 0 : dash - path.size() - 1);
      if (!line.empty() && line.find_first_not_of("0123456789") == std::string::npos)
        message = "line " + line + ": " + message.substr(dash + 3);
    }
    return fail(message.empty() ? "Assimp could not read the file" : message);
  }
  if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) {
    const bool onlyAnimation = scene->mNumAnimations > 0;  // BVH files carry a skeleton and motion only
    if (!onlyAnimation) return fail("incomplete scene (Assimp flagged it AI_SCENE_FLAGS_INCOMPLETE)");
  }
  for (unsigned a = 0; a < scene->mNumAnimations; ++a) {
    // 0 means "unspecified" (25 assumed below); a negative or non-finite rate (a BVH Frame Time of 0 or
    // below) would silently play at 25 frames/s or collapse the clip to an instant.
    const double rate = scene->mAnimations[a]->mTicksPerSecond;
    if (!std::isfinite(rate) || rate < 0.0)
      return fail("animation '" + oneLine(scene->mAnimations[a]->mName.C_Str()) + "': " + std::to_string(rate) +
                  " ticks per second (a BVH Frame Time must be > 0)");
  }
  Model model;
  model.path = path;
  std::unordered_map<const aiNode*, int> nodeIndex;
  addNodes(scene->mRootNode, -1, model, nodeIndex);
  NameIndex names;
  for (std::size_t n = 0; n < model.nodes.size(); ++n) names.nodes.emplace(model.nodes[n].name, static_cast<int>(n));
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    if (!(scene->mMeshes[m]->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) {
      model.meshes.push_back(ModelMesh{});  // keep mesh indices aligned with Assimp's
      continue;
    }
    model.meshes.push_back(convertMesh(scene->mMeshes[m], scene, model, names));
  }
  assignMeshNodes(scene->mRootNode, nodeIndex, model);
  for (unsigned a = 0; a < scene->mNumAnimations; ++a)
    model.animations.push_back(convertAnimation(scene->mAnimations[a], names));
  if (const std::string bad = checkModel(model); !bad.empty()) return fail(bad);
  if (model.bones.size() > static_cast<std::size_t>(kMaxSkinningBones)) {
    return fail("has " + std::to_string(model.bones.size()) + " bones; the skinning shader supports " +
                std::to_string(kMaxSkinningBones));
  }
  return model;
}

}  // namespace pba::graphics
