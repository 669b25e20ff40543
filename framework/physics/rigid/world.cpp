// World: bodies, joints and the solver stages of one step (see world.h for the order).
#include "physics/rigid/world.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "physics/rigid/exercises.h"
#include "physics/rigid/integrate.h"

namespace pba::rigid {

World::World(const WorldSettings& settings)
    : settings_(settings), broadPhase_(settings.broadPhase, settings.aabbMargin) {}

namespace {
collision::Aabb bodyAabb(const Body& b, Real speculative) {
  const collision::Aabb box = collision::computeAabb(b.shape, b.pose());
  return b.shape.kind == collision::ShapeKind::Plane ? box : box.fattened(speculative);
}
}  // namespace

Result<int> World::addBody(const BodyDesc& desc, const std::string& field) {
  Result<Body> made = makeBody(desc, field);
  if (!made) return Error{made.error()};
  Body b = std::move(made).value();
  const int index = static_cast<int>(bodies_.size());
  b.proxy = broadPhase_.add(bodyAabb(b, settings_.speculativeDistance), index, b.type == BodyType::Static);
  bodies_.push_back(std::move(b));
  return index;
}

Result<int> World::addJoint(const JointDesc& desc, const std::string& field) {
  // initJoint reads the joint's two bodies (and checks the indices against the count): loading only them
  // keeps building a world of n jointed bodies O(n), where loading every body for each joint made 136
  // ragdolls' 2,040 joints cost 4.4 million inertia rotations.
  fitSolverBodies();
  for (const int side : {desc.bodyA, desc.bodyB})
    if (side >= 0 && side < bodyCount()) loadSolverBody(static_cast<std::size_t>(side));
  Joint j;
  j.desc = desc;
  if (Status s = initJoint(j, solverBodies_, field); !s) return Error{s.error()};
  joints_.push_back(j);
  if (desc.bodyA >= 0) wake(desc.bodyA);
  wake(desc.bodyB);
  return static_cast<int>(joints_.size()) - 1;
}

void World::wake(int i) {
  if (i < 0 || i >= bodyCount()) return;
  bodies_[i].sleeping = false;
  bodies_[i].sleepTime = 0.0;
}

void World::setVelocity(int i, const Vec3& linear, const Vec3& angular) {
  bodies_[i].linearVelocity = linear;
  bodies_[i].angularVelocity = angular;
  wake(i);
}

void World::rebuildBroadPhase() {
  broadPhase_ = collision::BroadPhase(settings_.broadPhase, settings_.aabbMargin);
  for (std::size_t i = 0; i < bodies_.size(); ++i)
    bodies_[i].proxy = broadPhase_.add(bodyAabb(bodies_[i], settings_.speculativeDistance), static_cast<int>(i),
                                       bodies_[i].type == BodyType::Static);
}

void World::updateBroadPhase() {
  if (broadPhase_.kind() != settings_.broadPhase) rebuildBroadPhase();
  for (const Body& b : bodies_)
    if (b.type != BodyType::Static && !b.sleeping)
      broadPhase_.move(b.proxy, bodyAabb(b, settings_.speculativeDistance));
}

void World::placeDragged() {
  if (!mouse_ || drag_ < 0) return;
  Body& b = bodies_[drag_];
  b.position += mouse_->target - (b.position + b.orientation * mouse_->localB);
  b.linearVelocity = Vec3(0.0);
  b.angularVelocity = Vec3(0.0);
  broadPhase_.move(b.proxy, bodyAabb(b, settings_.speculativeDistance));
}

void World::fitSolverBodies() {
  const std::size_t n = bodies_.size();
  solverBodies_.resize(n + 1);
  solverBodies_[n] = SolverBody{};  // the world
  awake_.resize(n);
}

void World::loadSolverBody(std::size_t i) {
  const Body& b = bodies_[i];
  SolverBody& s = solverBodies_[i];
  s = SolverBody{};
  awake_[i] = 0;
  s.c = b.position;
  s.q = b.orientation;
  if (b.type == BodyType::Kinematic) {
    s.v = b.linearVelocity;
    s.w = b.angularVelocity;
  } else if (b.isDynamic() && !b.sleeping) {
    awake_[i] = 1;
    s.v = b.linearVelocity;
    s.w = b.angularVelocity;
    s.invMass = b.inverseMass;
    s.invI = worldInverseInertia(b.orientation, b.inverseInertiaBody);
  }
}

void World::loadSolverBodies() {
  fitSolverBodies();
  for (std::size_t i = 0; i < bodies_.size(); ++i) loadSolverBody(i);
}

void World::step(Real dt) {
  if (!(dt > 0.0)) return;
  updateBroadPhase();
  collide();
  updateIslandsAndSleep();
  solve(dt);
  solveContinuous(dt);
  updateSleepTimers(dt);
  time_ += dt;
}

void World::solve(Real dt) {
  loadSolverBodies();
  const int n = static_cast<int>(bodies_.size());
  const WorldSettings& s = settings_;
  const int substeps = std::max(1, s.substeps);
  const Real h = dt / substeps;
  const Real contactHertz = std::min(s.contactHertz, 0.25 / h);
  ContactSolverStep cstep{&settings_, h, makeSoft(contactHertz, s.contactDampingRatio, h),
                          makeSoft(2.0 * contactHertz, s.contactDampingRatio, h)};
  JointStep jstep{h, makeSoft(2.0 * contactHertz, s.jointDampingRatio, h), s.warmStarting};
  if (s.jointHertz > 0.0) jstep.soft = makeSoft(std::min(s.jointHertz, 0.5 / h), s.jointDampingRatio, h);

  sweeps_.resize(n);
  startVelocity_.resize(n);
  startAngularVelocity_.resize(n);
  for (int i = 0; i < n; ++i) {
    sweeps_[i].c0 = bodies_[i].position, sweeps_[i].q0 = bodies_[i].orientation;
    startVelocity_[i] = bodies_[i].linearVelocity, startAngularVelocity_[i] = bodies_[i].angularVelocity;
  }

  // The solver's copy of each awake manifold (kept between steps: no allocation once warm).
  activeContacts_.clear();
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    const ContactConstraint& c = contacts_[k];
    if (c.manifold.count == 0 || !(awake_[c.bodyA] || awake_[c.bodyB])) continue;
    activeContacts_.push_back(static_cast<int>(k));
  }
  if (solverContacts_.size() < activeContacts_.size()) solverContacts_.resize(activeContacts_.size() * 3 / 2 + 16);
  const std::span<SolverContact> active(solverContacts_.data(), activeContacts_.size());
  for (std::size_t i = 0; i < active.size(); ++i)
    prepareContact(contacts_[activeContacts_[i]], solverBodies_, s.warmStarting, active[i]);
  std::vector<Joint*> joints;
  for (Joint& j : joints_) {
    j.a = bodyOfJointSide(j.desc.bodyA);
    j.b = j.desc.bodyB;
    if ((j.a < n && awake_[j.a]) || awake_[j.b]) {
      prepareJoint(j, solverBodies_, jstep);
      joints.push_back(&j);
    }
  }
  if (mouse_) {
    mouse_->a = n;
    mouse_->b = drag_;
    if (awake_[drag_]) {
      prepareJoint(*mouse_, solverBodies_, jstep);
      joints.push_back(&*mouse_);
    }
  }

