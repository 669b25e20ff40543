// Drawing of the cloth lab: the cloth as lit two-sided triangles with smooth per-vertex normals
// (DebugDraw::triangles streams meshes that change every frame), coloured by a pattern laid out on the
// rest shape (so it moves with the fabric), by strain bands, or plain; wireframe, links, colliders, pins.
#include <algorithm>
#include <array>
#include <cmath>

#include "cloth_scene.h"
#include "physics/collision/shape_draw.h"

namespace pba::lab {

using namespace pba::cloth;
namespace {

constexpr Color kWire{0.15f, 0.16f, 0.18f, 1.0f};
constexpr Color kCollider{0.62f, 0.64f, 0.68f, 1.0f};
// Strain bands: < 0.5 %, < 2 %, < 5 %, < 10 %, ≥ 10 %.
constexpr std::array<Real, 4> kStrainBands{0.005, 0.02, 0.05, 0.10};
constexpr std::array<Color, 5> kStrainColors{colors::kBlue, colors::kGreen, colors::kYellow, colors::kOrange,
                                             colors::kRed};

Color scaled(const Color& c, float k) {
  return {std::min(1.0f, c.r * k), std::min(1.0f, c.g * k), std::min(1.0f, c.b * k), c.a};
}

/// Two axes spanning the rest shape (the two largest extents of its bounding box), its low corner and a
/// pattern cell size: a whole number of edge lengths (the shortest rest edge, a grid's spacing), so that
/// on a grid the squares follow the grid lines.
struct RestFrame {
  int u = 0, v = 2;
  Vec3 origin{0.0};
  Real cellU = 0.1, cellV = 0.1;    // [m]
  Real stepsU = 1.0, stepsV = 1.0;  // edge lengths per cell (whole numbers on a grid)
};
RestFrame restFrame(const Cloth& c) {
  Vec3 lo(std::numeric_limits<Real>::max()), hi(std::numeric_limits<Real>::lowest());
  for (const Vec3& x : c.restPosition) {
    lo = glm::min(lo, x);
    hi = glm::max(hi, x);
  }
  const Vec3 extent = hi - lo;
  std::array<int, 3> axes{0, 1, 2};
  std::sort(axes.begin(), axes.end(), [&](int a, int b) { return extent[a] > extent[b]; });
  const Real target = std::max(1e-3, extent[axes[1]] / 6.0);
  // Per axis, the shortest rest edge component along it (a grid's spacing on that axis).
  auto cellAlong = [&](int a) {
    Real spacing = std::numeric_limits<Real>::max();
    for (const Link& l : c.constraints) {
      const Real d = std::abs(c.restPosition[l.i][a] - c.restPosition[l.j][a]);
      if (d > 1e-6 * target) spacing = std::min(spacing, d);
    }
    return spacing < target ? std::pair{spacing * std::round(target / spacing), std::round(target / spacing)}
                            : std::pair{target, 1.0};
  };
  const auto [cellU, stepsU] = cellAlong(axes[0]);
  const auto [cellV, stepsV] = cellAlong(axes[1]);
  return {axes[0], axes[1], lo - Vec3(1e-9), cellU, cellV, stepsU, stepsV};
}

/// Pattern group of triangle t: checker (2 groups) or woven (4: ground, warp stripe, weft stripe, both).
int patternGroup(const Cloth& c, const Triangle& t, const RestFrame& f, Pattern pattern) {
  const Vec3 centroid = (c.restPosition[t[0]] + c.restPosition[t[1]] + c.restPosition[t[2]]) / 3.0;
  const Real u = (centroid[f.u] - f.origin[f.u]) / f.cellU, v = (centroid[f.v] - f.origin[f.v]) / f.cellV;
  if (pattern == Pattern::Checker) return static_cast<int>(std::floor(u) + std::floor(v)) & 1;
  // Woven: in each cell a stripe a third as wide, made of whole edge lengths (so it follows a grid).
  const auto stripe = [](Real s, Real steps) {
    const Real width = std::max(1.0, std::round(steps / 3.0));
    return std::floor((s - std::floor(s)) * steps + 1e-6) < width ? 1 : 0;
  };
  return stripe(u, f.stepsU) + 2 * stripe(v, f.stepsV);
}

Real triangleStrain(const Cloth& c, const Triangle& t) {
  Real worst = 0.0;
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t a = t[k], b = t[(k + 1) % 3];
    const Real rest = glm::length(c.restPosition[a] - c.restPosition[b]);
    worst = std::max(worst, std::abs(glm::length(c.position[a] - c.position[b]) / rest - 1.0));
  }
  return worst;
}

}  // namespace

void vertexNormals(const Cloth& c, std::vector<Vec3>& out) {
  out.assign(c.size(), Vec3(0.0));
  for (const Triangle& t : c.triangles) {
    const Vec3 n = glm::cross(c.position[t[1]] - c.position[t[0]], c.position[t[2]] - c.position[t[0]]);  // 2 × area
    for (std::uint32_t v : t) out[v] += n;
  }
  for (Vec3& n : out) {
    const Real l = glm::length(n);
    n = l > 0.0 ? n / l : Vec3(0.0, 1.0, 0.0);
  }
}

void ClothScene::drawCloth(DebugDraw& d, const Cloth& c, const Color& base) const {
  std::vector<Vec3> normals;
  vertexNormals(c, normals);
  std::array<std::vector<std::uint32_t>, 5> groups;
  std::array<Color, 5> tint{base, scaled(base, 0.55f), scaled(base, 1.35f), scaled(base, 0.8f), base};
  const RestFrame frame = restFrame(c);
  for (const Triangle& t : c.triangles) {
    int g = 0;
    if (strainColors_) {
      const Real s = triangleStrain(c, t);
      while (g < 4 && s >= kStrainBands[static_cast<std::size_t>(g)]) ++g;
    } else if (pattern_ != Pattern::Plain) {
      g = patternGroup(c, t, frame, pattern_);
    }
    groups[static_cast<std::size_t>(g)].insert(groups[static_cast<std::size_t>(g)].end(), t.begin(), t.end());
  }
  // Slate squares: dark against the white floor, so that a square on it never reads as a hole in the cloth.
  if (pattern_ == Pattern::Checker) tint[1] = Color{0.22f, 0.26f, 0.34f, base.a};
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (!groups[g].empty()) d.triangles(c.position, normals, groups[g], strainColors_ ? kStrainColors[g] : tint[g]);
  }
  if (wireframe_) {
    for (const Edge& e : c.edges) d.line(c.position[e.a], c.position[e.b], kWire);
  }
  if (showLinks_) {
    const std::vector<Link>& links = usesSprings(settings_.kind) ? c.springs : c.constraints;
    constexpr std::array<Color, kLinkKinds> kKind{colors::kBlue, colors::kGreen, colors::kOrange};
    for (const Link& l : links) d.line(c.position[l.i], c.position[l.j], kKind[static_cast<std::size_t>(l.kind)]);
  }
  const Real pinSize = std::max(0.01, 1.5 * thickness_);
  for (const Pin& p : c.pins) {
    d.sphere(c.position[p.particle], pinSize,
             static_cast<int>(p.particle) == dragged_ ? colors::kYellow : colors::kRed);
  }
}

void ClothScene::drawColliders(DebugDraw& d) const {
  for (const Collider& c : colliders_) collision::drawShape(d, c.shape, c.pose, kCollider);
}

void ClothScene::draw(DebugDraw& d) const {
  drawColliders(d);
  drawCloth(d, cloth_, clothColor_);
  drawExtras(d);
}

}  // namespace pba::lab
