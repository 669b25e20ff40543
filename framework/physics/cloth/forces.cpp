#include "physics/cloth/forces.h"

#include <algorithm>
#include <cmath>

#include "physics/exercises/not_implemented.h"
#include "physics/springs/spring_network.h"

namespace pba::cloth {
namespace {
constexpr Real kMinLength = 1e-12;  // [m] a spring shorter than this has no direction
// [m/s] Slower flow exerts no aerodynamic force (only the CLOTH-3 solution uses it: maybe unused in the hand-out).
[[maybe_unused]] constexpr Real kMinSpeed = 1e-12;

std::size_t index(LinkKind k) { return static_cast<std::size_t>(k); }
}  // namespace

std::array<Real, kLinkKinds> springStiffness(const ClothMaterial& m) {
  return {m.stretchStiffness, m.shearStiffness, m.bendStiffness};
}

std::array<Real, kLinkKinds> constraintCompliance(const ClothMaterial& m) {
  return {m.stretchCompliance, m.shearCompliance, m.bendLinkCompliance};
}

void accumulateSpringForces(std::span<const Link> springs, const ClothMaterial& m, std::span<const Vec3> x,
                            std::span<const Vec3> v, bool withDamping, std::span<Vec3> f) {
  const std::array<Real, kLinkKinds> k = springStiffness(m);
  const Real kd = withDamping ? m.springDamping : 0.0;
  for (const Link& s : springs) {
    // PART-4, the particles lab's damped spring: the cloth holds no copy of it.
    const Vec3 fi = springs::dampedSpringForce(x[s.i], x[s.j], v[s.i], v[s.j], k[index(s.kind)], s.restLength, kd);
    f[s.i] += fi;
    f[s.j] -= fi;
  }
}

Real springEnergy(std::span<const Link> springs, const ClothMaterial& m, std::span<const Vec3> x) {
  const std::array<Real, kLinkKinds> k = springStiffness(m);
  Real e = 0.0;
  for (const Link& s : springs) {
    const Real stretch = glm::length(x[s.j] - x[s.i]) - s.restLength;
    e += 0.5 * k[index(s.kind)] * stretch * stretch;
  }
  return e;
}

void springJacobians(std::span<const Link> springs, const ClothMaterial& m, std::span<const Vec3> x,
                     const SpringJacobianSettings& settings, std::vector<SpringJacobian>& out) {
  const std::array<Real, kLinkKinds> k = springStiffness(m);
  out.resize(springs.size());
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const Link& link = springs[s];
    SpringJacobian& J = out[s];
    J.i = link.i;
    J.j = link.j;
    const Vec3 r = x[link.j] - x[link.i];
    const Real l = glm::length(r);
    if (l < kMinLength) {
      J.direction = Vec3(0.0);
      J.stiffness = J.lateral = J.damping = 0.0;
      continue;
    }
    J.direction = r / l;
    J.stiffness = k[index(link.kind)];
    const Real lateral = 1.0 - link.restLength / l;
    J.lateral = J.stiffness * (settings.clampCompressedLateral ? std::max(0.0, lateral) : lateral);
    J.damping = m.springDamping;
  }
}

Mat3 stiffnessBlock(const SpringJacobian& s) {
  const Mat3 nn = glm::outerProduct(s.direction, s.direction);
  return s.lateral * Mat3(1.0) + (s.stiffness - s.lateral) * nn;
}

Mat3 dampingBlock(const SpringJacobian& s) { return s.damping * glm::outerProduct(s.direction, s.direction); }

Vec3 triangleAerodynamicForce([[maybe_unused]] const Vec3& x0, [[maybe_unused]] const Vec3& x1,
                              [[maybe_unused]] const Vec3& x2, [[maybe_unused]] const Vec3& v0,
                              [[maybe_unused]] const Vec3& v1, [[maybe_unused]] const Vec3& v2,
                              [[maybe_unused]] const Vec3& wind, [[maybe_unused]] Real airDensity,
                              [[maybe_unused]] Real dragCoefficient, [[maybe_unused]] Real liftCoefficient) {
  // BEGIN SOLUTION
  const Vec3 u = (v0 + v1 + v2) / 3.0 - wind;
  const Real speed = glm::length(u);
  const Vec3 normal = glm::cross(x1 - x0, x2 - x0);
  const Real twiceArea = glm::length(normal);
  if (speed < kMinSpeed || twiceArea == 0.0) return Vec3(0.0);
  const Vec3 flow = u / speed;
  Vec3 n = normal / twiceArea;
  if (glm::dot(n, flow) < 0.0) n = -n;
  const Real cosTheta = glm::dot(n, flow);
  const Real pressureArea = 0.5 * airDensity * speed * speed * 0.5 * twiceArea * cosTheta;  // q A cos θ
  return -dragCoefficient * pressureArea * flow - liftCoefficient * pressureArea * (n - cosTheta * flow);
  // END SOLUTION
  // STUB: return exercises::notImplemented("CLOTH-3", Vec3(0.0), x0, x1, x2, v0, v1, v2, wind, airDensity, dragCoefficient, liftCoefficient);
}

void accumulateExternalForces(const Cloth& cloth, const ClothEnvironment& env, Real t, std::span<const Vec3> x,
                              std::span<const Vec3> v, std::span<Vec3> f) {
  for (std::size_t i = 0; i < cloth.size(); ++i) {
    if (cloth.inverseMass[i] == 0.0) continue;
    f[i] += cloth.mass[i] * (env.gravity - env.massDamping * v[i]);
  }
  if (!env.aerodynamics) return;
  for (const Triangle& tri : cloth.triangles) {
    const Vec3 centroid = (x[tri[0]] + x[tri[1]] + x[tri[2]]) / 3.0;
    const Vec3 wind = particles::windVelocity(env.wind, centroid, t);
    const Vec3 third = triangleAerodynamicForce(x[tri[0]], x[tri[1]], x[tri[2]], v[tri[0]], v[tri[1]], v[tri[2]], wind,
                                                env.airDensity, env.dragCoefficient, env.liftCoefficient) /
                       3.0;
    for (std::uint32_t k : tri) {
      if (cloth.inverseMass[k] != 0.0) f[k] += third;
    }
  }
}

Real kineticEnergy(const Cloth& cloth) {
  Real e = 0.0;
  for (std::size_t i = 0; i < cloth.size(); ++i) {
    if (cloth.inverseMass[i] != 0.0) e += 0.5 * cloth.mass[i] * glm::dot(cloth.velocity[i], cloth.velocity[i]);
  }
  return e;
}

Real gravityEnergy(const Cloth& cloth, const Vec3& gravity) {
  Real e = 0.0;
  for (std::size_t i = 0; i < cloth.size(); ++i) {
    if (cloth.inverseMass[i] != 0.0) e -= cloth.mass[i] * glm::dot(gravity, cloth.position[i]);
  }
  return e;
}

// Start-up probe: tells the lab whether CLOTH-3 is still a stub.
PBA_EXERCISE_PROBE(triangleAerodynamicForce(Vec3(0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0), Vec3(0.0), Vec3(0.0),
                                            Vec3(0.0), Vec3(0.0, 0.0, 1.0), 1.2, 1.0, 0.5));

}  // namespace pba::cloth
