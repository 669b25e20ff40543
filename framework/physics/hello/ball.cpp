#include "physics/hello/ball.h"

#include <algorithm>
#include <cmath>

#include "physics/core/validate.h"
#include "physics/exercises/not_implemented.h"
#include "physics/particles/collision.h"

namespace pba::hello {

Status validate(const BallDesc& d) {
  for (Status s :
       {checkRange("mass", d.mass, 1e-6, 1e6), checkRange("radius", d.radius, 1e-4, 100.0),
        checkRange("restitution", d.restitution, 0.0, 1.0), checkRange("drag", d.drag, 0.0, 1e4),
        checkRange("gravity", d.gravity, 0.0, 1e3), checkRange("dropHeight", d.dropHeight, 0.0, 1e4),
        checkRange("groundHeight", d.groundHeight, -1e4, 1e4), checkRange("restingSpeed", d.restingSpeed, 0.0, 1e3)}) {
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

BounceResult groundContact(const BallDesc& d, const BallState& moved, Real h) {
  const Vec3 groundPoint(0.0, d.groundHeight, 0.0);
  const Real phi = heightAboveGround(d, moved);  // the ball's lowest point above the ground [m]
  BounceResult r{moved, false};
  const Real normalSpeed = moved.velocity.y;  // N·v, N = ŷ
  if (phi < particles::kContactSlop && normalSpeed < 0.0) {
    // Steps 3–4 of the particles lab's contact model, under the inward acceleration g.
    const particles::ContactApproach approach =
        particles::classifyApproach(std::max(0.0, -phi), -normalSpeed, d.gravity, d.restingSpeed, h);
    BallState atContact = moved;
    if (approach.kind == particles::ContactKind::Impact) {
      atContact.velocity.y = -approach.contactSpeed;  // the normal velocity at the contact time
      r = bounceOffPlane(atContact, d.radius, d.restitution, groundPoint, kUp);
    } else {
      r = bounceOffPlane(atContact, d.radius, 0.0, groundPoint, kUp);
      r.bounced = false;  // resting contact is not a bounce
    }
  }
  // Safety net (a no-op after a correct HELLO-2 except at exact touching, which HELLO-2's strict contact
  // test leaves alone): never below the ground, never moving into it while touching it.
  const Real floorY = d.groundHeight + d.radius;
  if (r.state.position.y < floorY) r.state.position.y = floorY;
  if (r.state.position.y - floorY < particles::kContactSlop) r.state.velocity.y = std::max(r.state.velocity.y, 0.0);
  return r;
}

BounceResult stepDrop(const BallDesc& d, const BallState& s, Real h) {
  return groundContact(d, eulerStep(s, acceleration(d, s.velocity), h), h);
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

Vec3 springBallForce(const SpringDesc& d, const BallState& s) {
  // BEGIN SOLUTION
  constexpr Real kMinSpringLength = 1e-12;  // [m] a shorter spring has no direction
  const Vec3 weight(0.0, -d.mass * d.gravity, 0.0);
  const Vec3 drag = -d.drag * s.velocity;
  const Vec3 fromAnchor = s.position - d.anchor;
  const Real length = glm::length(fromAnchor);
  if (length < kMinSpringLength) return weight + drag;
  const Vec3 axis = fromAnchor / length;
  const Real tension = d.stiffness * (length - d.restLength) + d.damping * glm::dot(axis, s.velocity);
  return weight + drag - tension * axis;
  // END SOLUTION
  // STUB: return exercises::notImplemented("HELLO-3", Vec3(0.0), d, s);
}

BallState stepSpringBall(const SpringDesc& d, const BallState& state, Real dt, const SpringBallForce& force) {
  // BEGIN SOLUTION
  const Real omega = std::sqrt(d.stiffness / d.mass);      // [rad/s] natural angular frequency
  const Real dampingRate = (d.damping + d.drag) / d.mass;  // [1/s]
  const Real fastest = std::max(omega, dampingRate);
  const Real needed = std::ceil(fastest * dt / kMaxRateTimesSubstep);
  const int substeps = static_cast<int>(std::clamp(needed, 1.0, static_cast<Real>(kMaxSpringSubsteps)));
  const Real h = dt / substeps;
  BallState s = state;
  for (int i = 0; i < substeps; ++i) {
    const Vec3 acceleration = force(s) / d.mass;
    s.velocity += h * acceleration;  // velocity first ...
    s.position += h * s.velocity;    // ... then the position with the new velocity
  }
  return s;
  // END SOLUTION
  // STUB: return exercises::notImplemented("HELLO-4", state, d, dt, force);
}

Real springExtension(const SpringDesc& d, const BallState& s) {
  return glm::length(s.position - d.anchor) - d.restLength;
}

Real springEnergy(const SpringDesc& d, const BallState& s) {
  // BEGIN SOLUTION
  const Real stretch = springExtension(d, s);
  const Real kinetic = 0.5 * d.mass * glm::dot(s.velocity, s.velocity);
  const Real elastic = 0.5 * d.stiffness * stretch * stretch;
  const Real gravitational = d.mass * d.gravity * (s.position.y - d.anchor.y);
  return kinetic + elastic + gravitational;
  // END SOLUTION
  // STUB: return exercises::notImplemented("HELLO-5", Real(0.0), d, s);
}

// Start-up probes: tell the lab whether HELLO-3, HELLO-4 and HELLO-5 are still stubs.
PBA_EXERCISE_PROBE(springBallForce(SpringDesc{}, BallState{}));
PBA_EXERCISE_PROBE(stepSpringBall(SpringDesc{}, BallState{}, 0.01, [](const BallState&) { return Vec3(0.0); }));
PBA_EXERCISE_PROBE(springEnergy(SpringDesc{}, BallState{}));

BallState springEquilibrium(const SpringDesc& d) {
  // k (l − L) = m g  ⇒  l = L + m g / k, straight below the anchor.
  const Real length = d.restLength + d.mass * d.gravity / d.stiffness;
  return BallState{d.anchor - Vec3(0.0, length, 0.0), Vec3(0.0)};
}

}  // namespace pba::hello
