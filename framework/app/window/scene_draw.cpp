#include "app/window/scene_draw.h"

#include <string>

namespace pba::app {
namespace {
glm::vec3 f(const Vec3& v) { return glm::vec3(v); }
glm::vec4 f(const Color& c) { return {c.r, c.g, c.b, c.a}; }
}  // namespace

void SceneDraw::point(const Vec3& p, float sizePixels, const Color& color) { out_.point(f(p), sizePixels, f(color)); }
void SceneDraw::line(const Vec3& a, const Vec3& b, const Color& color) { out_.line(f(a), f(b), f(color)); }
void SceneDraw::arrow(const Vec3& from, const Vec3& to, const Color& color) { out_.arrow(f(from), f(to), f(color)); }
void SceneDraw::sphere(const Vec3& c, Real r, const Color& color) {
  out_.sphere(f(c), static_cast<float>(r), f(color));
}
void SceneDraw::box(const Vec3& c, const Vec3& h, const Quat& q, const Color& color) {
  out_.box(f(c), f(h), glm::quat(q), f(color));
}
void SceneDraw::capsule(const Vec3& a, const Vec3& b, Real r, const Color& color) {
  out_.capsule(f(a), f(b), static_cast<float>(r), f(color));
}
void SceneDraw::triangles(std::span<const Vec3> positions, std::span<const Vec3> normals,
                          std::span<const std::uint32_t> indices, const Color& color) {
  graphics::MeshData mesh;
  mesh.positions.reserve(positions.size());
  for (const Vec3& p : positions) mesh.positions.push_back(f(p));
  mesh.normals.reserve(positions.size());
  for (size_t i = 0; i < positions.size(); ++i)
    mesh.normals.push_back(i < normals.size() ? f(normals[i]) : glm::vec3(0, 1, 0));
  for (size_t t = 0; t + 2 < indices.size(); t += 3)  // drop triangles that index past the vertices
    if (indices[t] < positions.size() && indices[t + 1] < positions.size() && indices[t + 2] < positions.size())
      mesh.indices.insert(mesh.indices.end(), {indices[t], indices[t + 1], indices[t + 2]});
  out_.triangles(std::move(mesh), f(color));
}
void SceneDraw::text(const Vec3& p, std::string_view label, const Color& color) {
  out_.label(f(p), std::string(label), f(color));
}

}  // namespace pba::app
