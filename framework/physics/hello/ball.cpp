#include "physics/hello/ball.h"

#include <algorithm>
#include <cmath>

#include "physics/core/validate.h"
#include "physics/exercises/not_implemented.h"

namespace pba::hello {

Status validate(const BallDesc& d) {
  for (Status s : {checkRange("mass", d.mass, 1e-6, 1e6), checkRange("radius", d.radius, 1e-4, 100.0),
                   checkRange("restitution", d.restitution, 0.0, 1.0), checkRange("drag", d.drag, 0.0, 1e4),
                   checkRange("gravity", d.gravity, 0.0, 1e3), checkRange("dropHeight", d.dropHeight, 0.0, 1e4),
                   checkRange("groundHeight", d.groundHeight, -1e4, 1e4)}) {
    if (!s) return s;
  }
  return Status::success();
}

std::optional<std::string> nonFiniteState(const BallState& s) {
  if (!isFinite(s.position)) return "ball position is not finite";
  if (!isFinite(s.velocity)) return "ball velocity is not finite";
  return std::nullopt;
}

BallState initialState(const BallDesc& d) {
  return BallState{Vec3(0.0, d.groundHeight + d.radius + d.dropHeight, 0.0), Vec3(0.0)};
}

Vec3 acceleration(const BallDesc& d, const Vec3& v) { return Vec3(0.0, -d.gravity, 0.0) - (d.drag / d.mass) * v; }

Real energy(const BallDesc& d, const BallState& s) {
  return 0.5 * d.mass * glm::dot(s.velocity, s.velocity) + d.mass * d.gravity * heightAboveGround(d, s);
}

Real heightAboveGround(const BallDesc& d, const BallState& s) { return s.position.y - d.radius - d.groundHeight; }

BallState eulerStep(const BallState& state, const Vec3& acceleration, Real h) {
  // BEGIN SOLUTION
  BallState next;
  next.position = state.position + h * state.velocity;
  next.velocity = state.velocity + h * acceleration;
  return next;
  // END SOLUTION
  // STUB: return exercises::notImplemented("HELLO-1", state, acceleration, h);
}

BounceResult bounceOffPlane(const BallState& state, Real radius, Real restitution, const Vec3& planePoint,
                            const Vec3& planeNormal) {
  // BEGIN SOLUTION
  const Real distance = glm::dot(planeNormal, state.position - planePoint);
  const Real normalSpeed = glm::dot(planeNormal, state.velocity);
  if (distance >= radius || normalSpeed >= 0.0) return {state, false};
  const Vec3 normalVelocity = normalSpeed * planeNormal;
  const Vec3 tangentialVelocity = state.velocity - normalVelocity;
  BounceResult out{state, true};
  out.state.velocity = tangentialVelocity - restitution * normalVelocity;
  out.state.position += (radius - distance) * planeNormal;
  return out;
  // END SOLUTION
  // STUB: return exercises::notImplemented("HELLO-2", BounceResult{state, false}, radius, restitution, planePoint, planeNormal);
}

// Start-up probes: tell the lab whether HELLO-1 and HELLO-2 are still stubs.
PBA_EXERCISE_PROBE(eulerStep(BallState{}, Vec3(0.0), 0.01));
PBA_EXERCISE_PROBE(bounceOffPlane(BallState{}, 0.1, 0.5, Vec3(0.0), kUp));

BounceResult stepDrop(const BallDesc& d, const BallState& s, Real h) {
  const BallState moved = eulerStep(s, acceleration(d, s.velocity), h);
  BounceResult r = bounceOffPlane(moved, d.radius, d.restitution, Vec3(0.0, d.groundHeight, 0.0), kUp);
  // Safety net that keeps the scene sane even while HELLO-2 is a stub: never let the ball fall
  // through the ground. It does not bounce, so an unimplemented HELLO-2 is still plain to see.
  const Real floorY = d.groundHeight + d.radius;
  if (r.state.position.y < floorY) {
    r.state.position.y = floorY;
    r.state.velocity.y = std::max(r.state.velocity.y, 0.0);
  }
  return r;
}

Status validate(const SpringDesc& d) {
  for (Status s : {checkRange("mass", d.mass, 1e-6, 1e6), checkRange("stiffness", d.stiffness, 1e-6, 1e7),
                   checkRange("restLength", d.restLength, 1e-4, 1e3), checkRange("damping", d.damping, 0.0, 1e4),
                   checkRange("drag", d.drag, 0.0, 1e4), checkRange("gravity", d.gravity, 0.0, 1e3),
                   checkFinite("anchor", d.anchor)}) {
    if (!s) return s;
  }
  return Status::success();
}

Vec3 springForce(const SpringDesc& d, const BallState& s) {
  const Vec3 delta = s.position - d.anchor;
  const Real length = glm::length(delta);
  if (length <= 0.0) return Vec3(0.0);
  const Vec3 direction = delta / length;
  const Real magnitude = d.stiffness * (length - d.restLength) + d.damping * glm::dot(direction, s.velocity);
  return -magnitude * direction;
}

Vec3 springBallForce(const SpringDesc& d, const BallState& s) {
  return springForce(d, s) + Vec3(0.0, -d.mass * d.gravity, 0.0) - d.drag * s.velocity;
}

BallState symplecticEulerStep(const SpringDesc& d, const BallState& s, Real h) {
  BallState next;
  next.velocity = s.velocity + (h / d.mass) * springBallForce(d, s);
  next.position = s.position + h * next.velocity;
  return next;
}

Real springExtension(const SpringDesc& d, const BallState& s) { return glm::length(s.position - d.anchor) - d.restLength; }

Real springEnergy(const SpringDesc& d, const BallState& s) {
  const Real e = springExtension(d, s);
  return 0.5 * d.mass * glm::dot(s.velocity, s.velocity) + 0.5 * d.stiffness * e * e +
         d.mass * d.gravity * (s.position.y - d.anchor.y);
}

BallState springEquilibrium(const SpringDesc& d) {
  // k (l − L) = m g  ⇒  l = L + m g / k, straight below the anchor.
  const Real length = d.restLength + d.mass * d.gravity / d.stiffness;
  return BallState{d.anchor - Vec3(0.0, length, 0.0), Vec3(0.0)};
}

}  // namespace pba::hello
