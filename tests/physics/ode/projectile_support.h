#pragma once
// A projectile for the integrator tests: one particle (3 coordinates, mass 2 kg) under gravity, plus a
// push along x that grows linearly in time, F_x = m·ramp·t (ramp = 0: none). Its closed form under
// gravity alone, x(t) = x₀ + v₀ t + g t²/2 and v(t) = v₀ + g t, is what methods exact for a constant
// acceleration must follow.
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "physics/core/types.h"
#include "physics/ode/integrators.h"
#include "physics/ode/ode_system.h"

namespace pba::ode::testing {

class Projectile final : public SecondOrderSystem {
 public:
  std::vector<Real> q{0.0, 2.0, 0.0}, v{3.0, 10.0, -1.0}, w{0.5, 0.5, 0.5};
  Real ramp = 0.0;  ///< [m/s³]: the push's acceleration grows by this per second
  Vec3 g{0.0, -kStandardGravity, 0.0};
  std::size_t dofCount() const override { return 3; }
  std::span<Real> positions() override { return q; }
  std::span<const Real> positions() const override { return q; }
  std::span<Real> velocities() override { return v; }
  std::span<const Real> velocities() const override { return v; }
  std::span<const Real> inverseMasses() const override { return w; }
  void force(Real t, std::span<const Real>, std::span<const Real>, std::span<Real> out) const override {
    for (int i = 0; i < 3; ++i) out[static_cast<std::size_t>(i)] = g[i] / w[0];
    out[0] += ramp * t / w[0];
  }
};

/// Steps a projectile under gravity alone (ramp 0) `steps` times by h and checks after every step its
/// position and velocity against the closed form, to `positionTolerance` and `velocityTolerance`, and its
/// clock against n h.
inline ::testing::AssertionResult followsTheProjectile(Integrator& integrator, Real h, int steps,
                                                       Real positionTolerance, Real velocityTolerance) {
  Projectile p;
  const Vec3 x0{p.q[0], p.q[1], p.q[2]}, v0{p.v[0], p.v[1], p.v[2]};
  for (int n = 1; n <= steps; ++n) {
    integrator.step(p, h);
    const Real t = n * h;
    const Vec3 x = x0 + v0 * t + 0.5 * p.g * t * t;
    const Vec3 v = v0 + p.g * t;
    for (int i = 0; i < 3; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!(std::abs(p.q[k] - x[i]) <= positionTolerance) || !(std::abs(p.v[k] - v[i]) <= velocityTolerance))
        return ::testing::AssertionFailure()
               << integratorName(integrator.kind()) << ", step " << n << ", coordinate " << i << ": (q, v) = ("
               << p.q[k] << ", " << p.v[k] << "), exact (" << x[i] << ", " << v[i] << ")";
    }
    if (!(std::abs(p.time() - t) <= 1e-12))
      return ::testing::AssertionFailure()
             << integratorName(integrator.kind()) << ", step " << n << ": time " << p.time() << ", expected " << t;
  }
  return ::testing::AssertionSuccess();
}

}  // namespace pba::ode::testing
