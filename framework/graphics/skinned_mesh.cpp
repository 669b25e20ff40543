// SkinnedMesh: GPU upload of positions, normals, bone ids and weights.
#include "graphics/skinned_mesh.h"

#include <vector>

namespace pba::graphics {
namespace {

template <typename T>
void upload(GLuint vbo, const std::vector<T>& data) {
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
}

}  // namespace

SkinnedMesh::SkinnedMesh(const ModelMesh& mesh) : indexCount_(static_cast<GLsizei>(mesh.indices.size())) {
  const std::size_t n = mesh.positions.size();
  if (n > 0) {
    boundsMin_ = boundsMax_ = mesh.positions.front();
    for (const glm::vec3& p : mesh.positions) {
      boundsMin_ = glm::min(boundsMin_, p);
      boundsMax_ = glm::max(boundsMax_, p);
    }
  }
  const std::vector<glm::ivec4> ids = mesh.skinned() ? mesh.boneIds : std::vector<glm::ivec4>(n, glm::ivec4(0));
  const std::vector<glm::vec4> weights =
      mesh.skinned() ? mesh.boneWeights : std::vector<glm::vec4>(n, glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(4, vbo_);
  upload(vbo_[0], mesh.positions);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  upload(vbo_[1], mesh.normals);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  upload(vbo_[2], ids);
  glEnableVertexAttribArray(2);
  glVertexAttribIPointer(2, 4, GL_INT, 0, nullptr);  // integer attribute: no float conversion
  upload(vbo_[3], weights);
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
  glGenBuffers(1, &ebo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
}

SkinnedMesh::~SkinnedMesh() {
  glDeleteBuffers(4, vbo_);
  glDeleteBuffers(1, &ebo_);
  glDeleteVertexArrays(1, &vao_);
}

void SkinnedMesh::draw() const {
  if (indexCount_ == 0) return;
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

}  // namespace pba::graphics
