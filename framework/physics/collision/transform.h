#pragma once
// A rigid transform x ↦ R x + p (rotation as a unit quaternion), the pose of a shape or a body.
#include "physics/core/types.h"

namespace pba::collision {

struct Transform {
  Vec3 position{0.0};         ///< [m] world position of the local origin
  Quat rotation{1, 0, 0, 0};  ///< unit quaternion, local → world

  Vec3 apply(const Vec3& local) const { return rotation * local + position; }
  Vec3 applyInverse(const Vec3& world) const { return glm::conjugate(rotation) * (world - position); }
  Vec3 rotate(const Vec3& localDirection) const { return rotation * localDirection; }
  Vec3 rotateInverse(const Vec3& worldDirection) const { return glm::conjugate(rotation) * worldDirection; }
};

/// a ∘ b: first b, then a.
inline Transform compose(const Transform& a, const Transform& b) {
  return {a.apply(b.position), a.rotation * b.rotation};
}
/// The transform of b's frame seen from a's frame: a⁻¹ ∘ b.
inline Transform relative(const Transform& a, const Transform& b) {
  const Quat ia = glm::conjugate(a.rotation);
  return {ia * (b.position - a.position), ia * b.rotation};
}

}  // namespace pba::collision
