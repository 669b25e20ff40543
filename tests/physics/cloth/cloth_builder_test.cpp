// The cloth's description, builders and topology (no exercise code: Mesh layout only).
#include <algorithm>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "cloth_test_support.h"
#include "physics/cloth/topology.h"
#include "physics/cloth/xpbd.h"
#include "support/expect_helpers.h"

namespace pba::cloth {
namespace {

using testing::meshGrid;

TEST(ClothGrid, HasTheGridsParticlesTrianglesEdgesAndMass) {
  const int n = 5;
  ClothMaterial m;
  m.massPerArea = 0.3;
  const Cloth c = meshGrid(n, 2.0, 1.0, GridPins::None, m);
  EXPECT_EQ(c.size(), 25u);
  EXPECT_EQ(c.triangles.size(), 2u * 4u * 4u);
  // Edges of a triangulated (n−1)² grid: rows, columns and one diagonal per quad.
  EXPECT_EQ(c.edges.size(), 2u * 5u * 4u + 16u);
  EXPECT_EQ(c.constraints.size(), c.edges.size());
  // Lumped masses add up to massPerArea × area exactly (up to rounding).
  EXPECT_NEAR(c.totalMass(), 0.3 * 4.0, 1e-12);
  // Inner edges: 56 edges, 16 on the border; each inner one gives a bend spring and a bending stencil.
  EXPECT_EQ(c.bending.size(), c.edges.size() - 16u);
  EXPECT_EQ(c.springs.size(), c.edges.size() + c.bending.size());
}

TEST(ClothGrid, PinsTheParticlesItNamesWhereTheyAre) {
  const Cloth c = meshGrid(6, 1.0, 2.0, GridPins::TopCorners);
  ASSERT_EQ(c.pins.size(), 2u);
  EXPECT_EQ(c.pins[0].particle, 0u);
  EXPECT_EQ(c.pins[1].particle, 5u);
  for (const Pin& p : c.pins) {
    EXPECT_EQ(c.inverseMass[p.particle], 0.0);
    EXPECT_EQ(c.position[p.particle], p.target);
  }
  const Cloth row = meshGrid(6, 1.0, 2.0, GridPins::TopRow);
  EXPECT_EQ(row.pins.size(), 6u);
}

TEST(ClothGrid, QuadDiagonalsAreShearAndTheRestStretch) {
  const Cloth c = meshGrid(4, 0.3, 1.0, GridPins::None);
  for (const Link& l : c.constraints) {
    const Real expected = l.kind == LinkKind::Shear ? 0.1 * std::sqrt(2.0) : 0.1;
    EXPECT_NEAR(l.restLength, expected, 1e-12);
  }
}

TEST(ClothMesh, BuildsFromAnyTriangleMeshAndValidatesIt) {
  TriangleMesh tetra;  // the surface of a tetrahedron: closed, every edge shared by two triangles
  tetra.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const Result<Cloth> c = buildCloth(tetra, ClothMaterial{});
  ASSERT_TRUE(c.ok()) << c.error();
  EXPECT_EQ(c.value().edges.size(), 6u);
  EXPECT_EQ(c.value().bending.size(), 6u);
  for (const Edge& e : c.value().edges) EXPECT_TRUE(e.oppositeB.has_value());
}

TEST(ClothMesh, BadInputGivesAnErrorNamingTheField) {
  const ClothMaterial m;
  TriangleMesh empty;
  EXPECT_NE(buildCloth(empty, m).error().find("mesh.triangles"), std::string::npos);

  TriangleMesh outOfRange{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 7}}};
  EXPECT_NE(buildCloth(outOfRange, m).error().find("mesh.triangles[0]: vertex index 7 out of range"),
            std::string::npos);

  TriangleMesh degenerate{{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}};
  EXPECT_NE(buildCloth(degenerate, m).error().find("zero area"), std::string::npos);

