#include "physics/core/debug_draw.h"

#include <algorithm>
#include <cmath>

namespace pba {
namespace {
// Any unit vector perpendicular to n (n assumed unit length).
Vec3 anyPerpendicular(const Vec3& n) {
  const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  return glm::normalize(glm::cross(n, helper));
}
constexpr int kArcSegmentsPerTurn = 48;
}  // namespace

void DebugDraw::frame(const Vec3& origin, const Quat& q, Real scale) {
  line(origin, origin + q * Vec3(scale, 0, 0), colors::kRed);
  line(origin, origin + q * Vec3(0, scale, 0), colors::kGreen);
  line(origin, origin + q * Vec3(0, 0, scale), colors::kBlue);
}

void DebugDraw::arc(const Vec3& center, const Vec3& axis, const Vec3& from, Real angle, Real radius,
                    const Color& color) {
  const Real axisLength = glm::length(axis);
  if (!(axisLength > 0.0) || !(radius > 0.0)) return;
  const Vec3 n = axis / axisLength;
  Vec3 u = from - glm::dot(from, n) * n;
  u = glm::length(u) > 1e-12 ? glm::normalize(u) : anyPerpendicular(n);
  const Vec3 v = glm::cross(n, u);
  const int segments = std::max(2, static_cast<int>(std::ceil(std::abs(angle) / (2 * kPi) * kArcSegmentsPerTurn)));
  Vec3 previous = center + radius * u;
  for (int i = 1; i <= segments; ++i) {
    const Real t = angle * static_cast<Real>(i) / segments;
    const Vec3 next = center + radius * (std::cos(t) * u + std::sin(t) * v);
    line(previous, next, color);
    previous = next;
  }
}

void DebugDraw::circle(const Vec3& center, const Vec3& axis, Real radius, const Color& color) {
  const Real axisLength = glm::length(axis);
  if (!(axisLength > 0.0)) return;
  arc(center, axis, anyPerpendicular(axis / axisLength), 2 * kPi, radius, color);
}

void DebugDraw::cone(const Vec3& apex, const Vec3& axis, Real halfAngle, Real length, const Color& color) {
  const Real axisLength = glm::length(axis);
  if (!(axisLength > 0.0)) return;
  const Vec3 n = axis / axisLength;
  const Vec3 rimCenter = apex + n * (length * std::cos(halfAngle));
  const Real rimRadius = length * std::sin(halfAngle);
  circle(rimCenter, n, std::abs(rimRadius), color);
  const Vec3 u = anyPerpendicular(n);
  const Vec3 v = glm::cross(n, u);
  for (const Vec3& d : {u, v, -u, -v}) line(apex, rimCenter + rimRadius * d, color);
}

void DebugDraw::triangles(std::span<const Vec3> positions, std::span<const Vec3> /*normals*/,
                          std::span<const std::uint32_t> indices, const Color& color) {
  for (size_t t = 0; t + 2 < indices.size(); t += 3)
    for (size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = indices[t + k], b = indices[t + (k + 1) % 3];
      if (a < positions.size() && b < positions.size()) line(positions[a], positions[b], color);
    }
}

}  // namespace pba
