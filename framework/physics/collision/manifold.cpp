#include "physics/collision/manifold.h"

#include <algorithm>
#include <cmath>

namespace pba::collision {

void clipPolygon(const ClipPolygon& in, const Vec3& n, Real offset, std::uint32_t planeCode, ClipPolygon& out) {
  out.n = 0;
  if (in.n == 0) return;
  for (int i = 0; i < in.n; ++i) {
    const int j = (i + 1) % in.n;
    const Vec3& a = in.p[i];
    const Vec3& b = in.p[j];
    const Real da = glm::dot(n, a) - offset, db = glm::dot(n, b) - offset;
    if (da <= 0.0) out.push(a, in.id[i]);
    if ((da <= 0.0) != (db <= 0.0)) {
      const Real t = da / (da - db);
      // The new vertex is where edge (i → j) crosses this plane: id from the edge's start and the plane.
      out.push(a + t * (b - a), 0x10000u | ((in.id[i] & 0xFFu) << 8) | (planeCode & 0xFFu));
    }
  }
}

void reduceToFour(const ManifoldPoint* c, int count, const Vec3& n, Manifold& out) {
  out.count = 0;
  if (count <= 4) {
    for (int i = 0; i < count; ++i) out.add(c[i].point, c[i].separation, c[i].id);
    return;
  }
  int i1 = 0;
  for (int i = 1; i < count; ++i)
    if (c[i].separation < c[i1].separation) i1 = i;
  int i2 = -1;
  Real best = -1.0;
  for (int i = 0; i < count; ++i) {
    const Vec3 d = c[i].point - c[i1].point;
    const Real dd = glm::dot(d, d);
    if (i != i1 && dd > best) best = dd, i2 = i;
  }
  // Signed area (× 2) of triangle (a, b, p) about the normal.
  auto area = [&](int a, int b, int p) {
    return glm::dot(glm::cross(c[b].point - c[a].point, c[p].point - c[a].point), n);
  };
  int i3 = -1;
  best = -1.0;
  for (int i = 0; i < count; ++i) {
    const Real a = std::abs(area(i1, i2, i));
    if (i != i1 && i != i2 && a > best) best = a, i3 = i;
  }
  // The fourth point: the largest area added outside one of the triangle's edges.
  const Real orientation = area(i1, i2, i3) >= 0.0 ? 1.0 : -1.0;
  int i4 = -1;
  best = 0.0;
  for (int i = 0; i < count; ++i) {
    if (i == i1 || i == i2 || i == i3) continue;
    const Real gain =
        std::max({-orientation * area(i1, i2, i), -orientation * area(i2, i3, i), -orientation * area(i3, i1, i)});
    if (gain > best) best = gain, i4 = i;
  }
  for (int i : {i1, i2, i3, i4})
    if (i >= 0) out.add(c[i].point, c[i].separation, c[i].id);
}

}  // namespace pba::collision
