// Debug drawing of the particle ragdoll: boxes in their fitted frames, particles and sticks, joint
// points, hinge axes with their limit arcs, cones of the ball limits, contacts.
#include "physics/ragdoll/particle_ragdoll.h"

namespace pba::ragdoll {

void ParticleRagdoll::draw(DebugDraw& d, const ParticleDrawOptions& o, const Color& color) const {
  if (o.boxes)
    for (int b = 0; b < boneCount(); ++b) {
      const collision::Transform t = boneFrame(b);
      d.box(t.position, bones_[b].halfExtents, t.rotation, bones_[b].fixed ? colors::kGrey : color);
    }
  if (o.particles) {
    for (const Stick& s : sticks_) d.line(x_[s.a], x_[s.b], colors::kDark);
    for (const Vec3& p : x_) d.point(p, 5.0f, colors::kDark);
  }
  if (o.joints)
    for (const Joint& j : joints_) {
      for (const PointPair& p : j.points) d.point(pointOf(j.a, p.inA), 7.0f, colors::kYellow);
      const Real reach = glm::length(pointOf(j.a, j.axisEnd) - pointOf(j.a, j.origin));
      if (j.kind == JointKind::Hinge) {
        const auto [f, ref] = hingeMeasure(j);
        d.line(f.origin - 0.8 * reach * f.axis, f.origin + 0.8 * reach * f.axis, colors::kOrange);
        if (j.limited) {
          const Vec3 from = std::cos(j.lower) * f.zero + std::sin(j.lower) * glm::cross(f.axis, f.zero);
          d.arc(f.origin, f.axis, from, j.upper - j.lower, 0.6 * reach, colors::kOrange);
          d.line(f.origin, f.origin + 0.6 * reach * from, colors::kOrange);
          const Vec3 to = std::cos(j.upper) * f.zero + std::sin(j.upper) * glm::cross(f.axis, f.zero);
          d.line(f.origin, f.origin + 0.6 * reach * to, colors::kOrange);
        }
      } else if (j.limited) {
        const Vec3 apex = pointOf(j.a, j.origin);
        d.cone(apex, glm::normalize(pointOf(j.a, j.axisEnd) - apex), std::min(j.cone, 0.5 * kPi), 0.6 * reach,
               colors::kOrange);
      }
    }
  if (o.contacts)
    for (const Contact& c : contacts_) {
      d.point(c.point, 8.0f, colors::kRed);
      d.arrow(c.point, c.point + 0.15 * c.normal, colors::kYellow);
    }
}

}  // namespace pba::ragdoll
