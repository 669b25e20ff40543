// SkinnedMesh: a ModelMesh uploaded with its bone attributes for GPU linear blend skinning
// (skinned.vert; bone matrices in a uniform block of up to kMaxSkinningBones mat4). Layout:
//   0 position (vec3) · 1 normal (vec3) · 2 bone ids (ivec4) · 3 bone weights (vec4)
// An unskinned ModelMesh uploads with all weight on bone 0; draw it with one matrix.
#pragma once

#include "graphics/model.h"

#include "graphics/gl.h"

namespace pba::graphics {

class SkinnedMesh {
 public:
  explicit SkinnedMesh(const ModelMesh& mesh);  ///< needs a current GL context
  ~SkinnedMesh();
  SkinnedMesh(const SkinnedMesh&) = delete;
  SkinnedMesh& operator=(const SkinnedMesh&) = delete;

  /// Binds the VAO and issues the indexed draw; the caller has set the program and bone block.
  void draw() const;
  GLsizei indexCount() const { return indexCount_; }
  const glm::vec3& boundsMin() const { return boundsMin_; }  ///< mesh space, bind pose
  const glm::vec3& boundsMax() const { return boundsMax_; }

 private:
  GLuint vao_ = 0, vbo_[4] = {0, 0, 0, 0}, ebo_ = 0;
  GLsizei indexCount_ = 0;
  glm::vec3 boundsMin_{0.0f}, boundsMax_{0.0f};
};

}  // namespace pba::graphics
