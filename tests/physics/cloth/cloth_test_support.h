#pragma once
// Builders and helpers shared by the cloth tests. Everything here is reference-only library code (no
// exercise): grids use the Mesh spring layout, so no test but CLOTH-1's runs gridSpringTopology.
#include <cstdint>
#include <cstring>
#include <vector>

#include "physics/cloth/cloth.h"
#include "physics/cloth/solver.h"
#include "physics/core/byte_hash.h"
#include "support/fp_traps.h"

namespace pba::cloth::testing {

/// A square cloth of n × n particles, size × size metres, horizontal at height y, pinned as asked,
/// with the Mesh layout (every edge a spring, bend springs across inner edges).
inline Cloth meshGrid(int n, Real size, Real y, GridPins pins, const ClothMaterial& material = {}) {
  GridDesc d;
  d.resolutionX = d.resolutionY = n;
  d.width = d.height = size;
  d.center = Vec3(0.0, y, 0.0);
  d.pins = pins;
  d.layout = SpringLayout::Mesh;
  return buildClothGrid(d, material).value();
}

/// Two horizontal sheets of n × n particles `spacing` apart in one cloth, the upper one `gap` above the
/// lower one (at the grid's default height, 1.5 m); the lower one's particles come first and are pinned.
/// Mesh layout, soft springs (k = 100 N/m stretch and shear, 10 bend), thickness = spacing.
struct StackedSheets {
  Cloth cloth;
  ClothMaterial material;
  std::uint32_t upperFirst = 0;  ///< index of the upper sheet's first particle
};
inline StackedSheets stackedSheets(int n, Real spacing, Real gap) {
  GridDesc d;
  d.resolutionX = d.resolutionY = n;
  d.width = d.height = (n - 1) * spacing;
  d.layout = SpringLayout::Mesh;
  TriangleMesh both = gridMesh(d);
  const auto offset = static_cast<std::uint32_t>(both.vertices.size());
  d.center.y += gap;
  const TriangleMesh upper = gridMesh(d);
  both.vertices.insert(both.vertices.end(), upper.vertices.begin(), upper.vertices.end());
  for (Triangle t : upper.triangles) both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  std::vector<std::uint32_t> pinned(offset);
  for (std::uint32_t i = 0; i < offset; ++i) pinned[i] = i;
  StackedSheets sheets;
  sheets.material.thickness = spacing;
  sheets.material.stretchStiffness = sheets.material.shearStiffness = 100.0;
  sheets.material.bendStiffness = 10.0;
  sheets.material.springDamping = 0.005;
  sheets.cloth = buildCloth(both, sheets.material, pinned).value();
  sheets.upperFirst = offset;
  return sheets;
}

/// A vertical chain of `particles` (mass m each) hanging from a pinned top at height `top`, links of rest
/// length L, with the chain's links as springs AND as distance constraints (no triangles: the solvers
/// only need the arrays). Starts at rest length.
inline Cloth hangingChain(int particles, Real m, Real L, Real top, const ClothMaterial& material) {
  Cloth c;
  c.material = material;
  for (int k = 0; k < particles; ++k) {
    c.position.emplace_back(0.0, top - k * L, 0.0);
    c.velocity.emplace_back(0.0);
    c.restPosition.push_back(c.position.back());
    c.mass.push_back(m);
    c.inverseMass.push_back(1.0 / m);
  }
  for (int k = 0; k + 1 < particles; ++k) {
    const Link link{static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(k + 1), L, LinkKind::Stretch};
    c.springs.push_back(link);
    c.constraints.push_back(link);
  }
  pin(c, 0, c.position[0]);
  return c;
}

/// Length of link k of the chain minus its rest length [m].
inline Real chainExtension(const Cloth& c, std::size_t k) {
  return glm::length(c.position[k + 1] - c.position[k]) - c.constraints[k].restLength;
}

/// Steps `frames` frames of dt, returns the stats of the last one.
inline ClothStepStats run(Cloth& cloth, ClothSolver& solver, const ClothEnvironment& env,
                          std::span<const Collider> colliders, const ClothSolverSettings& s, Real dt, int frames,
                          Real* time = nullptr) {
  ClothStepStats stats;
  Real t = time ? *time : 0.0;
  for (int f = 0; f < frames; ++f) {
    stats = solver.step(cloth, env, colliders, s, dt, t);
    t += dt;
  }
  if (time) *time = t;
  return stats;
}

/// A hash of the bits of positions and velocities: equal hashes ⇔ (practically) identical state.
inline std::uint64_t stateHash(const Cloth& c) {
  ByteHash h;
  h.addAll(std::span<const Vec3>(c.position));
  h.addAll(std::span<const Vec3>(c.velocity));
  return h.value();
}

}  // namespace pba::cloth::testing
