#pragma once
// Soft constraints (Catto, "Solver2D" and Box2D v3 src/solver.h b2MakeSoft; derived from the implicit
// spring-damper of Catto's GDC 2011 "Soft Constraints"). A constraint C with a spring of frequency f and
// damping ratio ζ, integrated implicitly with step h, gives the velocity update
//   λ = −m_eff · massScale · (Ċ + biasRate · C) − impulseScale · λ_accumulated
// with ω = 2πf, a₁ = 2ζ + hω, a₂ = hωa₁, a₃ = 1/(1 + a₂):
//   biasRate = ω / a₁,  massScale = a₂ a₃,  impulseScale = a₃.
// Limiting cases: f → ∞ gives massScale → 1, impulseScale → 0 and biasRate → 1/h: a rigid constraint
// that removes the whole error in one step. f = 0 gives no force at all.
#include <cmath>

#include "physics/core/types.h"

namespace pba::rigid {

struct Softness {
  Real biasRate = 0.0;  ///< [1/s]
  Real massScale = 1.0;
  Real impulseScale = 0.0;
};

inline Softness makeSoft(Real hertz, Real dampingRatio, Real h) {
  if (hertz == 0.0) return {0.0, 1.0, 0.0};
  const Real omega = 2.0 * kPi * hertz;
  const Real a1 = 2.0 * dampingRatio + h * omega;
  const Real a2 = h * omega * a1;
  const Real a3 = 1.0 / (1.0 + a2);
  return {omega / a1, a2 * a3, a3};
}

}  // namespace pba::rigid
