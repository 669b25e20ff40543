#include "physics/ode/pendulum.h"

#include <cmath>
#include <utility>

#include "physics/core/validate.h"

namespace pba::ode {

Status validate(const PendulumDesc& d) {
  for (Status s :
       {checkPositive("pendulum.mass", d.mass), checkPositive("pendulum.comOffset length", comDistance(d)),
        checkRange("pendulum.inertiaCm", d.inertiaCm, 0.0, 1e6), checkRange("pendulum.damping", d.damping, 0.0, 1e3),
        checkRange("pendulum.gravity", d.gravity, 0.0, 1e3)}) {
    if (!s) return s;
  }
  return Status::success();
}

Real comDistance(const PendulumDesc& d) { return std::hypot(d.comOffset.x, d.comOffset.y); }

Real comOffsetAngle(const PendulumDesc& d) { return std::atan2(d.comOffset.x, -d.comOffset.y); }

Vec3 pivotAccelerationFromPositions(const Vec3& previous, const Vec3& current, const Vec3& next, Real h) {
  return (next - 2.0 * current + previous) / (h * h);
}

Real pivotInertia(const PendulumDesc& d) {
  const Real l = comDistance(d);
  return d.inertiaCm + d.mass * l * l;
}

Vec3 centerOfMassOffset(const PendulumDesc& d, Real angle) {
  const Real phi = angle + comOffsetAngle(d);
  return comDistance(d) * Vec3(std::sin(phi), -std::cos(phi), 0.0);
}

Real angularAcceleration(const PendulumDesc& d, const PendulumState& s, const Vec3& ap) {
  const Vec3 y = centerOfMassOffset(d, s.angle);
  const Vec3 yPerp(-y.y, y.x, 0.0);  // y rotated by +90° about z
  // In the pivot's frame the body feels gravity plus the fictitious force −m a_p at its centre of mass.
  const Real torque =
      -d.mass * glm::dot(ap, yPerp) - d.mass * d.gravity * comDistance(d) * std::sin(s.angle + comOffsetAngle(d));
  return torque / pivotInertia(d);
}

PendulumState stepPendulum(const PendulumDesc& d, const PendulumState& s, const Vec3& ap, Real h) {
  PendulumState n;
  n.angularVelocity = (s.angularVelocity + h * angularAcceleration(d, s, ap)) * std::exp(-d.damping * h);
  n.angle = s.angle + h * n.angularVelocity;
  return n;
}

Real pendulumEnergy(const PendulumDesc& d, const PendulumState& s) {
  return 0.5 * pivotInertia(d) * s.angularVelocity * s.angularVelocity +
         d.mass * d.gravity * comDistance(d) * (1.0 - std::cos(s.angle + comOffsetAngle(d)));
}

PendulumSystem::PendulumSystem(const PendulumDesc& desc, PivotAcceleration pivotAcceleration)
    : OwnedStateSystem({0.0}, {0.0}, {1.0}), pivotAcceleration_(std::move(pivotAcceleration)) {
  setDesc(desc);
}

void PendulumSystem::setDesc(const PendulumDesc& desc) {
  desc_ = desc;
  w_[0] = 1.0 / pivotInertia(desc_);
}

void PendulumSystem::setPendulumState(const PendulumState& s) {
  positions()[0] = s.angle;
  velocities()[0] = s.angularVelocity;
  stateChanged();
}

void PendulumSystem::force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const {
  const Vec3 ap = pivotAcceleration_ ? pivotAcceleration_(t) : Vec3(0.0);
  const Real inertia = pivotInertia(desc_);
  out[0] = inertia * (angularAcceleration(desc_, PendulumState{q[0], v[0]}, ap) - desc_.damping * v[0]);
}

}  // namespace pba::ode
