// Integrator names and the run-time dispatch of Integrator::step().
#include <cassert>

#include "physics/ode/integrators.h"

namespace pba::ode {

int integratorOrder(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::Euler:
    case IntegratorKind::SymplecticEuler:
    case IntegratorKind::ImplicitEuler:
      return 1;
    case IntegratorKind::Midpoint:
    case IntegratorKind::Verlet:
    case IntegratorKind::VelocityVerlet:
      return 2;
    case IntegratorKind::Rk4:
      return 4;
    case IntegratorKind::Adaptive:
      return 5;
  }
  return 1;
}

std::optional<DueStep> nextDueStep(Real t, Real h, Real until, Real stopAt) {
  assert(h > 0.0);
  const Real tolerance = 1e-9 * h;
  const Real remaining = stopAt - t;
  if (remaining <= tolerance) return std::nullopt;
  const bool last = remaining <= h + tolerance;
  const DueStep step{last ? remaining : h, last ? stopAt : t + h};
  if (step.end > until + tolerance) return std::nullopt;
  return step;
}

void Integrator::setKind(IntegratorKind kind) {
  if (kind != kind_) reset();
  kind_ = kind;
}

void Integrator::reset() {
  verlet_ = VerletHistory{};
  adaptive_ = AdaptiveState{};
  implicitStats_ = ImplicitEulerStats{};
}

Status Integrator::setImplicitSettings(const ImplicitEulerSettings& settings) {
  if (Status s = validate(settings); !s) return s;
  implicitSettings_ = settings;
  return Status::success();
}

Status Integrator::setAdaptiveSettings(const AdaptiveSettings& settings) {
  if (Status s = validate(settings); !s) return s;
  adaptiveSettings_ = settings;
  return Status::success();
}

void Integrator::step(SecondOrderSystem& system, Real h) {
  assert(h > 0.0);
  switch (kind_) {
    case IntegratorKind::Euler:
      explicitEulerStep(system, h, work_);
      break;
    case IntegratorKind::SymplecticEuler:
      symplecticEulerStep(system, h, work_);
      break;
    case IntegratorKind::Midpoint:
      midpointStep(system, h, work_);
      break;
    case IntegratorKind::Rk4:
      rk4Step(system, h, work_);
      break;
    case IntegratorKind::Verlet:
      verletStep(system, h, verlet_, work_);
      break;
    case IntegratorKind::VelocityVerlet:
      velocityVerletStep(system, h, work_);
      break;
    case IntegratorKind::ImplicitEuler:
      implicitStats_ = implicitEulerStep(system, h, implicitSettings_, work_);
      break;
    case IntegratorKind::Adaptive:
      adaptiveStep(system, h, adaptiveSettings_, adaptive_, work_);
      break;
  }
}

}  // namespace pba::ode
