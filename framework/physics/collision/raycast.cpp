#include "physics/collision/raycast.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/collision/dynamic_tree.h"

namespace pba::collision {

std::optional<RayHit> rayCastSphere(Real radius, const Ray& ray, Real maxT) {
  if (glm::dot(ray.origin, ray.origin) < radius * radius) return std::nullopt;  // starts inside
  const std::optional<Real> t = intersectRaySphere(ray, Vec3(0.0), radius);     // the entering root
  if (!t || *t > maxT) return std::nullopt;
  const Vec3 p = pointAt(ray, *t);
  return RayHit{*t, p, p / radius, -1};
}

std::optional<RayHit> rayCastCapsule(Real halfHeight, Real radius, const Ray& ray, Real maxT) {
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  // Inside test: distance from the segment below the radius.
  const Real yc = std::clamp(o.y, -halfHeight, halfHeight);
  if (glm::dot(o - Vec3(0, yc, 0), o - Vec3(0, yc, 0)) < radius * radius) return std::nullopt;
  std::optional<RayHit> best;
  // Side: infinite cylinder x² + z² = r² around the y axis, accepted where |y| ≤ halfHeight.
  const Real a = d.x * d.x + d.z * d.z;
  if (a > 1e-18) {
    const Real b = o.x * d.x + o.z * d.z;
    const Real c = o.x * o.x + o.z * o.z - radius * radius;
    const Real disc = b * b - a * c;
    if (disc >= 0.0) {
      const Real t = (-b - std::sqrt(disc)) / a;
      const Real y = o.y + t * d.y;
      if (t >= 0.0 && t <= maxT && std::abs(y) <= halfHeight) {
        const Vec3 p = pointAt(ray, t);
        best = RayHit{t, p, glm::normalize(Vec3(p.x, 0.0, p.z)), -1};
      }
    }
  }
  // End caps: the two spheres.
  for (Real cy : {-halfHeight, halfHeight}) {
    const Ray shifted{o - Vec3(0, cy, 0), d};
    if (std::optional<RayHit> h = rayCastSphere(radius, shifted, maxT); h && (!best || h->t < best->t)) {
      h->point += Vec3(0, cy, 0);
      best = h;
    }
  }
  return best;
}

std::optional<RayHit> rayCastBox(const Vec3& h, const Ray& ray, Real maxT) {
  // Slabs (Ericson §5.3.3), remembering which slab the entry belongs to for the normal.
  Real tEnter = -std::numeric_limits<Real>::max(), tExit = std::numeric_limits<Real>::max();
  int enterAxis = -1;
  Real enterSign = 0.0;
  for (int k = 0; k < 3; ++k) {
    const Real o = ray.origin[k], d = ray.direction[k];
    if (std::abs(d) < 1e-300) {
      if (o < -h[k] || o > h[k]) return std::nullopt;
      continue;
    }
    Real t1 = (-h[k] - o) / d, t2 = (h[k] - o) / d;
    Real sign = -1.0;
    if (t1 > t2) std::swap(t1, t2), sign = 1.0;
    if (t1 > tEnter) tEnter = t1, enterAxis = k, enterSign = sign;
    tExit = std::min(tExit, t2);
    if (tEnter > tExit) return std::nullopt;
  }
  if (enterAxis < 0 || tEnter < 0.0 || tEnter > maxT) return std::nullopt;  // inside, or beyond maxT
  Vec3 n(0.0);
  n[enterAxis] = enterSign;
  return RayHit{tEnter, pointAt(ray, tEnter), n, -1};
}

std::optional<RayHit> rayCastHull(const ConvexHull& hull, const Ray& ray, Real maxT) {
  // Clip the ray against every face's half-space (Ericson §5.3.8).
  Real tEnter = 0.0, tExit = maxT;
  int enterFace = -1;
  for (std::size_t f = 0; f < hull.faces.size(); ++f) {
    const HullFace& face = hull.faces[f];
    const Real denom = glm::dot(face.normal, ray.direction);
    const Real dist = face.offset - glm::dot(face.normal, ray.origin);  // > 0: origin inside this half-space
    if (std::abs(denom) < 1e-300) {
      if (dist < 0.0) return std::nullopt;
      continue;
    }
    const Real t = dist / denom;
    if (denom < 0.0) {
      if (t > tEnter) tEnter = t, enterFace = static_cast<int>(f);
    } else {
      tExit = std::min(tExit, t);
    }
    if (tEnter > tExit) return std::nullopt;
  }
  if (enterFace < 0) return std::nullopt;  // starts inside
  return RayHit{tEnter, pointAt(ray, tEnter), hull.faces[enterFace].normal, -1};
}

std::optional<RayHit> rayCastPlane(const Ray& ray, Real maxT) {
  if (ray.origin.y < 0.0 || ray.direction.y >= 0.0) return std::nullopt;
  const Real t = -ray.origin.y / ray.direction.y;
  if (t > maxT) return std::nullopt;
  return RayHit{t, pointAt(ray, t), kUp, -1};
}

std::optional<RayHit> rayCastTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Ray& ray, Real maxT) {
  // Möller–Trumbore (Ericson §5.3.6 in barycentric form), both sides.
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = glm::cross(ray.direction, e2);
  const Real det = glm::dot(e1, p);
  if (std::abs(det) < 1e-300) return std::nullopt;
  const Real inv = 1.0 / det;
  const Vec3 s = ray.origin - a;
  const Real u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const Vec3 q = glm::cross(s, e1);
  const Real v = glm::dot(ray.direction, q) * inv;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const Real t = glm::dot(e2, q) * inv;
  if (t < 0.0 || t > maxT) return std::nullopt;
  Vec3 n = glm::normalize(glm::cross(e1, e2));
  if (glm::dot(n, ray.direction) > 0.0) n = -n;
  return RayHit{t, pointAt(ray, t), n, -1};
}

std::optional<RayHit> rayCastMesh(const TriangleMesh& mesh, const Ray& ray, Real maxT) {
  std::optional<RayHit> best;
  mesh.tree->rayCast(ray.origin, ray.direction, maxT, [&](int proxy, Real currentMax) {
    const int t = mesh.tree->userData(proxy);
    const auto& tri = mesh.triangles[t];
    if (std::optional<RayHit> h =
            rayCastTriangle(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]], ray, currentMax)) {
      h->triangle = t;
      best = h;
      return h->t;
    }
    return currentMax;
  });
  return best;
}

std::optional<RayHit> rayCast(const Shape& shape, const Transform& pose, const Ray& ray, Real maxT) {
  const Ray local{pose.applyInverse(ray.origin), pose.rotateInverse(ray.direction)};
  std::optional<RayHit> hit;
  switch (shape.kind) {
    case ShapeKind::Sphere:
      hit = rayCastSphere(shape.radius, local, maxT);
      break;
    case ShapeKind::Capsule:
      hit = rayCastCapsule(shape.halfHeight, shape.radius, local, maxT);
      break;
    case ShapeKind::Box:
      hit = rayCastBox(shape.halfExtents, local, maxT);
      break;
    case ShapeKind::Hull:
      hit = rayCastHull(*shape.hull, local, maxT);
      break;
    case ShapeKind::Plane:
      hit = rayCastPlane(local, maxT);
      break;
    case ShapeKind::Mesh:
      hit = rayCastMesh(*shape.mesh, local, maxT);
      break;
  }
  if (hit) {
    hit->point = pose.apply(hit->point);
    hit->normal = pose.rotate(hit->normal);
  }
  return hit;
}

}  // namespace pba::collision
