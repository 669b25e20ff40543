// LineRenderer: vertex streaming for thick lines and dots.
#include "graphics/line_renderer.h"

#include <cstddef>

namespace pba::graphics {
namespace {

// A per-instance float attribute: each segment or dot is one instance of a 4-vertex strip.
void instanceAttribute(GLuint index, GLint size, GLsizei stride, std::size_t offset) {
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
  glVertexAttribDivisor(index, 1);
}

template <typename T>
void stream(GLuint vbo, const std::vector<T>& data) {
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data(), GL_STREAM_DRAW);
}

}  // namespace

std::unique_ptr<LineRenderer> LineRenderer::create(const std::string& shaderDir, std::string* error) {
  std::unique_ptr<LineRenderer> r(new LineRenderer());
  r->lineShader_ = ShaderProgram::load(shaderDir, "line", error);
  if (!r->lineShader_) return nullptr;
  r->pointShader_ = ShaderProgram::load(shaderDir, "point", error);
  if (!r->pointShader_) return nullptr;
  glGenVertexArrays(1, &r->lineVao_);
  glGenBuffers(1, &r->lineVbo_);
  glBindVertexArray(r->lineVao_);
  glBindBuffer(GL_ARRAY_BUFFER, r->lineVbo_);
  // A segment is two consecutive LineVertex records: start (locations 0, 1) and end (2, 3).
  constexpr auto segment = static_cast<GLsizei>(2 * sizeof(LineVertex));
  instanceAttribute(0, 3, segment, offsetof(LineVertex, position));
  instanceAttribute(1, 4, segment, offsetof(LineVertex, color));
  instanceAttribute(2, 3, segment, sizeof(LineVertex) + offsetof(LineVertex, position));
  instanceAttribute(3, 4, segment, sizeof(LineVertex) + offsetof(LineVertex, color));
  glGenVertexArrays(1, &r->pointVao_);
  glGenBuffers(1, &r->pointVbo_);
  glBindVertexArray(r->pointVao_);
  glBindBuffer(GL_ARRAY_BUFFER, r->pointVbo_);
  instanceAttribute(0, 3, sizeof(PointVertex), offsetof(PointVertex, position));
  instanceAttribute(1, 4, sizeof(PointVertex), offsetof(PointVertex, color));
  instanceAttribute(2, 1, sizeof(PointVertex), offsetof(PointVertex, size));
  glBindVertexArray(0);
  return r;
}

LineRenderer::~LineRenderer() {
  const GLuint buffers[] = {lineVbo_, pointVbo_};
  glDeleteBuffers(2, buffers);
  const GLuint arrays[] = {lineVao_, pointVao_};
  glDeleteVertexArrays(2, arrays);
}

void LineRenderer::addLine(const glm::vec3& a, const glm::vec3& b, const glm::vec4& colorA, const glm::vec4& colorB) {
  lines_.push_back({a, colorA});
  lines_.push_back({b, colorB});
}

void LineRenderer::addPoint(const glm::vec3& p, float sizePx, const glm::vec4& color) {
  points_.push_back({p, color, sizePx});
}

void LineRenderer::clear() {
  lines_.clear();
  points_.clear();
}

void LineRenderer::draw(const glm::mat4& viewProj, const glm::vec2& viewport, float lineWidthPx,
                        float pointScale) const {
  if (!lines_.empty()) {
    lineShader_->use();
    lineShader_->set("uViewProj", viewProj);
    lineShader_->set("uViewport", viewport);
    lineShader_->set("uWidth", lineWidthPx);
    glBindVertexArray(lineVao_);
    stream(lineVbo_, lines_);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(lines_.size() / 2));
  }
  if (!points_.empty()) {
    pointShader_->use();
    pointShader_->set("uViewProj", viewProj);
    pointShader_->set("uViewport", viewport);
    pointShader_->set("uSizeScale", pointScale);
    glBindVertexArray(pointVao_);
    stream(pointVbo_, points_);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(points_.size()));
  }
  glBindVertexArray(0);
}

}  // namespace pba::graphics
