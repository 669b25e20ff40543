// LineRenderer: batches of thick anti-aliased lines (line.vert/frag: each segment is one instance of a
// screen-space quad, width in pixels) and screen-sized dots (point.*), one instanced draw call each. No
// geometry shader, so the same code runs on OpenGL 3.3 and WebGL2.
#pragma once

#include "graphics/shader.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace pba::graphics {

class LineRenderer {
 public:
  static std::unique_ptr<LineRenderer> create(const std::string& shaderDir, std::string* error);
  ~LineRenderer();
  LineRenderer(const LineRenderer&) = delete;
  LineRenderer& operator=(const LineRenderer&) = delete;

  void addLine(const glm::vec3& a, const glm::vec3& b, const glm::vec4& colorA, const glm::vec4& colorB);
  void addPoint(const glm::vec3& p, float sizePx, const glm::vec4& color);
  void clear();
  std::size_t lineCount() const { return lines_.size() / 2; }
  std::size_t pointCount() const { return points_.size(); }

  /// Draws everything added since clear(); blending must be enabled by the caller.
  void draw(const glm::mat4& viewProj, const glm::vec2& viewport, float lineWidthPx, float pointScale) const;

 private:
  struct LineVertex {
    glm::vec3 position;
    glm::vec4 color;
  };
  struct PointVertex {
    glm::vec3 position;
    glm::vec4 color;
    float size;
  };
  LineRenderer() = default;
  std::unique_ptr<ShaderProgram> lineShader_, pointShader_;
  GLuint lineVao_ = 0, lineVbo_ = 0, pointVao_ = 0, pointVbo_ = 0;
  std::vector<LineVertex> lines_;
  std::vector<PointVertex> points_;
};

}  // namespace pba::graphics
