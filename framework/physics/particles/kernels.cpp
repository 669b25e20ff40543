#include "physics/particles/kernels.h"

namespace pba::particles {

void stepGravityDragPlane(std::span<Vec3> x, std::span<Vec3> v, const FusedStepDesc& d, Real h) {
  const Vec3 n = d.ground.normal;
  const Real offset = glm::dot(n, d.ground.point) + d.radius;  // contact when n·x < offset
  const Vec3 dv = h * d.gravity;
  const Real keep = 1.0 - h * d.dragRate;
  const std::size_t count = x.size();
  Vec3* __restrict xs = x.data();
  Vec3* __restrict vs = v.data();
  for (std::size_t i = 0; i < count; ++i) {
    Vec3 vi = keep * vs[i] + dv;
    Vec3 xi = xs[i] + h * vi;
    const Real phi = glm::dot(n, xi) - offset;
    if (phi < kContactSlop) [[unlikely]] {
      if (phi < 0.0) xi -= phi * n;
      if (glm::dot(vi, n) < 0.0) {
        vi = contactVelocity(vi, n, d.material);
        const Real vn = glm::dot(vi, n);
        if (vn < 0.0) vi -= vn * n;
      }
    }
    xs[i] = xi;
    vs[i] = vi;
  }
}

}  // namespace pba::particles
