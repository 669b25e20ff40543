// World queries and presentation: ray casts, the mouse drag, statistics, the non-finite check and
// debug drawing.
#include <algorithm>
#include <cmath>

#include "physics/collision/shape_draw.h"
#include "physics/core/format.h"
#include "physics/rigid/world.h"

namespace pba::rigid {

std::optional<WorldRayHit> World::rayCast(const Ray& ray, Real maxT, bool dynamicOnly) const {
  std::optional<WorldRayHit> best;
  broadPhase_.rayCast(ray.origin, ray.direction, maxT, [&](int i, Real currentMax) {
    if (dynamicOnly && !bodies_[i].isDynamic()) return currentMax;
    const std::optional<collision::RayHit> h = collision::rayCast(bodies_[i].shape, bodies_[i].pose(), ray, currentMax);
    if (!h) return currentMax;
    best = WorldRayHit{i, *h};
    return h->t;
  });
  return best;
}

std::vector<WorldRayHit> World::rayCastAll(const Ray& ray, Real maxT) const {
  std::vector<WorldRayHit> hits;
  broadPhase_.rayCast(ray.origin, ray.direction, maxT, [&](int i, Real currentMax) {
    if (const std::optional<collision::RayHit> h = collision::rayCast(bodies_[i].shape, bodies_[i].pose(), ray, maxT))
      hits.push_back({i, *h});
    return currentMax;
  });
  std::sort(hits.begin(), hits.end(), [](const WorldRayHit& a, const WorldRayHit& b) { return a.hit.t < b.hit.t; });
  return hits;
}

void World::beginDrag(int i, const Vec3& worldPoint) {
  if (i < 0 || i >= bodyCount() || !bodies_[i].isDynamic()) return;
  endDrag();
  wake(i);
  loadSolverBodies();
  Joint j;
  j.desc.kind = JointKind::Mouse;
  j.desc.bodyA = -1;
  j.desc.bodyB = i;
  j.desc.anchor = worldPoint;
  j.desc.hertz = 5.0;
  j.desc.dampingRatio = 0.7;
  // Box2D's samples: a thousand times the body's weight, so the body follows but cannot break the world.
  j.desc.maxForce = 1000.0 * bodies_[i].mass * std::max(glm::length(settings_.gravity), 1.0);
  if (initJoint(j, solverBodies_, "drag")) {
    mouse_ = j;
    drag_ = i;
  }
}

void World::dragTo(const Vec3& target) {
  if (!mouse_) return;
  mouse_->target = target;
  wake(drag_);
}

void World::endDrag() {
  mouse_.reset();
  drag_ = -1;
}

WorldStats World::stats() const {
  WorldStats s;
  s.bodies = bodyCount();
  for (const Body& b : bodies_) {
    if (!b.isDynamic()) continue;
    ++s.dynamicBodies;
    if (b.sleeping) ++s.sleeping;
    s.kineticEnergy += kineticEnergy(b);
    s.potentialEnergy -= b.mass * b.gravityScale * glm::dot(settings_.gravity, b.position);
    s.momentum += b.mass * b.linearVelocity;
    s.angularMomentum += glm::cross(b.position, b.mass * b.linearVelocity) + angularMomentum(b);
  }
  for (const ContactConstraint& c : contacts_) {
    if (c.manifold.count == 0) continue;
    ++s.manifolds;
    for (int i = 0; i < c.manifold.count; ++i) {
      const Real sep = c.manifold.points[i].separation;
      if (sep < settings_.linearSlop) ++s.contacts;
      s.maxPenetration = std::max(s.maxPenetration, -sep);
    }
  }
  s.maxJointError = maxJointError_;
  s.solverIterations = std::max(1, settings_.substeps) * (settings_.iterations + settings_.relaxIterations);
  s.ccdHits = ccdHits_;
  return s;
}

std::optional<std::string> World::nonFiniteState() const {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const Body& b = bodies_[i];
    const std::string who = "body " + (b.name.empty() ? std::to_string(i) : "'" + b.name + "'");
    if (!isFinite(b.position)) return who + " position is not finite";
    if (!isFinite(b.linearVelocity)) return who + " velocity is not finite";
    if (!isFinite(b.angularVelocity)) return who + " angular velocity is not finite";
    if (!std::isfinite(b.orientation.w) || !isFinite(Vec3(b.orientation.x, b.orientation.y, b.orientation.z)))
      return who + " orientation is not finite";
  }
  return std::nullopt;
}

