// Joint set-up, warm starting and the measurements shared by every joint type.
#include <cmath>

#include "physics/core/validate.h"

#include "physics/core/enum_names.h"
#include "physics/rigid/contact_solver.h"
#include "physics/rigid/joint.h"
#include "physics/rigid/joint_rows.h"

namespace pba::rigid {

namespace {
constexpr auto kJointKindNames = enumNames<JointKind>({{JointKind::Ball, "ball"},
                                                       {JointKind::Hinge, "hinge"},
                                                       {JointKind::ConeTwist, "cone-twist"},
                                                       {JointKind::Fixed, "fixed"},
                                                       {JointKind::Slider, "slider"},
                                                       {JointKind::Distance, "distance"},
                                                       {JointKind::Mouse, "mouse"}});
}  // namespace

const char* jointKindName(JointKind kind) { return kJointKindNames.name(kind).data(); }

Status initJoint(Joint& j, const std::vector<SolverBody>& bodies, const std::string& field) {
  const JointDesc& d = j.desc;
  const int n = static_cast<int>(bodies.size()) - 1;  // the last solver body is the world
  if (d.bodyA < -1 || d.bodyA >= n) return Error{field + ".bodyA: no body " + std::to_string(d.bodyA)};
  if (d.bodyB < 0 || d.bodyB >= n) return Error{field + ".bodyB: no body " + std::to_string(d.bodyB)};
  if (d.bodyA == d.bodyB) return Error{field + ".bodyB: must differ from bodyA"};
  if (Status s = checkFinite(field + ".anchor", d.anchor); !s) return s;
  if (Status s = checkFinite(field + ".axis", d.axis); !s) return s;
  const Real axisLength = glm::length(d.axis);
  if (!(axisLength > 1e-9)) return Error{field + ".axis: must not be zero"};
  if (d.enableLimit && !(d.lower <= d.upper)) return Error{field + ".lower: must be <= upper"};
  if (!(d.swingSpan >= 0.0)) return Error{field + ".swingSpan: must be >= 0"};
  if (d.hertz < 0.0 || d.dampingRatio < 0.0) return Error{field + ".hertz: spring settings must be >= 0"};
  j.a = d.bodyA < 0 ? n : d.bodyA;
  j.b = d.bodyB;
  const SolverBody& A = bodies[j.a];
  const SolverBody& B = bodies[j.b];
  const Vec3 axis = d.axis / axisLength;
  j.localA = glm::conjugate(A.q) * (d.anchor - A.c);
  const Vec3 anchorB = d.kind == JointKind::Distance ? d.anchorB : d.anchor;
  j.localB = glm::conjugate(B.q) * (anchorB - B.c);
  j.axisA = glm::conjugate(A.q) * axis;
  j.axisB = glm::conjugate(B.q) * axis;
  j.relative0 = glm::conjugate(A.q) * B.q;
  j.target = anchorB;
  if (d.kind == JointKind::Distance) {
    j.restLength = d.length >= 0.0 ? d.length : glm::length(anchorB - d.anchor);
    if (!(j.restLength >= 0.0) || !(d.minLength <= d.maxLength))
      return Error{field + ".length: invalid length or limits"};
  }
  return Status::success();
}

void warmStartJoint(const Joint& j, std::vector<SolverBody>& bodies) {
  SolverBody& A = bodies[j.a];
  SolverBody& B = bodies[j.b];
  // Linear impulse at the anchors: the point rows, and for the distance joint its axis rows.
  Vec3 linear = j.pointImpulse;
  Vec3 angular = j.angularImpulse;
  const Vec3& u = j.axisWorld;
  switch (j.desc.kind) {
    case JointKind::Hinge:
      angular = j.angularImpulse.x * j.hingeBasis[0] + j.angularImpulse.y * j.hingeBasis[1] +
                (j.motorImpulse + j.lowerImpulse - j.upperImpulse) * u;
      break;
    case JointKind::ConeTwist:
      angular = (j.lowerImpulse - j.upperImpulse) * u - j.swingImpulse * j.hingeBasis[0];
      break;
    case JointKind::Slider:
      linear = j.pointImpulse + (j.motorImpulse + j.lowerImpulse - j.upperImpulse) * u;
      break;
    case JointKind::Distance:
      linear = (j.springImpulse + j.lowerImpulse - j.upperImpulse) * u;
      angular = Vec3(0.0);
      break;
    case JointKind::Ball:
    case JointKind::Mouse:
      angular = Vec3(0.0);
      break;
    case JointKind::Fixed:
      break;
  }
  // A slider's linear rows act on A at the arm r_A + d (see joint_slider below); the others at r_A.
  const Vec3 armA = j.desc.kind == JointKind::Slider ? detail::anchorB(j, B) - A.c : j.rA;
  applyImpulse(A, armA, linear, -1.0);
  applyImpulse(B, j.rB, linear, 1.0);
  applyAngularImpulse(A, angular, -1.0);
  applyAngularImpulse(B, angular, 1.0);
}

Real jointPositionError(const Joint& j, const std::vector<SolverBody>& bodies) {
  const SolverBody& A = bodies[j.a];
  const SolverBody& B = bodies[j.b];
  const Vec3 d = detail::anchorB(j, B) - detail::anchorA(j, A);
  switch (j.desc.kind) {
    case JointKind::Distance: {
      const Real l = glm::length(d);
      if (j.desc.hertz > 0.0) return 0.0;  // a spring has no error, only a stretch
      return std::abs(l - j.restLength);
    }
    case JointKind::Slider: {
      const Vec3 u = A.q * j.axisA;
      return glm::length(d - glm::dot(d, u) * u);
    }
    case JointKind::Mouse:
      return 0.0;
    default:
      return glm::length(d);
  }
}

Real jointCoordinate(const Joint& j, const std::vector<SolverBody>& bodies) {
  const SolverBody& A = bodies[j.a];
  const SolverBody& B = bodies[j.b];
  if (j.desc.kind == JointKind::Slider) return glm::dot(detail::anchorB(j, B) - detail::anchorA(j, A), A.q * j.axisA);
  return detail::twistAngle(j, A, B);
}

Real jointSwingAngle(const Joint& j, const std::vector<SolverBody>& bodies) {
  const Vec3 a = bodies[j.a].q * j.axisA, b = bodies[j.b].q * j.axisB;
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace pba::rigid
