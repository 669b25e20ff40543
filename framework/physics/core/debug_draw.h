#pragma once
// pba::DebugDraw: how solvers and scenes show themselves without knowing about OpenGL.
// The physics library calls this interface; pba::app implements it with pba::graphics
// (the model is Box2D's b2DebugDraw). All positions are world space [m].
#include <cstdint>
#include <span>
#include <string_view>

#include "physics/core/types.h"

namespace pba {

/// Linear RGBA colour in [0, 1].
struct Color {
  float r = 1.0f, g = 1.0f, b = 1.0f, a = 1.0f;
};

/// A small palette that reads well on a projector (high contrast on the light background).
namespace colors {
inline constexpr Color kRed{0.86f, 0.20f, 0.18f, 1.0f};
inline constexpr Color kGreen{0.20f, 0.66f, 0.29f, 1.0f};
inline constexpr Color kBlue{0.16f, 0.42f, 0.86f, 1.0f};
inline constexpr Color kOrange{0.95f, 0.55f, 0.12f, 1.0f};
inline constexpr Color kPurple{0.55f, 0.30f, 0.78f, 1.0f};
inline constexpr Color kYellow{0.96f, 0.80f, 0.15f, 1.0f};
inline constexpr Color kTeal{0.10f, 0.62f, 0.64f, 1.0f};
inline constexpr Color kPink{0.92f, 0.40f, 0.62f, 1.0f};
inline constexpr Color kGrey{0.55f, 0.57f, 0.60f, 1.0f};
inline constexpr Color kDark{0.15f, 0.16f, 0.18f, 1.0f};
inline constexpr Color kWhite{1.0f, 1.0f, 1.0f, 1.0f};
}  // namespace colors

class DebugDraw {
 public:
  virtual ~DebugDraw() = default;

  /// A dot of fixed screen size (pixels) at p.
  virtual void point(const Vec3& p, float sizePixels, const Color& color) = 0;
  /// A straight segment from a to b.
  virtual void line(const Vec3& a, const Vec3& b, const Color& color) = 0;
  /// An arrow from `from` to `to` with a head proportional to its length.
  virtual void arrow(const Vec3& from, const Vec3& to, const Color& color) = 0;
  /// Lit solid sphere.
  virtual void sphere(const Vec3& center, Real radius, const Color& color) = 0;
  /// Lit solid box: centre, half extents along its local axes [m], orientation.
  virtual void box(const Vec3& center, const Vec3& halfExtents, const Quat& orientation, const Color& color) = 0;
  /// Lit solid capsule between the centres of its two end spheres.
  virtual void capsule(const Vec3& a, const Vec3& b, Real radius, const Color& color) = 0;
  /// A text label anchored at a world position (drawn in screen space, always facing the viewer).
  virtual void text(const Vec3& p, std::string_view label, const Color& color) = 0;
  /// A lit triangle mesh (skinned characters, cloth): world positions, unit normals (one per position),
  /// indices in threes, counter-clockwise seen from outside. Backends without a triangle path draw the
  /// edges instead (this default).
  virtual void triangles(std::span<const Vec3> positions, std::span<const Vec3> normals,
                         std::span<const std::uint32_t> indices, const Color& color);

  // Helpers composed from the primitives above (not virtual: every backend gets them for free).

  /// A coordinate frame: x red, y green, z blue, each axis `scale` metres long.
  void frame(const Vec3& origin, const Quat& orientation, Real scale);
  /// A circular arc of `radius` about `axis` through `center`, starting at direction `from`
  /// (projected onto the plane normal to axis) and sweeping `angle` radians counter-clockwise.
  void arc(const Vec3& center, const Vec3& axis, const Vec3& from, Real angle, Real radius, const Color& color);
  /// A full circle.
  void circle(const Vec3& center, const Vec3& axis, Real radius, const Color& color);
  /// A cone of half-angle `halfAngle` [rad] around `axis` with apex at `apex`, drawn as rim + 4 rulings.
  void cone(const Vec3& apex, const Vec3& axis, Real halfAngle, Real length, const Color& color);
};

/// A DebugDraw that discards everything: used in headless mode and in tests.
class NullDebugDraw final : public DebugDraw {
 public:
  void point(const Vec3&, float, const Color&) override {}
  void line(const Vec3&, const Vec3&, const Color&) override {}
  void arrow(const Vec3&, const Vec3&, const Color&) override {}
  void sphere(const Vec3&, Real, const Color&) override {}
  void box(const Vec3&, const Vec3&, const Quat&, const Color&) override {}
  void capsule(const Vec3&, const Vec3&, Real, const Color&) override {}
  void text(const Vec3&, std::string_view, const Color&) override {}
  void triangles(std::span<const Vec3>, std::span<const Vec3>, std::span<const std::uint32_t>, const Color&) override {}
};

}  // namespace pba
