#include "physics/ragdoll/ragdoll_desc.h"

#include "physics/core/enum_names.h"

#include <cmath>

#include "physics/core/validate.h"

namespace pba::ragdoll {

namespace {
constexpr auto kJointKindNames = enumNames<JointKind>({{JointKind::Ball, "ball"}, {JointKind::Hinge, "hinge"}});
}  // namespace

const char* jointKindName(JointKind kind) { return kJointKindNames.name(kind).data(); }

namespace {

Status validateBone(const BoneDesc& b, const std::string& field) {
  if (Status s = checkFinite(field + ".center", b.center); !s) return s;
  if (Status s = checkFinite(field + ".velocity", b.velocity); !s) return s;
  if (Status s = checkFinite(field + ".angularVelocity", b.angularVelocity); !s) return s;
  if (!(b.halfExtents.x > 0.0 && b.halfExtents.y > 0.0 && b.halfExtents.z > 0.0) || !isFinite(b.halfExtents))
    return Error{field + ".halfExtents: must be positive and finite"};
  if (!b.fixed && !(b.mass > 0.0 && std::isfinite(b.mass))) return Error{field + ".mass: must be positive and finite"};
  const Real q = std::sqrt(b.orientation.w * b.orientation.w + b.orientation.x * b.orientation.x +
                           b.orientation.y * b.orientation.y + b.orientation.z * b.orientation.z);
  if (!(std::abs(q - 1.0) < 1e-6)) return Error{field + ".orientation: must be a unit quaternion"};
  return Status::success();
}

Status validateJoint(const JointDesc& j, int bones, const std::string& field) {
  if (j.boneA < 0 || j.boneA >= bones) return Error{field + ".boneA: no bone " + std::to_string(j.boneA)};
  if (j.boneB < 0 || j.boneB >= bones) return Error{field + ".boneB: no bone " + std::to_string(j.boneB)};
  if (j.boneA == j.boneB) return Error{field + ".boneB: must differ from boneA"};
  if (Status s = checkFinite(field + ".anchor", j.anchor); !s) return s;
  if (Status s = checkFinite(field + ".axis", j.axis); !s) return s;
  if (!(glm::length(j.axis) > 1e-9)) return Error{field + ".axis: must not be zero"};
  if (j.limited && j.kind == JointKind::Hinge) {
    if (!(j.lower <= 0.0) || !std::isfinite(j.lower))
      return Error{field + ".lower: must be <= 0 (the start is angle 0)"};
    if (!(j.upper >= 0.0) || !std::isfinite(j.upper))
      return Error{field + ".upper: must be >= 0 (the start is angle 0)"};
    if (!(j.upper - j.lower < 2.0 * kPi)) return Error{field + ".upper: the range must be below 360 degrees"};
  }
  if (j.limited && j.kind == JointKind::Ball && !(j.coneAngle >= 0.0 && j.coneAngle < kPi))
    return Error{field + ".coneAngle: must be in [0, 180) degrees"};
  return Status::success();
}

}  // namespace

Status validate(const RagdollDesc& desc, const std::string& field) {
  if (desc.bones.empty()) return Error{field + ".bones: must not be empty"};
  for (std::size_t i = 0; i < desc.bones.size(); ++i) {
    const std::string name = desc.bones[i].name.empty() ? std::to_string(i) : desc.bones[i].name;
    if (Status s = validateBone(desc.bones[i], field + ".bones[" + name + "]"); !s) return s;
  }
  for (std::size_t i = 0; i < desc.joints.size(); ++i)
    if (Status s = validateJoint(desc.joints[i], static_cast<int>(desc.bones.size()),
                                 field + ".joints[" + std::to_string(i) + "]");
        !s)
      return s;
  if (!(desc.friction >= 0.0)) return Error{field + ".friction: must be >= 0"};
  return Status::success();
}

RagdollDesc translated(RagdollDesc desc, const Vec3& offset) {
  for (BoneDesc& b : desc.bones) b.center += offset;
  for (JointDesc& j : desc.joints) j.anchor += offset;
  return desc;
}

void append(RagdollDesc& desc, const RagdollDesc& other) {
  const int base = static_cast<int>(desc.bones.size());
  desc.bones.insert(desc.bones.end(), other.bones.begin(), other.bones.end());
  for (JointDesc j : other.joints) {
    j.boneA += base, j.boneB += base;
    desc.joints.push_back(j);
  }
}

Real totalMass(const RagdollDesc& desc) {
  Real m = 0.0;
  for (const BoneDesc& b : desc.bones)
    if (!b.fixed) m += b.mass;
  return m;
}

}  // namespace pba::ragdoll
