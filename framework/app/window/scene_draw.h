#pragma once
// The bridge of docs/architecture.md §1: implements the physics library's pba::DebugDraw with pba::graphics.
// Converts double-precision world data to float at this one place.
#include "graphics/debug_renderer.h"
#include "physics/core/debug_draw.h"

namespace pba::app {

class SceneDraw final : public DebugDraw {
 public:
  explicit SceneDraw(graphics::DebugRenderer& out) : out_(out) {}

  void point(const Vec3& p, float sizePixels, const Color& color) override;
  void line(const Vec3& a, const Vec3& b, const Color& color) override;
  void arrow(const Vec3& from, const Vec3& to, const Color& color) override;
  void sphere(const Vec3& center, Real radius, const Color& color) override;
  void box(const Vec3& center, const Vec3& halfExtents, const Quat& orientation, const Color& color) override;
  void capsule(const Vec3& a, const Vec3& b, Real radius, const Color& color) override;
  void text(const Vec3& p, std::string_view label, const Color& color) override;
  void triangles(std::span<const Vec3> positions, std::span<const Vec3> normals, std::span<const std::uint32_t> indices,
                 const Color& color) override;

 private:
  graphics::DebugRenderer& out_;
};

}  // namespace pba::app
