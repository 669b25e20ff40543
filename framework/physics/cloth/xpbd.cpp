#include "physics/cloth/xpbd.h"

#include <array>
#include <cmath>

#include "physics/cloth/forces.h"
#include "physics/cloth/xpbd_fast_path.h"
#include "physics/exercises/not_implemented.h"

namespace pba::cloth {
namespace {
// [m] Coincident particles have no constraint direction (only the CLOTH-2 solution uses it: maybe unused in the
// hand-out).
[[maybe_unused]] constexpr Real kMinLength = 1e-12;
}  // namespace

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

void projectIsometricBending([[maybe_unused]] const BendingStencil& s, [[maybe_unused]] std::span<Vec3> x,
                             [[maybe_unused]] std::span<const Real> w, [[maybe_unused]] Real compliance,
                             [[maybe_unused]] Real h, [[maybe_unused]] Vec3& lambda) {
  // BEGIN SOLUTION
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
  // END SOLUTION
  // STUB: exercises::markNotImplemented("CLOTH-6");
}

namespace {
// flatten: CLOTH-2's correction is inlined into the sweep (the call would cost as much as the correction).
// The sweep hands CLOTH-2 the scaled compliance α̃ = α/h² of each kind, computed once, with h = 1: then
// α̃/h² is α̃ exactly and the compiler drops the division, one of the four a constraint costs.
// One loop per mode: XPBD adds the corrections as they are (PBD's stiffness would be 1, and 1·Δx is Δx to
// the bit) and passes λ; PBD scales them and passes λ = 0.
template <bool kXpbd>
[[gnu::flatten]] void sweepLinks(std::span<const Link> links, const std::array<Real, kLinkKinds>& alphaTilde,
                                 Real pbdStiffness, std::span<Vec3> x, std::span<const Real> w,
                                 std::span<Real> lambda) {
  for (std::size_t k = 0; k < links.size(); ++k) {
    const Link& l = links[k];
    const DistanceCorrection c =
        xpbdDistanceCorrection(x[l.i], x[l.j], w[l.i], w[l.j], l.restLength,
                               alphaTilde[static_cast<std::size_t>(l.kind)], 1.0, kXpbd ? lambda[k] : 0.0);
    if constexpr (kXpbd) {
      x[l.i] += c.deltaI;
      x[l.j] += c.deltaJ;
    } else {
      x[l.i] += pbdStiffness * c.deltaI;
      x[l.j] += pbdStiffness * c.deltaJ;
    }
    lambda[k] += c.deltaLambda;
  }
}
}  // namespace

void sweepXpbdLinksScalar(std::span<const Link> links, const std::array<Real, kLinkKinds>& alphaTilde,
                          std::span<Vec3> x, std::span<const Real> w, std::span<Real> lambda) {
  sweepLinks<true>(links, alphaTilde, 1.0, x, w, lambda);
}

void sweepDistanceConstraints(std::span<const Link> links, const std::array<Real, kLinkKinds>& compliance,
                              const SweepMode& mode, Real h, std::span<Vec3> x, std::span<const Real> w,
                              std::span<Real> lambda) {
  std::array<Real, kLinkKinds> alphaTilde{};
  for (std::size_t k = 0; k < kLinkKinds; ++k) alphaTilde[k] = mode.xpbd ? compliance[k] / (h * h) : 0.0;
  if (mode.xpbd) {
    sweepXpbdLinksFast(links, alphaTilde, x, w, lambda);  // CLOTH-2's fast path (xpbd_fast_path.h)
  } else {
    sweepLinks<false>(links, alphaTilde, mode.pbdStiffness, x, w, lambda);
  }
}

void sweepIsometricBending(std::span<const BendingStencil> stencils, Real compliance, const SweepMode& mode, Real h,
                           std::span<Vec3> x, std::span<const Real> w, std::span<Vec3> lambda) {
  for (std::size_t k = 0; k < stencils.size(); ++k) {
    const BendingStencil& s = stencils[k];
    if (mode.xpbd) {
      projectIsometricBending(s, x, w, compliance, h, lambda[k]);
      continue;
    }
    // PBD: the exact projection (compliance 0) scaled by the stiffness, as for stretch.
    std::array<Vec3, 4> before;
    for (int v = 0; v < 4; ++v) before[v] = x[s.vertex[v]];
    Vec3 unused(0.0);
    projectIsometricBending(s, x, w, 0.0, h, unused);
    for (int v = 0; v < 4; ++v) x[s.vertex[v]] = before[v] + mode.pbdStiffness * (x[s.vertex[v]] - before[v]);
  }
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

namespace {
/// CLOTH-6 on a folded pair of unit right triangles (weights of no particular stencil).
void probeIsometricBending() {
  BendingStencil s;
  s.vertex = {0, 1, 2, 3};
  s.weight = {1.0, 1.0, -1.0, -1.0};
  std::array<Vec3, 4> x{Vec3(0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0), Vec3(1.0, 0.0, 1.0)};
  const std::array<Real, 4> w{1.0, 1.0, 1.0, 1.0};
  Vec3 lambda(0.0);
  projectIsometricBending(s, x, w, 0.0, 0.01, lambda);
}
}  // namespace
// Start-up probe: tells the lab whether CLOTH-6 is still a stub.
PBA_EXERCISE_PROBE(probeIsometricBending());

}  // namespace pba::cloth
