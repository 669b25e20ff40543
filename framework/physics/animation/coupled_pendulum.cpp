#include "physics/animation/coupled_pendulum.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pba::animation {

namespace {

constexpr int kMaxSweeps = 500;             // Gauss-Seidel sweeps per projection (a few dozen in practice)
constexpr Real kRelativeTolerance = 1e-13;  // [1] |g_k| / L_k² and |ġ_k| / (L_k² / s) at convergence

}  // namespace

Status CoupledPendulum::validate() const {
  if (masses.empty()) return Error{"masses: at least one link"};
  if (lengths.size() != masses.size())
    return Error{"lengths: " + std::to_string(lengths.size()) + " for " + std::to_string(masses.size()) + " masses"};
  for (size_t k = 0; k < masses.size(); ++k) {
    if (!(masses[k] > 0.0) || !std::isfinite(masses[k])) return Error{"masses[" + std::to_string(k) + "]: must be > 0"};
    if (!(lengths[k] > 0.0) || !std::isfinite(lengths[k]))
      return Error{"lengths[" + std::to_string(k) + "]: must be > 0"};
  }
  if (!(damping >= 0.0) || !std::isfinite(damping)) return Error{"damping: must be >= 0"};
  return Status::success();
}

void CoupledPendulum::rest(const Vec3& at, const Vec3& direction) {
  pivot = at;
  pivotVelocity = Vec3(0.0);
  positions.assign(masses.size(), at);
  velocities.assign(masses.size(), Vec3(0.0));
  Vec3 p = at;
  for (size_t k = 0; k < masses.size(); ++k) positions[k] = p = p + lengths[k] * glm::normalize(direction);
}

void CoupledPendulum::step(const Vec3& newPivot, const Vec3& newPivotVelocity, const Vec3& gravity, Real h) {
  const size_t n = masses.size();
  if (n == 0 || positions.size() != n || velocities.size() != n || !(h > 0.0)) return;
  // Point k − 1 of rod k (the pivot for k = 0) and the inverse masses (the pivot's is 0: it is driven).
  auto w = [&](size_t k) { return 1.0 / masses[k]; };
  const std::vector<Vec3> old = positions;
  auto oldStart = [&](size_t k) { return k == 0 ? pivot : old[k - 1]; };

  // SHAKE: v½ = v + h/2 g, x' = x + h v½, then tensions along the old rods until |x'_k − x'_{k−1}| = L_k.
  std::vector<Vec3> half(n);
  for (size_t k = 0; k < n; ++k) {
    half[k] = velocities[k] + 0.5 * h * gravity;
    positions[k] = old[k] + h * half[k];
  }
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    Real worst = 0.0;
    for (size_t k = 0; k < n; ++k) {
      const Vec3 start = k == 0 ? newPivot : positions[k - 1];
      const Vec3 r = positions[k] - start, d = old[k] - oldStart(k);
      const Real L2 = lengths[k] * lengths[k];
      const Real c = glm::dot(r, r) - L2;
      worst = std::max(worst, std::abs(c) / L2);
      const Real wa = k == 0 ? 0.0 : w(k - 1), wb = w(k);
      const Real denominator = 2.0 * (wa + wb) * glm::dot(r, d);
      if (std::abs(denominator) < 1e-300) continue;
      const Real lambda = c / denominator;  // first-order root of g(x' + δ) = 0 along d
      if (k > 0) positions[k - 1] += wa * lambda * d;
      positions[k] -= wb * lambda * d;
    }
    if (worst < kRelativeTolerance) break;
  }
  for (size_t k = 0; k < n; ++k) half[k] = (positions[k] - old[k]) / h;

  // RATTLE's second half: v' = v½ + h/2 g, then no rod stretches: (x'_k − x'_{k−1})·(v'_k − v'_{k−1}) = 0.
  for (size_t k = 0; k < n; ++k) velocities[k] = half[k] + 0.5 * h * gravity;
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    Real worst = 0.0;
    for (size_t k = 0; k < n; ++k) {
      const Vec3 d = positions[k] - (k == 0 ? newPivot : positions[k - 1]);
      const Vec3 vStart = k == 0 ? newPivotVelocity : velocities[k - 1];
      const Real L2 = glm::dot(d, d);
      const Real rate = glm::dot(d, velocities[k] - vStart);
      worst = std::max(worst, std::abs(rate) / (lengths[k] * lengths[k]));
      const Real wa = k == 0 ? 0.0 : w(k - 1), wb = w(k);
      const Real mu = rate / ((wa + wb) * L2);
      if (k > 0) velocities[k - 1] += wa * mu * d;
      velocities[k] -= wb * mu * d;
    }
    if (worst < kRelativeTolerance) break;
  }
  pivot = newPivot;
  pivotVelocity = newPivotVelocity;
  if (damping > 0.0) {
    const Real keep = std::exp(-damping * h);
    for (Vec3& v : velocities) v = pivotVelocity + keep * (v - pivotVelocity);
  }
}

Real CoupledPendulum::energy(const Vec3& gravity) const {
  Real e = 0.0;
  for (size_t k = 0; k < masses.size() && k < positions.size() && k < velocities.size(); ++k) {
    const Vec3 v = velocities[k] - pivotVelocity;
    e += 0.5 * masses[k] * glm::dot(v, v) - masses[k] * glm::dot(gravity, positions[k] - pivot);
  }
  return e;
}

Real CoupledPendulum::constraintError() const {
  Real worst = 0.0;
  for (size_t k = 0; k < positions.size() && k < lengths.size(); ++k) {
    const Vec3 start = k == 0 ? pivot : positions[k - 1];
    worst = std::max(worst, std::abs(glm::length(positions[k] - start) - lengths[k]));
  }
  return worst;
}

}  // namespace pba::animation
