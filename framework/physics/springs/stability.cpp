#include "physics/springs/stability.h"

#include <cmath>
#include <vector>

namespace pba::springs {

Real highestAngularFrequency(std::span<const Spring> springs, std::span<const Vec3> x,
                             std::span<const Real> inverseMass, int maxIterations, Real relativeTolerance) {
  const std::size_t n = x.size();
  std::vector<Real> scale(n);  // M^{-1/2}: √(1/m) per particle, 0 where pinned
  for (std::size_t i = 0; i < n; ++i) scale[i] = inverseMass[i] > 0.0 ? std::sqrt(inverseMass[i]) : 0.0;
  // A start with a part along every mode: a fixed, irregular vector (no zero components where free).
  std::vector<Vec3> z(n), u(n), df(n);
  const std::vector<Vec3> noVelocity(n, Vec3(0.0));
  for (std::size_t i = 0; i < n; ++i)
    z[i] = scale[i] * Vec3(std::sin(1.0 + 2.3 * static_cast<Real>(i)), std::cos(0.7 + 1.9 * static_cast<Real>(i)),
                           std::sin(2.1 + 3.7 * static_cast<Real>(i)));
  Real quotient = 0.0;
  for (int it = 0; it < maxIterations; ++it) {
    Real zz = 0.0;
    for (const Vec3& v : z) zz += glm::dot(v, v);
    if (zz == 0.0) return 0.0;
    // S z = M^{-1/2} K M^{-1/2} z; the differential is −K u (damping off: no velocity differential).
    for (std::size_t i = 0; i < n; ++i) u[i] = scale[i] * z[i], df[i] = Vec3(0.0);
    accumulateSpringDifferential(springs, x, u, noVelocity, df);
    Real zSz = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 sz = -scale[i] * df[i];
      zSz += glm::dot(z[i], sz);
      z[i] = sz;
    }
    const Real next = zSz / zz;
    // Normalise to keep the iterate's size near 1 (K's entries can be 10⁷ N/m).
    Real norm = 0.0;
    for (const Vec3& v : z) norm += glm::dot(v, v);
    norm = std::sqrt(norm);
    if (norm == 0.0) return 0.0;
    for (Vec3& v : z) v /= norm;
    const bool settled = it > 0 && std::abs(next - quotient) <= relativeTolerance * std::abs(next);
    quotient = next;
    if (settled) break;
  }
  return std::sqrt(std::max(quotient, 0.0));
}

}  // namespace pba::springs
