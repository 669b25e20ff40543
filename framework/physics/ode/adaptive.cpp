// Adaptive step size with the embedded Dormand–Prince 5(4) pair (Dormand & Prince 1980; coefficients
// from Hairer, Nørsett & Wanner, "Solving Ordinary Differential Equations I", Table 5.2).
// The Lobb notes' adaptive scheme compares two steps of h/2 with one step of h; an embedded pair gets
// the same error estimate from one step, reusing its stages (and the last stage is the first of the
// next step: "first same as last", 6 new evaluations per step).
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <string>

#include "physics/core/format.h"
#include "physics/exercises/not_implemented.h"

#include "physics/ode/integrators.h"

namespace pba::ode {
namespace {
// Butcher tableau of DOPRI5.
constexpr Real c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr Real a21 = 1.0 / 5;
constexpr Real a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr Real a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr Real a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr Real a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176, a65 = -5103.0 / 18656;
// 5th-order weights (also the 7th stage's row: FSAL).
constexpr Real b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
// Error weights e = b − b̂ (difference of the 5th- and 4th-order solutions).
constexpr Real e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525,
               e7 = -1.0 / 40;

constexpr Real kMinFactor = 0.2;  // the most a retry shrinks a substep (PART-8's bound, used for non-finite ones)
}  // namespace

StepDecision controlStep([[maybe_unused]] Real error, [[maybe_unused]] Real d,
                         [[maybe_unused]] const AdaptiveSettings& settings) {
  // BEGIN SOLUTION
  constexpr Real kSafety = 0.9, kMaxFactor = 5.0;
  const Real allowed = settings.tolerance * d;  // error per unit step
  const bool accept = error <= allowed || d <= settings.minStep;
  // Local error ∝ d⁵, so error per unit step ∝ d⁴: exponent 1/4.
  const Real factor = error > 0.0 ? kSafety * std::pow(allowed / error, 0.25) : kMaxFactor;
  return {accept, std::max(settings.minStep, d * std::clamp(factor, kMinFactor, kMaxFactor))};
  // END SOLUTION
  // STUB: return exercises::notImplemented("PART-8", StepDecision{true, d}, error, settings);  // fixed steps
}

Status validate(const AdaptiveSettings& s) {
  if (!(std::isfinite(s.tolerance) && s.tolerance > 0.0)) {
    return Error{"adaptive.tolerance: must be a finite number > 0, got " + formatExact(s.tolerance)};
  }
  if (!(std::isfinite(s.minStep) && s.minStep > 0.0)) {
    return Error{"adaptive.minStep: must be a finite number > 0 [s], got " + formatExact(s.minStep)};
  }
  if (s.maxSubsteps < 1) return Error{"adaptive.maxSubsteps: must be at least 1, got " + std::to_string(s.maxSubsteps)};
  return Status::success();
}

void adaptiveStep(OdeSystem& system, Real h, const AdaptiveSettings& settings, AdaptiveState& st, Workspace& w) {
  assert(validate(settings).ok());
  const std::size_t n = system.stateSize();
  Workspace::fit(n, {&w.state, &w.k1, &w.k2, &w.k3, &w.k4, &w.k5, &w.k6, &w.k7, &w.tmp, &w.tmp2});
  std::vector<Real>& s = w.state;   // a copy (swapped with the candidate y when a substep is accepted)
  std::vector<Real>& y = w.tmp;     // stage argument, then the candidate solution
  std::vector<Real>& err = w.tmp2;  // error estimate
  Real t = system.time();
  const Real end = t + h;
  system.getState(s);
  Real delta = st.nextStep > 0.0 ? std::min(st.nextStep, h) : h;
  system.derivative(t, s, w.k1);
  ++st.evaluations;
  auto stage = [&](Real tc, auto&& combine, std::vector<Real>& k) {
    for (std::size_t i = 0; i < n; ++i) y[i] = s[i] + combine(i);
    system.derivative(tc, y, k);
    ++st.evaluations;
  };
  bool reachedEnd = false;
  for (int sub = 0; sub < settings.maxSubsteps; ++sub) {
    const Real remaining = end - t;
    // Take the remainder when it is close to the proposal, so that no sliver of a step is left.
    const bool last = delta >= remaining * (1.0 - 1e-12) || remaining - delta < settings.minStep;
    const Real d = last ? remaining : delta;
    stage(
        t + c2 * d, [&](std::size_t i) { return d * a21 * w.k1[i]; }, w.k2);
    stage(
        t + c3 * d, [&](std::size_t i) { return d * (a31 * w.k1[i] + a32 * w.k2[i]); }, w.k3);
    stage(
        t + c4 * d, [&](std::size_t i) { return d * (a41 * w.k1[i] + a42 * w.k2[i] + a43 * w.k3[i]); }, w.k4);
    stage(
        t + c5 * d, [&](std::size_t i) { return d * (a51 * w.k1[i] + a52 * w.k2[i] + a53 * w.k3[i] + a54 * w.k4[i]); },
        w.k5);
    stage(
        t + d,
        [&](std::size_t i) {
          return d * (a61 * w.k1[i] + a62 * w.k2[i] + a63 * w.k3[i] + a64 * w.k4[i] + a65 * w.k5[i]);
        },
        w.k6);
    // 5th-order candidate (propagated, "local extrapolation"), and its derivative (FSAL stage 7).
    stage(
        t + d,
        [&](std::size_t i) { return d * (b1 * w.k1[i] + b3 * w.k3[i] + b4 * w.k4[i] + b5 * w.k5[i] + b6 * w.k6[i]); },
        w.k7);
    Real errorNorm = 0.0;
    bool finite = true;
    for (std::size_t i = 0; i < n; ++i) {
      err[i] = d * (e1 * w.k1[i] + e3 * w.k3[i] + e4 * w.k4[i] + e5 * w.k5[i] + e6 * w.k6[i] + e7 * w.k7[i]);
      // A NaN or ±∞ anywhere (in the candidate or in its derivative, which the next substep starts
      // from) makes the substep unusable, however small the other components' error.
      finite = finite && std::isfinite(err[i]) && std::isfinite(y[i]) && std::isfinite(w.k7[i]);
      if (!finite) break;
      const Real scale = std::max({1.0, std::abs(s[i]), std::abs(y[i])});
      errorNorm = std::max(errorNorm, std::abs(err[i]) / scale);
    }
    if (!finite) {
      // Never committed: retry at the smallest factor the controller allows, down to minStep.
      ++st.rejected;
      ++st.nonFiniteRejections;
      if (d <= settings.minStep) break;  // it stays non-finite at the smallest step: stop here
      delta = std::max(settings.minStep, kMinFactor * d);
      continue;
    }
    const StepDecision decision = controlStep(errorNorm, d, settings);
    const Real proposal = decision.next;
    if (decision.accept) {
      ++st.accepted;
      t = last ? end : t + d;
      s.swap(y);
      w.k1.swap(w.k7);  // FSAL
      if (!last || proposal < delta) delta = proposal;
      if (last) {
        reachedEnd = true;
        break;
      }
    } else {
      ++st.rejected;
      delta = proposal;
    }
  }
  st.nextStep = delta;
  st.shortfall = reachedEnd ? 0.0 : end - t;
  system.setState(s);
  system.setTime(t);  // the time of the state: end, or the last accepted substep when cut short
}

}  // namespace pba::ode
