#include "physics/ode/oscillator.h"

#include <cmath>

namespace pba::ode {

HarmonicOscillator::HarmonicOscillator(const OscillatorDesc& d)
    : OwnedStateSystem(std::vector<Real>(static_cast<std::size_t>(d.copies), d.x0),
                       std::vector<Real>(static_cast<std::size_t>(d.copies), d.v0),
                       std::vector<Real>(static_cast<std::size_t>(d.copies), 1.0 / d.mass)),
      desc_(d) {}

Real HarmonicOscillator::omega() const { return std::sqrt(desc_.stiffness / desc_.mass); }

Real HarmonicOscillator::exactPosition(Real t) const {
  const Real w = omega();
  return desc_.x0 * std::cos(w * t) + desc_.v0 / w * std::sin(w * t);
}

Real HarmonicOscillator::exactVelocity(Real t) const {
  const Real w = omega();
  return -desc_.x0 * w * std::sin(w * t) + desc_.v0 * std::cos(w * t);
}

Real HarmonicOscillator::energy(std::size_t i) const {
  const Real q = positions()[i], v = velocities()[i];
  return 0.5 * desc_.mass * v * v + 0.5 * desc_.stiffness * q * q;
}

void HarmonicOscillator::force(Real, std::span<const Real> q, std::span<const Real>, std::span<Real> out) const {
  for (std::size_t i = 0; i < q.size(); ++i) out[i] = -desc_.stiffness * q[i];
}

void HarmonicOscillator::acceleration(Real, std::span<const Real> q, std::span<const Real>, std::span<Real> out) const {
  // k in a local: stores through out could otherwise alias desc_ and reload it every iteration.
  const Real k = desc_.stiffness;
  const Real* __restrict w = w_.data();
  for (std::size_t i = 0; i < q.size(); ++i) out[i] = (-k * q[i]) * w[i];
}

void HarmonicOscillator::forceDifferential(Real, std::span<const Real>, std::span<const Real>, std::span<const Real> dq,
                                           std::span<const Real>, std::span<Real> out) {
  for (std::size_t i = 0; i < dq.size(); ++i) out[i] = -desc_.stiffness * dq[i];  // K = −k I, D = 0
}

void HarmonicOscillator::uncoupledForce(Real, std::span<const Real> q, std::span<const Real>, std::size_t first,
                                        std::span<Real> f, std::span<Real> dfdq, std::span<Real> dfdv) const {
  const Real k = desc_.stiffness;
  for (std::size_t i = 0; i < f.size(); ++i) {
    f[i] = -k * q[first + i];
    dfdq[i] = -k;
    dfdv[i] = 0.0;
  }
}

KeplerOrbit::KeplerOrbit(const OrbitDesc& d)
    : OwnedStateSystem({d.position.x, d.position.y, d.position.z}, {d.velocity.x, d.velocity.y, d.velocity.z},
                       std::vector<Real>(3, 1.0 / d.planetMass)),
      desc_(d) {}

Real KeplerOrbit::energy() const {
  return 0.5 * desc_.planetMass * glm::dot(velocity(), velocity()) -
         desc_.gm * desc_.planetMass / glm::length(position());
}

Vec3 KeplerOrbit::angularMomentum() const { return desc_.planetMass * glm::cross(position(), velocity()); }

Real KeplerOrbit::period() const {
  // E = −G M m / (2a)  ⇒  a = −G M m / (2E).
  const Real a = -desc_.gm * desc_.planetMass / (2.0 * energy());
  return 2.0 * kPi * std::sqrt(a * a * a / desc_.gm);
}

void KeplerOrbit::force(Real, std::span<const Real> q, std::span<const Real>, std::span<Real> out) const {
  const Vec3 r{q[0], q[1], q[2]};
  const Real d = glm::length(r);
  const Vec3 f = -desc_.gm * desc_.planetMass / (d * d * d) * r;
  out[0] = f.x;
  out[1] = f.y;
  out[2] = f.z;
}

}  // namespace pba::ode