  for (int sub = 0; sub < substeps; ++sub) {
    // Integrate velocities: gravity, damping (v ← v / (1 + h c), Box2D), gyroscopic term.
    for (int i = 0; i < n; ++i) {
      if (!awake_[i]) continue;
      const Body& b = bodies_[i];
      SolverBody& sb = solverBodies_[i];
      sb.v = (sb.v + h * b.gravityScale * s.gravity) / (1.0 + h * b.linearDamping);
      sb.w /= (1.0 + h * b.angularDamping);
      // ω × Iω vanishes when I is a multiple of 1 (spheres, cubes): skip the Newton step there.
      if (s.gyroscopic == GyroscopicMode::Implicit && !b.isotropic)
        sb.w = gyroscopicImplicitStep(sb.q, b.inertiaBody, sb.w, h);
    }
    if (s.warmStarting) {
      for (Joint* j : joints) warmStartJoint(*j, solverBodies_);
      for (const SolverContact& c : active) warmStartContact(c, solverBodies_);
    }
    for (int it = 0; it < s.iterations; ++it) {
      for (Joint* j : joints) solveJoint(*j, solverBodies_, jstep, true);
      for (SolverContact& c : active) solveContact(c, solverBodies_, cstep, true);
    }
    // Integrate positions with the new velocities.
    for (int i = 0; i < n; ++i) {
      const bool kinematic = bodies_[i].type == BodyType::Kinematic;
      if (!awake_[i] && !kinematic) continue;
      SolverBody& sb = solverBodies_[i];
      const Real speed = glm::length(sb.v);
      if (speed > s.maxLinearSpeed) sb.v *= s.maxLinearSpeed / speed;
      sb.c += h * sb.v;
      sb.dp += h * sb.v;
      sb.dtheta += h * sb.w;
      if (s.gyroscopic == GyroscopicMode::Midpoint && !kinematic && !bodies_[i].isotropic) {
        midpointFreeRotation(sb.q, sb.w, bodies_[i].inertiaBody, bodies_[i].inverseInertiaBody, h);
      } else {
        sb.q = integrateOrientation(sb.q, sb.w, h);  // RIGID-2
      }
    }
    for (int it = 0; it < s.relaxIterations; ++it) {
      for (Joint* j : joints) solveJoint(*j, solverBodies_, jstep, false);
      for (SolverContact& c : active) solveContact(c, solverBodies_, cstep, false);
    }
  }
  for (int it = 0; it < std::max(1, s.restitutionIterations); ++it)
    for (SolverContact& c : active) applyRestitution(c, solverBodies_, s);
  for (std::size_t i = 0; i < active.size(); ++i) storeImpulses(active[i], contacts_[activeContacts_[i]]);

  maxJointError_ = 0.0;
  for (const Joint& j : joints_) maxJointError_ = std::max(maxJointError_, jointPositionError(j, solverBodies_));
  for (int i = 0; i < n; ++i) {
    Body& b = bodies_[i];
    const SolverBody& sb = solverBodies_[i];
    if (awake_[i] || b.type == BodyType::Kinematic) {
      b.position = sb.c;
      b.orientation = sb.q;
      b.linearVelocity = sb.v;
      b.angularVelocity = sb.w;
    }
    sweeps_[i].c1 = b.position;
    sweeps_[i].q1 = b.orientation;
  }
}

}  // namespace pba::rigid
