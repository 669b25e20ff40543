#include "physics/springs/spring_network.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "physics/exercises/not_implemented.h"

namespace pba::springs {
namespace {
constexpr Real kMinLength = 1e-12;  // [m] below this a spring has no direction
}

Vec3 dampedSpringForce([[maybe_unused]] const Vec3& xi, [[maybe_unused]] const Vec3& xj,
                       [[maybe_unused]] const Vec3& vi, [[maybe_unused]] const Vec3& vj,
                       [[maybe_unused]] Real stiffness, [[maybe_unused]] Real restLength,
                       [[maybe_unused]] Real damping) {
  // BEGIN SOLUTION
  const Vec3 r = xj - xi;
  const Real l = glm::length(r);
  if (l < kMinLength) return Vec3(0.0);
  const Vec3 direction = r / l;
  const Real magnitude = stiffness * (l - restLength) + damping * glm::dot(direction, vj - vi);
  return magnitude * direction;
  // END SOLUTION
  // STUB: return exercises::notImplemented("PART-4", Vec3(0.0));
}

void accumulateSpringForces(std::span<const Spring> springs, std::span<const Vec3> x, std::span<const Vec3> v,
                            std::span<Vec3> f) {
  for (const Spring& s : springs) {
    const Vec3 fi = dampedSpringForce(x[s.i], x[s.j], v[s.i], v[s.j], s.stiffness, s.restLength, s.damping);
    f[s.i] += fi;
    f[s.j] -= fi;
  }
}

namespace {
// What the Jacobian of one spring needs (header, "Jacobian"): the unit direction r̂ and the lateral factor
// max(0, 1 − L/l) with the definiteness clamp. Nothing for a spring of (nearly) zero length.
struct Linearisation {
  Vec3 direction;
  Real lateral;
};
std::optional<Linearisation> linearise(const Spring& s, std::span<const Vec3> x) {
  const Vec3 r = x[s.j] - x[s.i];
  const Real l = glm::length(r);
  if (l < kMinLength) return std::nullopt;
  return Linearisation{r / l, std::max(0.0, 1.0 - s.restLength / l)};
}
}  // namespace

void accumulateSpringDifferential(std::span<const Spring> springs, std::span<const Vec3> x, std::span<const Vec3> dx,
                                  std::span<const Vec3> dv, std::span<Vec3> df) {
  for (const Spring& s : springs) {
    const std::optional<Linearisation> lin = linearise(s, x);
    if (!lin) continue;
    const Vec3 n = lin->direction;
    const Vec3 ddx = dx[s.j] - dx[s.i];
    const Vec3 ddv = dv[s.j] - dv[s.i];
    const Real along = glm::dot(n, ddx);
    // K_s ddx = k [ n (n·ddx) + lateral (ddx − n (n·ddx)) ],  K_d ddv = k_d n (n·ddv)
    const Vec3 d = s.stiffness * (along * n + lin->lateral * (ddx - along * n)) + s.damping * glm::dot(n, ddv) * n;
    df[s.i] += d;
    df[s.j] -= d;
  }
}

void accumulateSpringJacobianDiagonal(std::span<const Spring> springs, std::span<const Vec3> x,
                                      std::span<Mat3> dfdx, std::span<Mat3> dfdv) {
  for (const Spring& s : springs) {
    const std::optional<Linearisation> lin = linearise(s, x);
    if (!lin) continue;
    const Mat3 nn = glm::outerProduct(lin->direction, lin->direction);
    // ∂F_i/∂x_i = ∂F_j/∂x_j = −K_s and ∂F_i/∂v_i = ∂F_j/∂v_j = −K_d (header).
    const Mat3 ks = s.stiffness * (lin->lateral * Mat3(1.0) + (1.0 - lin->lateral) * nn);
    const Mat3 kd = s.damping * nn;
    dfdx[s.i] -= ks;
    dfdx[s.j] -= ks;
    dfdv[s.i] -= kd;
    dfdv[s.j] -= kd;
  }
}

Real springPotentialEnergy(std::span<const Spring> springs, std::span<const Vec3> x) {
  Real e = 0.0;
  for (const Spring& s : springs) {
    const Real stretch = glm::length(x[s.j] - x[s.i]) - s.restLength;
    e += 0.5 * s.stiffness * stretch * stretch;
  }
  return e;
}

Real maxRelativeStretch(std::span<const Spring> springs, std::span<const Vec3> x) {
  Real worst = 0.0;
  for (const Spring& s : springs) {
    worst = std::max(worst, std::abs(glm::length(x[s.j] - x[s.i]) - s.restLength) / s.restLength);
  }
  return worst;
}

// Start-up probe: tells the lab whether PART-4 is still a stub.
PBA_EXERCISE_PROBE(dampedSpringForce(Vec3(0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.0), Vec3(0.0), 1.0, 0.5, 0.1));

}  // namespace pba::springs
