#include "physics/particles/forces.h"

#include <cmath>

#include "physics/core/validate.h"

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

namespace {
// ∂f_i/∂v_i of the drag, −c₁ I − c₂ (|u| I + u uᵀ/|u|) with u = v − w (header): the one definition both
// the matrix-free differential and the preconditioner's diagonal blocks use.
Mat3 dragVelocityJacobian(const ForceDesc& desc, Real t, const Vec3& x, const Vec3& v, bool wind) {
  Mat3 j = -desc.drag.linear * Mat3(1.0);
  if (desc.drag.quadratic > 0.0) {
    const Vec3 u = wind ? v - windVelocity(desc.wind, x, t) : v;
    const Real s = glm::length(u);
    if (s > 0.0) j -= desc.drag.quadratic * (s * Mat3(1.0) + glm::outerProduct(u, u) / s);
  }
  return j;
}
bool hasDrag(const ForceDesc& desc) { return desc.drag.linear > 0.0 || desc.drag.quadratic > 0.0; }
bool hasWind(const ForceDesc& desc) { return glm::dot(desc.wind.base, desc.wind.base) > 0.0; }
}  // namespace

void accumulateDragDifferential(const ForceDesc& desc, Real t, std::span<const Vec3> x, std::span<const Vec3> v,
                                std::span<const Real> inverseMass, std::span<const Vec3> dv, std::span<Vec3> df) {
  if (!hasDrag(desc)) return;
  const bool wind = hasWind(desc);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (inverseMass[i] > 0.0) df[i] += dragVelocityJacobian(desc, t, x[i], v[i], wind) * dv[i];
  }
}

void accumulateDragJacobianDiagonal(const ForceDesc& desc, Real t, std::span<const Vec3> x, std::span<const Vec3> v,
                                    std::span<const Real> inverseMass, std::span<Mat3> dfdv) {
  if (!hasDrag(desc)) return;
  const bool wind = hasWind(desc);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (inverseMass[i] > 0.0) dfdv[i] += dragVelocityJacobian(desc, t, x[i], v[i], wind);
  }
}

Status validate(const ForceDesc& d) {
  for (Status s : {checkFinite("forces.gravity", d.gravity), checkRange("forces.drag.linear", d.drag.linear, 0.0, 1e9),
                   checkRange("forces.drag.quadratic", d.drag.quadratic, 0.0, 1e9),
                   checkFinite("forces.wind.base", d.wind.base), checkRange("forces.wind.gust", d.wind.gust, -1e6, 1e6),
                   checkRange("forces.wind.frequency", d.wind.frequency, 0.0, 1e6),
                   checkPositive("forces.wind.wavelength", d.wind.wavelength)}) {
    if (!s) return s;
  }
  for (const AttractorDesc& a : d.attractors) {
    for (Status s : {checkFinite("forces.attractors.center", a.center),
                     checkRange("forces.attractors.strength", a.strength, -1e12, 1e12),
                     checkPositive("forces.attractors.softening", a.softening)}) {
      if (!s) return s;
    }
  }
  for (const VortexDesc& vo : d.vortices) {
    if (Status s = checkFinite("forces.vortices.center", vo.center); !s) return s;
    if (!(isFinite(vo.axis) && std::abs(glm::length(vo.axis) - 1.0) <= 1e-9)) {
      return Error{"forces.vortices.axis: must be a unit vector"};
    }
    if (Status s = checkRange("forces.vortices.strength", vo.strength, -1e12, 1e12); !s) return s;
    if (Status s = checkPositive("forces.vortices.coreRadius", vo.coreRadius); !s) return s;
  }
  return Status::success();
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
