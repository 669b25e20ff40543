// Pose math for Model: local -> global node transforms, animation sampling (lerp positions and
// scales, slerp rotations between keys) and linear blend skinning (LBS) on the CPU, the reference
// the vertex shader (skinned.vert) implements:  v' = sum_i w_i * (G_bone_i * Offset_i) * v.
#pragma once

#include "graphics/model.h"

#include <vector>

namespace pba::graphics {

/// Local transforms of the rest (bind) pose, one per node.
std::vector<glm::mat4> restPose(const Model& model);

/// Global transforms of the bind pose, the pose the mesh was skinned in: each bone node at
/// inverse(offset), other nodes following their parent with their rest local transform. The rest pose
/// (node transforms in the file) may differ from it: e.g. glTF's simple_skin binds 0.5 m to the side.
std::vector<glm::mat4> bindPoseGlobals(const Model& model);

/// Global transforms from locals: G[i] = G[parent(i)] * L[i] (parents precede children in Model::nodes).
std::vector<glm::mat4> globalTransforms(const Model& model, const std::vector<glm::mat4>& local);

/// Local transforms at time t (s). Nodes without a channel keep their rest transform; a channel with
/// no keys of one kind keeps that part of the rest transform. loop = true wraps t into [0, duration).
std::vector<glm::mat4> sampleAnimation(const Model& model, const Animation& animation, float t, bool loop = true);

/// Skinning matrices S[b] = G[bone b's node] * Offset[b], one per bone (identity at the bind pose).
std::vector<glm::mat4> skinningMatrices(const Model& model, const std::vector<glm::mat4>& global);

/// CPU linear blend skinning of one mesh's positions (unskinned meshes are returned unchanged).
std::vector<glm::vec3> skinPositions(const ModelMesh& mesh, const std::vector<glm::mat4>& skinning);
/// The same blend applied to the normals (linear parts of the skinning matrices), renormalised.
std::vector<glm::vec3> skinNormals(const ModelMesh& mesh, const std::vector<glm::mat4>& skinning);

}  // namespace pba::graphics
