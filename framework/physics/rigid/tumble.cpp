#include "physics/rigid/tumble.h"

#include <algorithm>
#include <cmath>

namespace pba::rigid {

namespace {
Mat3 safeInverse(const Mat3& m) {
  const Real det = glm::determinant(m);
  return std::isfinite(det) && std::abs(det) > 1e-300 ? glm::inverse(m) : Mat3(0.0);
}
}  // namespace

void tumbleStep(TumbleBox& box, const TumbleSettings& s, Real h, std::vector<TumbleContact>& contacts) {
  contacts.clear();
  box.velocity += h * s.gravity;
  const Mat3 inertia = boxInertiaTensor(box.mass, box.halfExtents, box.orientation);
  ImpulseBody a{1.0 / box.mass, safeInverse(inertia), box.position, box.velocity, box.angularVelocity};
  const ImpulseBody ground{};
  const Vec3 n = kUp;
  for (int i = 0; i < 8; ++i) {
    const Vec3& e = box.halfExtents;
    const Vec3 corner =
        box.position + box.orientation * Vec3(i & 1 ? e.x : -e.x, i & 2 ? e.y : -e.y, i & 4 ? e.z : -e.z);
    // Corners within a millimetre count as touching, so a box at rest keeps its contacts from step to step.
    constexpr Real kTouching = 1e-3;  // [m]
    if (corner.y < kTouching) contacts.push_back({corner, std::max(0.0, -corner.y), 0.0, Vec3(0.0)});
  }
  for (int sweep = 0; sweep < s.sweeps; ++sweep) {
    for (TumbleContact& c : contacts) {
      const Real approach = -glm::dot(n, a.velocityAt(c.point));
      const Real e = approach > s.restingSpeed ? s.restitution : 0.0;
      const Real j = collisionImpulse(a, ground, c.point, n, e);
      a.velocity += a.inverseMass * j * n;
      a.angularVelocity += a.inverseInertia * glm::cross(c.point - a.position, j * n);
      c.normalImpulse += j;
      const Vec3 f = frictionImpulse(a, ground, c.point, n, j, s.friction);
      a.velocity += a.inverseMass * f;
      a.angularVelocity += a.inverseInertia * glm::cross(c.point - a.position, f);
      c.frictionImpulse += f;
    }
  }
  Real deepest = 0.0;
  for (const TumbleContact& c : contacts) deepest = std::max(deepest, c.depth);
  box.position.y += deepest;
  // Safety net (a no-op once RIGID-3 is solved): a box touching the ground never keeps sinking.
  if (!contacts.empty() && a.velocity.y < 0.0 && glm::length(a.velocity) < 1e3) {
    bool anyApproach = false;
    for (const TumbleContact& c : contacts)
      anyApproach |= glm::dot(n, a.velocityAt(c.point)) < 0.0 && c.normalImpulse == 0.0;
    if (anyApproach) a.velocity.y = 0.0;
  }
  box.velocity = a.velocity;
  box.angularVelocity = a.angularVelocity;
  box.position += h * box.velocity;
  box.orientation = integrateOrientation(box.orientation, box.angularVelocity, h);
}

Real tumbleEnergy(const TumbleBox& box, const TumbleSettings& s) {
  const Mat3 inertia = boxInertiaTensor(box.mass, box.halfExtents, box.orientation);
  return 0.5 * box.mass * glm::dot(box.velocity, box.velocity) +
         0.5 * glm::dot(box.angularVelocity, inertia * box.angularVelocity) -
         box.mass * glm::dot(s.gravity, box.position);
}

}  // namespace pba::rigid
