#include "physics/rigid/body.h"

#include <cmath>

#include "physics/core/format.h"
#include "physics/core/validate.h"

namespace pba::rigid {

Mat3 worldInverseInertia(const Quat& q, const Mat3& m) {
  const Mat3 axes = glm::mat3_cast(q);  // columns: the body's x, y, z axes in world coordinates
  Mat3 out(0.0);
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) {
      const Real mjk = m[k][j];  // glm is column-major: m[column][row]
      if (mjk == 0.0) continue;
      for (int c = 0; c < 3; ++c) out[c] += mjk * axes[j] * axes[k][c];
    }
  return out;
}

Real kineticEnergy(const Body& b) {
  if (!b.isDynamic()) return 0.0;
  const Vec3 l = angularMomentum(b);
  return 0.5 * b.mass * glm::dot(b.linearVelocity, b.linearVelocity) + 0.5 * glm::dot(b.angularVelocity, l);
}

Vec3 angularMomentum(const Body& b) {
  if (!b.isDynamic()) return Vec3(0.0);
  const Vec3 local = glm::conjugate(b.orientation) * b.angularVelocity;
  return b.orientation * (b.inertiaBody * local);
}

Result<Body> makeBody(const BodyDesc& d, const std::string& field) {
  auto fail = [&](const std::string& what) { return Error{field + "." + what}; };
  if (Status s = checkFinite(field + ".position", d.position); !s) return Error{s.error()};
  if (Status s = checkFinite(field + ".linearVelocity", d.linearVelocity); !s) return Error{s.error()};
  if (Status s = checkFinite(field + ".angularVelocity", d.angularVelocity); !s) return Error{s.error()};
  const Real qn = std::sqrt(glm::dot(d.orientation, d.orientation));
  if (!std::isfinite(qn) || std::abs(qn - 1.0) > 1e-6)
    return fail("orientation: must be a unit quaternion, |q| = " + formatShort(qn));
  if (Status s = checkRange(field + ".friction", d.friction, 0.0, 100.0); !s) return Error{s.error()};
  if (Status s = checkRange(field + ".restitution", d.restitution, 0.0, 1.0); !s) return Error{s.error()};
  if (Status s = checkRange(field + ".linearDamping", d.linearDamping, 0.0, 1e6); !s) return Error{s.error()};
  if (Status s = checkRange(field + ".angularDamping", d.angularDamping, 0.0, 1e6); !s) return Error{s.error()};
  if (!d.shape.isConvex() && d.type != BodyType::Static)
    return fail("type: a " + std::string(collision::shapeKindName(d.shape.kind)) + " can only be static");
  if (d.shape.isConvex() && d.shape.kind != collision::ShapeKind::Sphere && !d.shape.hull &&
      d.shape.kind != collision::ShapeKind::Capsule)
    return fail("shape: not built by a shape constructor");

  Body b;
  b.type = d.type;
  b.shape = d.shape;
  b.position = d.position;
  b.orientation = d.orientation / qn;
  b.friction = d.friction;
  b.restitution = d.restitution;
  b.linearDamping = d.linearDamping;
  b.angularDamping = d.angularDamping;
  b.gravityScale = d.gravityScale;
  b.bullet = d.bullet;
  b.continuous = d.continuous;
  b.allowSleep = d.allowSleep;
  b.color = d.color;
  b.name = d.name;
  if (d.type != BodyType::Dynamic) {
    if (d.type == BodyType::Kinematic) b.linearVelocity = d.linearVelocity, b.angularVelocity = d.angularVelocity;
    return b;
  }
  if (d.mass != 0.0) {
    if (Status s = checkPositive(field + ".mass", d.mass); !s) return Error{s.error()};
  } else if (Status s = checkPositive(field + ".density", d.density); !s) {
    return Error{s.error()};
  }
  collision::MassProperties m = collision::shapeMass(d.shape, d.mass > 0.0 ? 1.0 : d.density);
  if (d.shape.kind == collision::ShapeKind::Hull) {
    // Put the centre of mass at the body origin: move the hull, and the body by the same offset.
    const Vec3 offset = m.centerOfMass;
    b.shape.hull = std::make_shared<const collision::ConvexHull>(collision::translated(*d.shape.hull, -offset));
    b.position = d.position + b.orientation * offset;
  }
  if (d.mass > 0.0) {
    const Real scale = d.mass / m.mass;
    m.mass = d.mass;
    m.inertia *= scale;
  }
  if (!(m.mass > 0.0) || !std::isfinite(m.mass)) return fail("shape: has no volume");
  if (d.inertia != Mat3(0.0)) {
    if (!(glm::determinant(d.inertia) > 0.0) || d.inertia[0][0] <= 0.0 || d.inertia[1][1] <= 0.0 ||
        d.inertia[2][2] <= 0.0)
      return fail("inertia: must be symmetric positive definite");
    m.inertia = d.inertia;
  }
  b.mass = m.mass;
  b.inverseMass = 1.0 / m.mass;
  b.inertiaBody = m.inertia;
  {
    const Mat3& I = m.inertia;
    const Real scale = I[0][0] + I[1][1] + I[2][2];
    const Real off = std::abs(I[0][1]) + std::abs(I[0][2]) + std::abs(I[1][2]);
    b.isotropic = off <= 1e-12 * scale && std::abs(I[0][0] - I[1][1]) <= 1e-12 * scale &&
                  std::abs(I[1][1] - I[2][2]) <= 1e-12 * scale;
  }
  b.inverseInertiaBody = glm::inverse(m.inertia);
  b.inverseInertiaWorld = worldInverseInertia(b.orientation, b.inverseInertiaBody);
  b.linearVelocity = d.linearVelocity;
  b.angularVelocity = d.angularVelocity;
  return b;
}

}  // namespace pba::rigid
