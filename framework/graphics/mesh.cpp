// Mesh: GPU upload and instanced drawing.
#include "graphics/mesh.h"

#include <cstddef>

namespace pba::graphics {

Mesh::Mesh(const MeshData& data) : indexCount_(static_cast<GLsizei>(data.indices.size())) {
  if (!data.positions.empty()) {
    boundsMin_ = boundsMax_ = data.positions.front();
    for (const glm::vec3& p : data.positions) {
      boundsMin_ = glm::min(boundsMin_, p);
      boundsMax_ = glm::max(boundsMax_, p);
    }
  }
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &positionVbo_);
  glBindBuffer(GL_ARRAY_BUFFER, positionVbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.positions.size() * sizeof(glm::vec3)),
               data.positions.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glGenBuffers(1, &normalVbo_);
  glBindBuffer(GL_ARRAY_BUFFER, normalVbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.normals.size() * sizeof(glm::vec3)), data.normals.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glGenBuffers(1, &ebo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.indices.size() * sizeof(std::uint32_t)),
               data.indices.data(), GL_STATIC_DRAW);

  glGenBuffers(1, &instanceVbo_);
  glBindBuffer(GL_ARRAY_BUFFER, instanceVbo_);
  for (GLuint column = 0; column < 4; ++column) {
    glEnableVertexAttribArray(2 + column);
    glVertexAttribPointer(2 + column, 4, GL_FLOAT, GL_FALSE, sizeof(Instance),
                          reinterpret_cast<const void*>(offsetof(Instance, model) + column * sizeof(glm::vec4)));
    glVertexAttribDivisor(2 + column, 1);
  }
  glEnableVertexAttribArray(6);
  glVertexAttribPointer(6, 4, GL_FLOAT, GL_FALSE, sizeof(Instance),
                        reinterpret_cast<const void*>(offsetof(Instance, color)));
  glVertexAttribDivisor(6, 1);
  glBindVertexArray(0);
}

Mesh::~Mesh() {
  const GLuint buffers[] = {positionVbo_, normalVbo_, ebo_, instanceVbo_};
  glDeleteBuffers(4, buffers);
  glDeleteVertexArrays(1, &vao_);
}

void Mesh::update(const MeshData& data) {
  indexCount_ = static_cast<GLsizei>(data.indices.size());
  if (!data.positions.empty()) {
    boundsMin_ = boundsMax_ = data.positions.front();
    for (const glm::vec3& p : data.positions) {
      boundsMin_ = glm::min(boundsMin_, p);
      boundsMax_ = glm::max(boundsMax_, p);
    }
  }
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, positionVbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.positions.size() * sizeof(glm::vec3)),
               data.positions.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, normalVbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.normals.size() * sizeof(glm::vec3)), data.normals.data(),
               GL_STREAM_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.indices.size() * sizeof(std::uint32_t)),
               data.indices.data(), GL_STREAM_DRAW);
  glBindVertexArray(0);
}

void Mesh::drawInstanced(const std::vector<Instance>& instances) const {
  if (instances.empty() || indexCount_ == 0) return;
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, instanceVbo_);
  const auto bytes = static_cast<GLsizeiptr>(instances.size() * sizeof(Instance));
  if (bytes > instanceCapacity_) {
    instanceCapacity_ = bytes * 2;
    glBufferData(GL_ARRAY_BUFFER, instanceCapacity_, nullptr, GL_STREAM_DRAW);
  }
  glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, instances.data());
  glDrawElementsInstanced(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr, static_cast<GLsizei>(instances.size()));
  glBindVertexArray(0);
}

}  // namespace pba::graphics
