// Mesh: a MeshData uploaded to the GPU (VAO + VBOs + EBO) with a per-instance buffer, so that N equal
// primitives draw in one glDrawElementsInstanced call. Vertex attribute layout shared by the shaders:
//   0 position (vec3) · 1 normal (vec3) · 2..5 instance model matrix (mat4) · 6 instance colour (vec4)
#pragma once

#include "graphics/mesh_data.h"

#include <glm/glm.hpp>
#include "graphics/gl.h"

#include <vector>

namespace pba::graphics {

/// One instance: object-to-world matrix and linear-space-agnostic RGBA colour (sRGB as authored).
struct Instance {
  glm::mat4 model{1.0f};
  glm::vec4 color{1.0f};
};

class Mesh {
 public:
  explicit Mesh(const MeshData& data);  ///< needs a current GL context
  ~Mesh();
  Mesh(const Mesh&) = delete;
  Mesh& operator=(const Mesh&) = delete;

  /// Replaces the geometry (same layout; for meshes that change every frame).
  void update(const MeshData& data);
  /// Uploads `instances` and draws them all in one instanced call (no-op when empty).
  void drawInstanced(const std::vector<Instance>& instances) const;
  GLsizei indexCount() const { return indexCount_; }
  const glm::vec3& boundsMin() const { return boundsMin_; }  ///< object-space AABB
  const glm::vec3& boundsMax() const { return boundsMax_; }

 private:
  GLuint vao_ = 0, positionVbo_ = 0, normalVbo_ = 0, ebo_ = 0, instanceVbo_ = 0;
  GLsizei indexCount_ = 0;
  mutable GLsizeiptr instanceCapacity_ = 0;  ///< bytes allocated in instanceVbo_
  glm::vec3 boundsMin_{0.0f}, boundsMax_{0.0f};
};

}  // namespace pba::graphics
