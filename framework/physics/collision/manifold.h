#pragma once
// Contact manifolds: up to four contact points sharing one normal, each with a feature id that stays the
// same while the same features touch, so the solver can carry last step's impulses over (warm starting;
// Box2D's b2ManifoldPoint::id, Catto GDC 2006 "Fast and Simple Physics using Sequential Impulses").
#include <array>
#include <cstdint>

#include "physics/core/types.h"

namespace pba::collision {

/// Default speculative margin [m]: pairs closer than this get contact points before they touch, so the
/// solver can stop them without overshoot (Box2D's B2_SPECULATIVE_DISTANCE = 4 × linear slop).
inline constexpr Real kSpeculativeDistance = 0.02;

struct ManifoldPoint {
  Vec3 point{0.0};        ///< [m] world, midway between the two surfaces
  Real separation = 0.0;  ///< [m] signed gap along the normal, negative when penetrating
  std::uint32_t id = 0;   ///< feature id (stable while the same features touch)
};

struct Manifold {
  Vec3 normal{0.0, 1.0, 0.0};  ///< unit, world, from shape A toward shape B
  /// [m] separation of the pair along `normal` as the pair test found it (separating-axis value or
  /// signed distance); ≤ every point's separation for face contacts.
  Real separation = 0.0;
  std::array<ManifoldPoint, 4> points{};
  int count = 0;
  std::uint32_t key = 0;  ///< sub-shape key (mesh triangle index), 0 for convex pairs

  void add(const Vec3& p, Real s, std::uint32_t id) {
    if (count < 4) points[count++] = {p, s, id};
  }
  /// The same contact seen from B: normal reversed, points unchanged.
  Manifold flipped() const {
    Manifold m = *this;
    m.normal = -normal;
    return m;
  }
  Real deepest() const {
    Real s = count ? points[0].separation : 0.0;
    for (int i = 1; i < count; ++i) s = std::min(s, points[i].separation);
    return s;
  }
};

/// A convex polygon of world points with a feature id per vertex (clipping input and output). Only the
/// first n entries are set: the arrays are left uninitialised (zeroing 64 points cost more than clipping
/// a box face).
struct ClipPolygon {
  static constexpr int kCapacity = 64;
  std::array<Vec3, kCapacity> p;
  std::array<std::uint32_t, kCapacity> id;
  int n = 0;
  void push(const Vec3& x, std::uint32_t i) {
    if (n < kCapacity) p[n] = x, id[n] = i, ++n;
  }
};

/// Sutherland–Hodgman (Ericson §8.3.4): keeps the part of `in` with planeNormal·x ≤ planeOffset. A vertex
/// made where edge (i → i+1) crosses the plane gets the 17-bit id 0x10000 | (id_i & 0xFF) << 8 | planeCode.
void clipPolygon(const ClipPolygon& in, const Vec3& planeNormal, Real planeOffset, std::uint32_t planeCode,
                 ClipPolygon& out);

/// Picks at most 4 of `candidates` (all with the same normal) spanning the largest area: the deepest
/// point, the one farthest from it, the one making the largest triangle, and the one adding the most
/// area (Gregorius, "Robust Contact Creation for Physics Simulations", GDC 2015).
void reduceToFour(const ManifoldPoint* candidates, int count, const Vec3& normal, Manifold& out);

}  // namespace pba::collision
