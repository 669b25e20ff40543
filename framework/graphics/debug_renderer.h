// DebugRenderer: an immediate-mode collector of debug shapes for one frame (points, lines, arrows,
// spheres, boxes, capsules, coordinate frames, 3D text labels). flush(Renderer&) submits them; the
// app draws the labels' text itself (ImGui) at projectLabels() positions. bounds() frames the camera.
#pragma once

#include "graphics/camera.h"
#include "graphics/colors.h"
#include "graphics/mesh_data.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <string>
#include <vector>

namespace pba::graphics {

class Renderer;

struct Label {
  glm::vec3 position{0.0f};  ///< world, m
  std::string text;
  glm::vec4 color{colors::kDark};
};

struct ScreenLabel {
  glm::vec2 pixel{0.0f};  ///< top-left origin
  std::string text;
  glm::vec4 color{1.0f};
  bool visible = false;
};

class DebugRenderer {
 public:
  void point(const glm::vec3& p, float sizePx, const glm::vec4& color);
  void line(const glm::vec3& a, const glm::vec3& b, const glm::vec4& color);
  /// Lit arrow from `from` to `to`: cylinder shaft + cone head; shaftRadius <= 0 picks 3% of the length.
  void arrow(const glm::vec3& from, const glm::vec3& to, const glm::vec4& color, float shaftRadius = 0.0f);
  void sphere(const glm::vec3& center, float radius, const glm::vec4& color);
  void box(const glm::vec3& center, const glm::vec3& halfExtents, const glm::quat& rotation, const glm::vec4& color);
  void capsule(const glm::vec3& a, const glm::vec3& b, float radius, const glm::vec4& color);
  void cylinder(const glm::vec3& a, const glm::vec3& b, float radius, const glm::vec4& color);
  /// Axes x (red), y (green), z (blue) of a frame, `length` m long, as arrows.
  void frame(const glm::vec3& origin, const glm::quat& rotation, float length);
  void label(const glm::vec3& position, const std::string& text, const glm::vec4& color = colors::kDark);
  /// A lit triangle mesh in world space (streamed to the GPU each frame).
  void triangles(MeshData mesh, const glm::vec4& color);

  /// Submits everything to the renderer (between its beginFrame and endFrame). Keeps the data.
  void flush(Renderer& renderer) const;
  void clear();  ///< call once per frame after flush

  const std::vector<Label>& labels() const { return labels_; }
  std::vector<ScreenLabel> projectLabels(const OrbitCamera& camera, float viewportW, float viewportH) const;
  /// Axis-aligned box of everything submitted; false when nothing was submitted.
  bool bounds(glm::vec3* min, glm::vec3* max) const;
  bool empty() const;

 private:
  enum class Shape { Sphere, Box, Capsule, Cylinder, Cone };
  struct Solid {
    Shape shape;
    glm::vec3 a, b;  ///< sphere/box: centre in a; segments: a -> b
    glm::vec3 half;  ///< box half extents
    glm::quat rotation;
    float radius;
    glm::vec4 color;
  };
  struct Segment {
    glm::vec3 a, b;
    glm::vec4 color;
  };
  struct Dot {
    glm::vec3 p;
    float size;
    glm::vec4 color;
  };
  void grow(const glm::vec3& p, float margin = 0.0f);

  std::vector<Solid> solids_;
  std::vector<Segment> lines_;
  std::vector<Dot> points_;
  std::vector<Label> labels_;
  std::vector<std::pair<MeshData, glm::vec4>> meshes_;
  glm::vec3 min_{0.0f}, max_{0.0f};
  bool hasBounds_ = false;
};

}  // namespace pba::graphics