namespace {

Color greyed(const Color& c) { return {0.5f * c.r + 0.35f, 0.5f * c.g + 0.35f, 0.5f * c.b + 0.35f, c.a}; }

// Hull triangles gathered per colour, so that a pile of hundreds of hulls is a handful of draw calls.
struct HullBatch {
  Color color;
  collision::TriangleBatch triangles;
};

void addHull(std::vector<HullBatch>& batches, const collision::ConvexHull& h, const collision::Transform& pose,
             const Color& color) {
  auto same = [&](const HullBatch& b) {
    return b.color.r == color.r && b.color.g == color.g && b.color.b == color.b && b.color.a == color.a;
  };
  auto it = std::find_if(batches.begin(), batches.end(), same);
  if (it == batches.end()) it = batches.insert(batches.end(), HullBatch{color, {}});
  collision::appendHullTriangles(it->triangles, h, pose);
}

void drawAabb(DebugDraw& d, const collision::Aabb& b, const Color& c) {
  const Vec3 lo = b.min, hi = b.max;
  for (int k = 0; k < 4; ++k) {
    const Real x0 = (k & 1) ? hi.x : lo.x, z0 = (k & 2) ? hi.z : lo.z;
    d.line({x0, lo.y, z0}, {x0, hi.y, z0}, c);
  }
  for (Real y : {lo.y, hi.y}) {
    d.line({lo.x, y, lo.z}, {hi.x, y, lo.z}, c);
    d.line({hi.x, y, lo.z}, {hi.x, y, hi.z}, c);
    d.line({hi.x, y, hi.z}, {lo.x, y, hi.z}, c);
    d.line({lo.x, y, hi.z}, {lo.x, y, lo.z}, c);
  }
}

}  // namespace

void World::draw(DebugDraw& d, const WorldDrawOptions& o) const {
  if (o.shapes) {
    std::vector<HullBatch> hulls;
    for (const Body& b : bodies_) {
      const Color color = o.greySleeping && b.sleeping ? greyed(b.color) : b.color;
      const collision::Transform pose = b.pose();
      if (b.shape.kind == collision::ShapeKind::Hull)
        addHull(hulls, *b.shape.hull, pose, color);
      else
        collision::drawShape(d, b.shape, pose, color);
      if (o.frames && b.isDynamic())
        d.frame(b.position, b.orientation, 0.5 * std::max(collision::boundingRadius(b.shape), 0.1));
    }
    for (const HullBatch& h : hulls)
      d.triangles(h.triangles.positions, h.triangles.normals, h.triangles.indices, h.color);
  }
  if (o.contacts || o.impulses) {
    for (const ContactConstraint& c : contacts_) {
      for (int i = 0; i < c.manifold.count; ++i) {
        const collision::ManifoldPoint& p = c.manifold.points[i];
        const bool touching = p.separation < settings_.linearSlop;
        // Normals and impulses as lines: a pile has thousands of contacts, and arrows are meshes.
        if (o.contacts) {
          d.point(p.point, touching ? 7.0f : 4.0f, touching ? colors::kRed : colors::kGrey);
          if (touching) d.line(p.point, p.point + o.normalLength * c.manifold.normal, colors::kYellow);
        }
        if (o.impulses && i < c.count && c.points[i].normalImpulse > 0.0)
          d.line(p.point, p.point + o.impulseScale * c.points[i].normalImpulse * c.manifold.normal, colors::kOrange);
      }
    }
  }
  if (o.aabbTree) {
    broadPhase_.tree().forEachNode([&](const collision::Aabb& box, int height, bool leaf) {
      if (box.max.x - box.min.x > 1e5) return;  // planes
      drawAabb(d, box, leaf ? colors::kTeal : (height % 2 ? colors::kPurple : colors::kBlue));
    });
  }
  if (o.joints) {
    for (const Joint& j : joints_) {
      const int a = j.desc.bodyA;
      const Body& B = bodies_[j.desc.bodyB];
      const Vec3 pb = B.position + B.orientation * j.localB;
      const Vec3 pa = a < 0 ? j.target : bodies_[a].position + bodies_[a].orientation * j.localA;
      if (a >= 0) d.line(bodies_[a].position, pa, colors::kPurple);
      d.line(B.position, pb, colors::kPurple);
      d.point(pa, 6.0f, colors::kPurple);
      const Quat qa = a < 0 ? Quat(1, 0, 0, 0) : bodies_[a].orientation;
      const Vec3 axis = qa * j.axisA;
      switch (j.desc.kind) {
        case JointKind::Hinge:
          d.line(pa - 0.2 * axis, pa + 0.2 * axis, colors::kTeal);
          if (j.desc.enableLimit) {
            Vec3 t1, t2;
            tangentBasis(axis, t1, t2);
            d.arc(pa, axis, t1, j.desc.upper - j.desc.lower, 0.15, colors::kOrange);
          }
          break;
        case JointKind::ConeTwist:
          d.cone(pa, axis, j.desc.swingSpan, 0.25, colors::kOrange);
          break;
        case JointKind::Slider:
          d.line(pa + j.desc.lower * axis, pa + j.desc.upper * axis, colors::kTeal);
          break;
        case JointKind::Distance:
          d.line(pa, pb, j.desc.hertz > 0.0 ? colors::kGreen : colors::kDark);
          break;
        default:
          break;
      }
    }
    if (mouse_) {
      const Body& B = bodies_[drag_];
      const Vec3 pb = B.position + B.orientation * mouse_->localB;
      d.line(pb, mouse_->target, colors::kGreen);
      d.point(mouse_->target, 8.0f, colors::kGreen);
    }
  }
}

}  // namespace pba::rigid
