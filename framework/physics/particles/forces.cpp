#include "physics/particles/forces.h"

#include <cmath>

namespace pba::particles {

Vec3 windVelocity(const WindDesc& w, const Vec3& x, Real t) {
  const Real speed = glm::length(w.base);
  if (speed <= 0.0 || w.gust == 0.0) return w.base;
  const Vec3 d = w.base / speed;
  return w.base + w.gust * std::sin(2.0 * kPi * (w.frequency * t - glm::dot(x, d) / w.wavelength)) * d;
}

void accumulateFieldForces(const ForceDesc& desc, Real t, std::span<const Vec3> x, std::span<const Vec3> v,
                           std::span<const Real> inverseMass, std::span<Vec3> f) {
  const bool wind = glm::dot(desc.wind.base, desc.wind.base) > 0.0;
  const Real c1 = desc.drag.linear, c2 = desc.drag.quadratic;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Real w = inverseMass[i];
    if (w <= 0.0) continue;
    const Real m = 1.0 / w;
    Vec3 a = desc.gravity;
    for (const AttractorDesc& at : desc.attractors) {
      const Vec3 r = at.center - x[i];
      const Real d2 = glm::dot(r, r) + at.softening * at.softening;
      a += at.strength * r / (d2 * std::sqrt(d2));
    }
    for (const VortexDesc& vo : desc.vortices) {
      const Vec3 r = x[i] - vo.center;
      const Vec3 rPerp = r - glm::dot(r, vo.axis) * vo.axis;
      a += vo.strength * glm::cross(vo.axis, rPerp) / (glm::dot(rPerp, rPerp) + vo.coreRadius * vo.coreRadius);
    }
    Vec3 force = m * a;
    if (c1 > 0.0 || c2 > 0.0) {
      const Vec3 u = wind ? v[i] - windVelocity(desc.wind, x[i], t) : v[i];
      force -= (c1 + c2 * glm::length(u)) * u;
    }
    f[i] += force;
  }
}

void accumulateDragDifferential(const ForceDesc& desc, Real t, std::span<const Vec3> x, std::span<const Vec3> v,
                                std::span<const Real> inverseMass, std::span<const Vec3> dv, std::span<Vec3> df) {
  const Real c1 = desc.drag.linear, c2 = desc.drag.quadratic;
  if (c1 <= 0.0 && c2 <= 0.0) return;
  const bool wind = glm::dot(desc.wind.base, desc.wind.base) > 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (inverseMass[i] <= 0.0) continue;
    Vec3 d = -c1 * dv[i];
    if (c2 > 0.0) {
      const Vec3 u = wind ? v[i] - windVelocity(desc.wind, x[i], t) : v[i];
      const Real s = glm::length(u);
      if (s > 0.0) d -= c2 * (s * dv[i] + u * (glm::dot(u, dv[i]) / s));
    }
    df[i] += d;
  }
}

Real fieldPotentialEnergy(const ForceDesc& desc, std::span<const Vec3> x, std::span<const Real> inverseMass) {
  Real e = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (inverseMass[i] <= 0.0) continue;
    const Real m = 1.0 / inverseMass[i];
    e -= m * glm::dot(desc.gravity, x[i]);
    for (const AttractorDesc& at : desc.attractors) {
      const Vec3 r = at.center - x[i];
      e -= m * at.strength / std::sqrt(glm::dot(r, r) + at.softening * at.softening);
    }
  }
  return e;
}

}  // namespace pba::particles