  // Three triangles on edge 0–1: not a surface.
  TriangleMesh fan{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}};
  const std::string error = buildCloth(fan, m).error();
  EXPECT_NE(error.find("mesh.triangles[2]"), std::string::npos) << error;
  EXPECT_NE(error.find("non-manifold"), std::string::npos) << error;

  ClothMaterial negative;
  negative.stretchStiffness = -1.0;
  TriangleMesh one{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  EXPECT_NE(buildCloth(one, negative).error().find("material.stretchStiffness"), std::string::npos);
  ClothMaterial thick;
  thick.thickness = -0.01;
  EXPECT_NE(buildCloth(one, thick).error().find("material.thickness"), std::string::npos);

  GridDesc zero;
  zero.resolutionX = 0;
  EXPECT_NE(buildClothGrid(zero, m).error().find("resolutionX"), std::string::npos);
  GridDesc skew;
  skew.axisV = Vec3(1.0, 0.0, 0.0);
  EXPECT_NE(buildClothGrid(skew, m).error().find("axisV"), std::string::npos);
}

TEST(IsometricBending, VanishesOnFlatPairsUnderRigidMotionAndGrowsWithTheFold) {
  // Two triangles sharing the edge (0,0,0)–(1,0,0), opposite vertices at y = ±1 (a flat pair).
  TriangleMesh pair{{{0, 0, 0}, {1, 0, 0}, {0.3, 1, 0}, {0.6, -1, 0}}, {{0, 1, 2}, {1, 0, 3}}};
  Cloth c = buildCloth(pair, ClothMaterial{}).value();
  ASSERT_EQ(c.bending.size(), 1u);
  const BendingStencil& s = c.bending[0];
  auto constraint = [&](const std::vector<Vec3>& x) {
    Vec3 sum(0.0);
    for (int k = 0; k < 4; ++k) sum += s.weight[k] * x[s.vertex[k]];
    return sum;
  };
  // Any rotation and translation of the flat pair: C = 0 (rounding only).
  const Quat q = glm::angleAxis(0.7, glm::normalize(Vec3(1.0, 2.0, -0.5)));
  std::vector<Vec3> moved = c.restPosition;
  for (Vec3& x : moved) x = q * x + Vec3(3.0, -1.0, 2.0);
  EXPECT_LT(glm::length(constraint(c.restPosition)), 1e-12);
  EXPECT_LT(glm::length(constraint(moved)), 1e-12);
  // Folding vertex 3 about the shared edge by φ: |C| grows with the fold, and symmetric folds agree.
  auto folded = [&](Real phi) {
    std::vector<Vec3> x = c.restPosition;
    const Vec3 o = x[3];
    x[3] = Vec3(o.x, o.y * std::cos(phi), -o.y * std::sin(phi));
    return glm::length(constraint(x));
  };
  EXPECT_GT(folded(0.2), 0.0);
  EXPECT_GT(folded(0.6), folded(0.2));
  EXPECT_NEAR(folded(0.4), folded(-0.4), 1e-12);
  // Bending energy ½|C|²/α: with α = 0.5, at a fold of 0.6 rad.
  std::vector<Vec3> x = c.restPosition;
  x[3] = Vec3(x[3].x, x[3].y * std::cos(0.6), -x[3].y * std::sin(0.6));
  EXPECT_NEAR(bendingEnergy(c.bending, x, 0.5), folded(0.6) * folded(0.6), 1e-12);
}

TEST(ClothTopology, RebuildKeepsPinsAndRecomputesEverything) {
  Cloth c = meshGrid(4, 1.0, 1.0, GridPins::TopCorners);
  const std::size_t edges = c.edges.size();
  c.edges.clear();
  c.springs.clear();
  rebuildTopology(c);
  EXPECT_EQ(c.edges.size(), edges);
  EXPECT_EQ(c.inverseMass[0], 0.0);
  EXPECT_GT(c.inverseMass[1], 0.0);
  unpin(c, 0);
  EXPECT_GT(c.inverseMass[0], 0.0);
  EXPECT_EQ(c.pins.size(), 1u);
}

TEST(ClothState, NamesTheFirstNonFiniteParticle) {
  Cloth c = meshGrid(3, 1.0, 1.0, GridPins::None);
  EXPECT_FALSE(describeNonFinite(c).has_value());
  c.velocity[4].y = std::numeric_limits<Real>::infinity();
  EXPECT_EQ(describeNonFinite(c).value(), "cloth particle 4 velocity is not finite");
}

}  // namespace
}  // namespace pba::cloth
