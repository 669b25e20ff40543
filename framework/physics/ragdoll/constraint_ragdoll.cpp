#include "physics/ragdoll/constraint_ragdoll.h"

#include <algorithm>
#include <cmath>

#include "physics/rigid/builders.h"

namespace pba::ragdoll {

rigid::WorldSettings ragdollWorldSettings() {
  rigid::WorldSettings s;
  s.contactHertz = 60.0;         // a quarter of the substep rate (4 substeps at 60 Hz)
  s.jointHertz = 60.0;           // Box2D's value; 120 Hz made legs on a cone limit flail (spider)
  s.speculativeDistance = 0.08;  // [m] a spinning thin limb's corner travels up to ~7 cm per step
  return s;
}

rigid::WorldSettings skeletonRagdollWorldSettings() {
  rigid::WorldSettings s = ragdollWorldSettings();
  s.speculativeDistance = 0.02;  // [m] (see the header)
  return s;
}

rigid::JointDesc rigidJoint(const JointDesc& j, int bodyA, int bodyB) {
  rigid::JointDesc r;
  r.bodyA = bodyA;
  r.bodyB = bodyB;
  r.anchor = j.anchor;
  r.axis = glm::normalize(j.axis);
  if (j.kind == JointKind::Hinge) {
    r.kind = rigid::JointKind::Hinge;
    r.enableLimit = j.limited;
    r.lower = j.lower;
    r.upper = j.upper;
  } else if (j.limited) {
    r.kind = rigid::JointKind::ConeTwist;  // swing limited to the cone, twist free
    r.swingSpan = j.coneAngle;
  } else {
    r.kind = rigid::JointKind::Ball;
  }
  return r;
}

Result<ConstraintRagdoll> ConstraintRagdoll::addTo(rigid::World& world, const RagdollDesc& desc) {
  if (Status s = validate(desc); !s) return Error{s.error()};
  ConstraintRagdoll r;
  for (std::size_t i = 0; i < desc.bones.size(); ++i) {
    const BoneDesc& b = desc.bones[i];
    rigid::BodyDesc body;
    body.type = b.fixed ? rigid::BodyType::Static : rigid::BodyType::Dynamic;
    body.shape = collision::makeBox(b.halfExtents).value();
    body.position = b.center;
    body.orientation = b.orientation;
    if (!b.fixed) {
      body.mass = b.mass;
      body.linearVelocity = b.velocity;
      body.angularVelocity = b.angularVelocity;
    }
    body.friction = desc.friction;
    body.name = b.name.empty() ? "bone " + std::to_string(i) : b.name;
    Result<int> id = world.addBody(body, "ragdoll.bones[" + body.name + "]");
    if (!id) return Error{id.error()};
    r.bodies_.push_back(id.value());
  }
  for (std::size_t k = 0; k < desc.joints.size(); ++k) {
    const JointDesc& j = desc.joints[k];
    Result<int> id = world.addJoint(rigidJoint(j, r.bodies_[j.boneA], r.bodies_[j.boneB]),
                                    "ragdoll.joints[" + std::to_string(k) + "]");
    if (!id) return Error{id.error()};
    r.joints_.push_back(id.value());
  }
  r.desc_ = desc.joints;
  return r;
}

Result<ConstraintRagdoll> ConstraintRagdoll::build(const RagdollDesc& desc, const ConstraintSettings& settings) {
  rigid::World world(settings.world);
  if (settings.ground) rigid::addGround(world, desc.friction);
  Result<ConstraintRagdoll> r = addTo(world, desc);
  if (!r) return r;
  r.value().world_ = std::move(world);
  return r;
}

namespace {
std::vector<rigid::SolverBody> poses(const rigid::World& w) {
  std::vector<rigid::SolverBody> p(w.bodyCount() + 1);
  for (int i = 0; i < w.bodyCount(); ++i) p[i].c = w.body(i).position, p[i].q = w.body(i).orientation;
  return p;
}
}  // namespace

Real ConstraintRagdoll::angleAt(int joint, const std::vector<rigid::SolverBody>& p) const {
  const rigid::Joint& j = world_.joints()[joints_[joint]];
  return desc_[joint].kind == JointKind::Hinge ? rigid::jointCoordinate(j, p) : rigid::jointSwingAngle(j, p);
}

Real ConstraintRagdoll::jointAngle(int joint) const { return angleAt(joint, poses(world_)); }

ConstraintStats ConstraintRagdoll::stats() const {
  const rigid::WorldStats w = world_.stats();
  ConstraintStats s;
  s.bones = boneCount();
  s.constraints = static_cast<int>(joints_.size());
  s.contacts = w.contacts;
  s.sleeping = w.sleeping;
  s.maxJointError = w.maxJointError;
  for (int b : bodies_) {
    const rigid::Body& body = world_.body(b);
    if (!body.isDynamic()) continue;
    s.kineticEnergy += rigid::kineticEnergy(body);
    s.potentialEnergy -= body.mass * glm::dot(world_.settings().gravity, body.position);
    const Vec3& h = body.shape.halfExtents;
    for (int i = 0; i < 8; ++i) {
      const Vec3 corner(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z);
      s.maxPenetration = std::max(s.maxPenetration, -(body.position + body.orientation * corner).y);
    }
  }
  const std::vector<rigid::SolverBody> p = poses(world_);  // once: every joint reads it
  for (std::size_t k = 0; k < desc_.size(); ++k) {
    const JointDesc& j = desc_[k];
    if (!j.limited) continue;
    const Real a = angleAt(static_cast<int>(k), p);
    const Real beyond =
        j.kind == JointKind::Hinge ? std::max({0.0, a - j.upper, j.lower - a}) : std::max(0.0, a - j.coneAngle);
    s.maxLimitViolation = std::max(s.maxLimitViolation, beyond);
  }
  return s;
}

}  // namespace pba::ragdoll

namespace pba::ragdoll {

std::size_t ConstraintRagdoll::memoryBytes() const {
  const auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return sizeof(*this) + bytes(world_.bodies()) + bytes(world_.joints()) + bytes(world_.contacts()) + bytes(bodies_) +
         bytes(joints_) + bytes(desc_);
}

void ConstraintRagdoll::drawJoints(DebugDraw& d) const {
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    const rigid::Joint& j = world_.joints()[joints_[k]];
    const rigid::Body& a = world_.body(j.desc.bodyA);
    const rigid::Body& b = world_.body(j.desc.bodyB);
    const Vec3 anchor = a.position + a.orientation * j.localA;
    d.point(anchor, 7.0f, colors::kYellow);
    const Real reach = 0.8 * std::min(glm::length(a.shape.halfExtents), glm::length(b.shape.halfExtents));
    const Vec3 axis = a.orientation * j.axisA;
    if (desc_[k].kind == JointKind::Hinge) {
      d.line(anchor - 0.5 * reach * axis, anchor + 0.5 * reach * axis, colors::kOrange);
    } else if (desc_[k].limited) {
      d.cone(anchor, axis, std::min(desc_[k].coneAngle, 0.5 * kPi), 0.6 * reach, colors::kOrange);
    }
  }
}

}  // namespace pba::ragdoll
