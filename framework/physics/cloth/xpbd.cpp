#include "physics/cloth/xpbd.h"

#include <cmath>

#include "physics/cloth/forces.h"
#include "physics/exercises/not_implemented.h"

namespace pba::cloth {
namespace {
constexpr Real kMinLength = 1e-12;  // [m] coincident particles have no constraint direction
}

DistanceCorrection xpbdDistanceCorrection([[maybe_unused]] const Vec3& xi, [[maybe_unused]] const Vec3& xj,
                                          [[maybe_unused]] Real wi, [[maybe_unused]] Real wj,
                                          [[maybe_unused]] Real restLength, [[maybe_unused]] Real compliance,
                                          [[maybe_unused]] Real h, [[maybe_unused]] Real lambda) {
  // BEGIN SOLUTION
  const Vec3 r = xi - xj;
  const Real l = glm::length(r);
  const Real wSum = wi + wj;
  if (l < kMinLength || wSum == 0.0) return {};
  const Vec3 n = r / l;
  const Real alphaTilde = compliance / (h * h);
  const Real deltaLambda = (-(l - restLength) - alphaTilde * lambda) / (wSum + alphaTilde);
  return {wi * deltaLambda * n, -wj * deltaLambda * n, deltaLambda};
  // END SOLUTION
  // STUB: return exercises::notImplemented("CLOTH-2", DistanceCorrection{}, xi, xj, wi, wj, restLength, compliance, h, lambda);
}

void projectIsometricBending(const BendingStencil& s, std::span<Vec3> x, std::span<const Real> w, Real compliance,
                             Real h, Vec3& lambda) {
  Vec3 c(0.0);
  Real denominator = 0.0;
  for (int k = 0; k < 4; ++k) {
    c += s.weight[k] * x[s.vertex[k]];
    denominator += w[s.vertex[k]] * s.weight[k] * s.weight[k];
  }
  const Real alphaTilde = compliance / (h * h);
  if (denominator + alphaTilde <= 0.0) return;
  const Vec3 deltaLambda = (-c - alphaTilde * lambda) / (denominator + alphaTilde);
  lambda += deltaLambda;
  for (int k = 0; k < 4; ++k) x[s.vertex[k]] += w[s.vertex[k]] * s.weight[k] * deltaLambda;
}

Real bendingEnergy(std::span<const BendingStencil> stencils, std::span<const Vec3> x, Real compliance) {
  if (compliance <= 0.0) return 0.0;
  Real e = 0.0;
  for (const BendingStencil& s : stencils) {
    Vec3 c(0.0);
    for (int k = 0; k < 4; ++k) c += s.weight[k] * x[s.vertex[k]];
    e += 0.5 * glm::dot(c, c) / compliance;
  }
  return e;
}

Real constraintEnergy(std::span<const Link> constraints, std::span<const Vec3> x, const ClothMaterial& m) {
  const std::array<Real, kLinkKinds> alpha = constraintCompliance(m);
  Real e = 0.0;
  for (const Link& l : constraints) {
    const Real a = alpha[static_cast<std::size_t>(l.kind)];
    if (a <= 0.0) continue;
    const Real c = glm::length(x[l.i] - x[l.j]) - l.restLength;
    e += 0.5 * c * c / a;
  }
  return e;
}

// Start-up probe: tells the lab whether CLOTH-2 is still a stub.
PBA_EXERCISE_PROBE(xpbdDistanceCorrection(Vec3(0.0), Vec3(1.0, 0.0, 0.0), 1.0, 1.0, 0.5, 0.0, 0.01, 0.0));

}  // namespace pba::cloth
