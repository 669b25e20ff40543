// DebugRenderer: per-frame shape lists submitted to the Renderer.
#include "graphics/debug_renderer.h"

#include "graphics/renderer.h"

#include <algorithm>
#include <cmath>

namespace pba::graphics {

void DebugRenderer::grow(const glm::vec3& p, float margin) {
  if (!std::isfinite(p.x + p.y + p.z + margin)) return;
  const glm::vec3 m(std::abs(margin));
  if (!hasBounds_) {
    min_ = p - m;
    max_ = p + m;
    hasBounds_ = true;
    return;
  }
  min_ = glm::min(min_, p - m);
  max_ = glm::max(max_, p + m);
}

void DebugRenderer::point(const glm::vec3& p, float sizePx, const glm::vec4& color) {
  points_.push_back({p, sizePx, color});
  grow(p);
}

void DebugRenderer::line(const glm::vec3& a, const glm::vec3& b, const glm::vec4& color) {
  lines_.push_back({a, b, color});
  grow(a);
  grow(b);
}

void DebugRenderer::arrow(const glm::vec3& from, const glm::vec3& to, const glm::vec4& color, float shaftRadius) {
  const glm::vec3 d = to - from;
  const float length = glm::length(d);
  if (!(length > 1e-9f)) return;
  const float r = shaftRadius > 0.0f ? shaftRadius : 0.03f * length;
  const float headLength = std::min(6.0f * r, 0.4f * length);
  const glm::vec3 neck = to - d * (headLength / length);
  solids_.push_back({Shape::Cylinder, from, neck, glm::vec3(0.0f), glm::quat(1, 0, 0, 0), r, color});
  solids_.push_back({Shape::Cone, neck, to, glm::vec3(0.0f), glm::quat(1, 0, 0, 0), 2.2f * r, color});
  grow(from, 2.2f * r);
  grow(to, 2.2f * r);
}

void DebugRenderer::sphere(const glm::vec3& center, float radius, const glm::vec4& color) {
  solids_.push_back({Shape::Sphere, center, center, glm::vec3(0.0f), glm::quat(1, 0, 0, 0), radius, color});
  grow(center, radius);
}

void DebugRenderer::box(const glm::vec3& center, const glm::vec3& halfExtents, const glm::quat& rotation,
                        const glm::vec4& color) {
  solids_.push_back({Shape::Box, center, center, halfExtents, rotation, 0.0f, color});
  const glm::mat3 r = glm::mat3_cast(rotation);
  const glm::vec3 e = glm::abs(r[0]) * std::abs(halfExtents.x) + glm::abs(r[1]) * std::abs(halfExtents.y) +
                      glm::abs(r[2]) * std::abs(halfExtents.z);
  grow(center - e);
  grow(center + e);
}

void DebugRenderer::capsule(const glm::vec3& a, const glm::vec3& b, float radius, const glm::vec4& color) {
  solids_.push_back({Shape::Capsule, a, b, glm::vec3(0.0f), glm::quat(1, 0, 0, 0), radius, color});
  grow(a, radius);
  grow(b, radius);
}

void DebugRenderer::cylinder(const glm::vec3& a, const glm::vec3& b, float radius, const glm::vec4& color) {
  solids_.push_back({Shape::Cylinder, a, b, glm::vec3(0.0f), glm::quat(1, 0, 0, 0), radius, color});
  grow(a, radius);
  grow(b, radius);
}

void DebugRenderer::frame(const glm::vec3& origin, const glm::quat& rotation, float length) {
  const glm::mat3 r = glm::mat3_cast(rotation);
  arrow(origin, origin + r[0] * length, colors::kRed);
  arrow(origin, origin + r[1] * length, colors::kGreen);
  arrow(origin, origin + r[2] * length, colors::kBlue);
}

void DebugRenderer::label(const glm::vec3& position, const std::string& text, const glm::vec4& color) {
  labels_.push_back({position, text, color});
  grow(position);
}

void DebugRenderer::flush(Renderer& renderer) const {
  for (const Solid& s : solids_) {
    switch (s.shape) {
      case Shape::Sphere:
        renderer.drawSphere(s.a, s.radius, s.color);
        break;
      case Shape::Box:
        renderer.drawBox(s.a, s.half, s.rotation, s.color);
        break;
      case Shape::Capsule:
        renderer.drawCapsule(s.a, s.b, s.radius, s.color);
        break;
      case Shape::Cylinder:
        renderer.drawCylinder(s.a, s.b, s.radius, s.color);
        break;
      case Shape::Cone:
        renderer.drawCone(s.a, s.b, s.radius, s.color);
        break;
    }
  }
  for (const auto& [mesh, color] : meshes_) renderer.drawTriangles(mesh, color);
  for (const Segment& l : lines_) renderer.drawLine(l.a, l.b, l.color);
  for (const Dot& d : points_) renderer.drawPoint(d.p, d.size, d.color);
}

void DebugRenderer::clear() {
  solids_.clear();
  lines_.clear();
  points_.clear();
  labels_.clear();
  meshes_.clear();
  hasBounds_ = false;
}

std::vector<ScreenLabel> DebugRenderer::projectLabels(const OrbitCamera& camera, float viewportW,
                                                      float viewportH) const {
  std::vector<ScreenLabel> out;
  out.reserve(labels_.size());
  for (const Label& l : labels_) {
    const ScreenPoint s = camera.project(l.position, viewportW, viewportH);
    out.push_back({s.pixel, l.text, l.color, s.visible});
  }
  return out;
}

bool DebugRenderer::bounds(glm::vec3* min, glm::vec3* max) const {
  if (!hasBounds_) return false;
  if (min) *min = min_;
  if (max) *max = max_;
  return true;
}

bool DebugRenderer::empty() const {
  return solids_.empty() && lines_.empty() && points_.empty() && labels_.empty() && meshes_.empty();
}

void DebugRenderer::triangles(MeshData mesh, const glm::vec4& color) {
  if (mesh.indices.empty()) return;
  for (const glm::vec3& p : mesh.positions) grow(p);
  meshes_.emplace_back(std::move(mesh), color);
}

}  // namespace pba::graphics
