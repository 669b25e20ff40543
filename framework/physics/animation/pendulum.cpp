#include "physics/animation/pendulum.h"

#include <cmath>

#include "physics/exercises/not_implemented.h"

namespace pba::animation {

Vec3 rotateByVector(const Vec3& d, const Vec3& phi) {
  const Real angle = glm::length(phi);
  if (angle < 1e-15) return d;
  const Vec3 n = phi / angle;
  const Real c = std::cos(angle), s = std::sin(angle);
  return c * d + s * glm::cross(n, d) + (1.0 - c) * glm::dot(n, d) * n;
}

namespace {
/// Rotation vector taking unit a onto unit b (angle in [0, π]).
Vec3 rotationBetween(const Vec3& a, const Vec3& b) {
  const Vec3 axis = glm::cross(a, b);
  const Real s = glm::length(axis);
  const Real angle = std::atan2(s, glm::dot(a, b));
  if (s < 1e-12) return Vec3(0.0);
  return (angle / s) * axis;
}
}  // namespace

// ***** ANIM-4: the pendulum joint step with the reaction term (CMU asst4, "Pendulum joints") *****
// One symplectic Euler step dt [s] of a link of mass m, length L and inertia I about its pivot: its unit
// direction d, angular velocity ω [rad/s] (world axes), the pivot's acceleration a [m/s²], gravity g.
// (1) In the pivot's frame the link feels gravity and an inertial pull opposite to the pivot's
//     acceleration (the reaction term, only when drive.reaction is on).
// (2) The angular acceleration is the torque of that pull about the pivot over I; a spring joint (k > 0)
//     adds a restoring torque proportional to the rotation that takes the rest direction onto d
//     (rotationBetween gives it).
// (3) Symplectic Euler: update ω first, damp it (exponential decay at rate c), then turn d by the NEW ω
//     over dt (rotateByVector) and bring it back to unit length. A spin about the link itself does
//     nothing here: keep ω perpendicular to d.
// Check: small swings have the period 2π √(I / (m g L)); with the reaction on, a pivot accelerating
// downwards with g (falling freely) lets the link float.
// *****
PendulumState stepPendulum(const PendulumDesc& desc, const PendulumState& state, const PendulumDrive& drive, Real dt) {
  // BEGIN SOLUTION
  const Real inertia = desc.momentOfInertia();
  const Vec3 effectiveGravity = drive.reaction ? drive.gravity - drive.pivotAcceleration : drive.gravity;
  Vec3 alpha = (desc.mass * desc.length / inertia) * glm::cross(state.direction, effectiveGravity);
  if (desc.stiffness > 0.0) alpha -= (desc.stiffness / inertia) * rotationBetween(drive.restDirection, state.direction);
  PendulumState next;
  next.omega = (state.omega + dt * alpha) * std::exp(-desc.damping * dt);
  next.omega -= glm::dot(next.omega, state.direction) * state.direction;
  next.direction = glm::normalize(rotateByVector(state.direction, dt * next.omega));
  return next;
  // END SOLUTION
  // STUB: return exercises::notImplemented("ANIM-4", state, desc, drive, dt);
}

Real pendulumEnergy(const PendulumDesc& desc, const PendulumState& state, const PendulumDrive& drive) {
  const Real kinetic = 0.5 * desc.momentOfInertia() * glm::dot(state.omega, state.omega);
  const Real potential = -desc.mass * desc.length * glm::dot(state.direction, drive.gravity);
  Real spring = 0.0;
  if (desc.stiffness > 0.0) {
    const Vec3 phi = rotationBetween(drive.restDirection, state.direction);
    spring = 0.5 * desc.stiffness * glm::dot(phi, phi);
  }
  return kinetic + potential + spring;
}

void PendulumChain::rest(const Vec3& pivot, const Vec3& restDirection) {
  states.assign(links.size(), PendulumState{glm::normalize(restDirection), Vec3(0.0)});
  tips.resize(links.size());
  Vec3 p = pivot;
  for (size_t k = 0; k < links.size(); ++k) tips[k] = p = p + links[k].length * states[k].direction;
}

void PendulumChain::step(const Vec3& pivot, const PendulumDrive& drive, Real dt) {
  if (states.size() != links.size()) rest(pivot, drive.restDirection);
  PendulumDrive d = drive;
  Vec3 p = pivot;
  for (size_t k = 0; k < links.size(); ++k) {
    const PendulumState before = states[k];
    states[k] = stepPendulum(links[k], before, d, dt);
    // The tip's acceleration drives the next link: a + ω̇ × r + ω × (ω × r), r = L d.
    const Vec3 r = links[k].length * states[k].direction;
    const Vec3 omegaDot = (states[k].omega - before.omega) / dt;
    d.pivotAcceleration =
        d.pivotAcceleration + glm::cross(omegaDot, r) + glm::cross(states[k].omega, glm::cross(states[k].omega, r));
    d.restDirection = states[k].direction;
    tips[k] = p = p + r;
  }
}

Real PendulumChain::energy(const Vec3& pivot, const PendulumDrive& drive) const {
  static_cast<void>(pivot);
  Real e = 0.0;
  PendulumDrive d = drive;
  for (size_t k = 0; k < links.size() && k < states.size(); ++k) {
    e += pendulumEnergy(links[k], states[k], d);
    d.restDirection = states[k].direction;  // link k + 1's spring pulls toward link k (as in step)
  }
  return e;
}

}  // namespace pba::animation

PBA_EXERCISE_PROBE(pba::animation::stepPendulum(pba::animation::PendulumDesc{}, pba::animation::PendulumState{},
                                                pba::animation::PendulumDrive{}, 0.01));
