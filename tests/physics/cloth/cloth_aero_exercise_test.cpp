// CLOTH-3: the aerodynamic force on one triangle. Expected values from the flat-plate closed forms at
// angles where the trigonometry is exact by hand: face-on, edge-on, 45° and 60°. ClothWind steps a whole
// cloth (its springs are PART-4), so it is not CLOTH-3's own test.
#include <cmath>

#include <gtest/gtest.h>

#include "cloth_test_support.h"
#include "physics/cloth/forces.h"
#include "support/expect_helpers.h"

namespace pba::cloth {
namespace {

// A right triangle of area ½ m² in the plane z = 0 (normal ±z).
const Vec3 kX0(0.0, 0.0, 0.0), kX1(1.0, 0.0, 0.0), kX2(0.0, 1.0, 0.0);
constexpr Real kRho = 1.2, kCd = 1.1, kCl = 0.4;

Vec3 force(const Vec3& wind, const Vec3& v = Vec3(0.0)) {
  return triangleAerodynamicForce(kX0, kX1, kX2, v, v, v, wind, kRho, kCd, kCl);
}

TEST(CLOTH_3_Aerodynamics, FaceOnWindPushesWithTheFullDragAndNoLift) {
  // Wind 5 m/s along −z hits the plate face-on: u = v − w = (0, 0, 5) relative; drag −C_D ½ρ|u|² A û.
  const Vec3 f = force(Vec3(0.0, 0.0, -5.0));
  EXPECT_VEC3_NEAR(f, Vec3(0.0, 0.0, -kCd * 0.5 * kRho * 25.0 * 0.5), 1e-12);
}

TEST(CLOTH_3_Aerodynamics, EdgeOnWindAndStillAirExertNothingButATiltedFlowDoes) {
  EXPECT_VEC3_NEAR(force(Vec3(3.0, -2.0, 0.0)), Vec3(0.0), 1e-12);  // flow in the plate's plane
  EXPECT_VEC3_NEAR(force(Vec3(0.0)), Vec3(0.0), 0.0);
  // Tilted by 10° out of the plane: cos θ = sin 10°, so the drag along the flow is −C_D q A sin 10°.
  const Vec3 flow(std::cos(degToRad(10.0)), 0.0, std::sin(degToRad(10.0)));
  const Vec3 f = force(-4.0 * flow);
  EXPECT_NEAR(glm::dot(f, flow), -kCd * 0.5 * kRho * 16.0 * 0.5 * std::sin(degToRad(10.0)), 1e-12);
}

TEST(CLOTH_3_Aerodynamics, AtFortyFiveDegreesDragAndLiftFollowTheProjectedArea) {
  // Relative flow û = (1, 0, 1)/√2 at |u| = 4: cos θ = sin θ = 1/√2, q = ½ρ·16, A cos θ = ½/√2.
  const Real q = 0.5 * kRho * 16.0, projected = 0.5 / std::sqrt(2.0);
  const Vec3 flow = glm::normalize(Vec3(1.0, 0.0, 1.0));
  const Vec3 f = force(Vec3(0.0), 4.0 * flow);  // the plate moves through still air
  const Vec3 drag = -kCd * q * projected * flow;
  // Lift ⟂ û in the plane of û and n̂ = +z, pointing away from n̂: direction (1, 0, −1)/√2, size C_L q A cos θ sin θ.
  const Vec3 lift = kCl * q * projected * (1.0 / std::sqrt(2.0)) * glm::normalize(Vec3(1.0, 0.0, -1.0));
  EXPECT_VEC3_NEAR(f, drag + lift, 1e-12);
  EXPECT_NEAR(glm::dot(f - drag, flow), 0.0, 1e-12);  // the lift is perpendicular to the flow
}

TEST(CLOTH_3_Aerodynamics, IsTwoSidedAndGalilean) {
  // At 60° between flow and normal: reversing the vertex order (the other face) changes nothing, and a
  // plate moving at v in still air feels what a still plate feels in the wind −v.
  const Vec3 v = 3.0 * Vec3(std::sin(kPi / 3.0), 0.0, std::cos(kPi / 3.0));
  const Vec3 moving = force(Vec3(0.0), v);
  const Vec3 flipped = triangleAerodynamicForce(kX0, kX2, kX1, v, v, v, Vec3(0.0), kRho, kCd, kCl);
  EXPECT_VEC3_NEAR(flipped, moving, 1e-12);
  EXPECT_VEC3_NEAR(force(-v), moving, 1e-12);
  // Drag part: −C_D q A cos θ û with cos 60° = ½.
  const Vec3 flow = v / 3.0;
  EXPECT_NEAR(glm::dot(moving, flow), -kCd * 0.5 * kRho * 9.0 * 0.5 * 0.5, 1e-12);
}

TEST(ClothWind, BlowsAHangingClothDownwind) {
  // A cloth hanging from its top row in a steady 8 m/s wind along +x swings downwind and stays there.
  GridDesc d;
  d.resolutionX = d.resolutionY = 10;
  d.center = Vec3(0.0, 1.5, 0.0);
  d.axisU = Vec3(0.0, 0.0, 1.0);
  d.axisV = Vec3(0.0, -1.0, 0.0);  // hanging in the y–z plane, facing the wind
  d.pins = GridPins::TopRow;
  d.layout = SpringLayout::Mesh;
  Cloth c = buildClothGrid(d, ClothMaterial{}).value();
  ClothEnvironment env;
  env.aerodynamics = true;
  env.wind.base = Vec3(8.0, 0.0, 0.0);
  env.massDamping = 0.5;
  ClothSolverSettings s;
  s.kind = ClothSolverKind::Explicit;
  s.substeps = 40;
  ClothSolver solver;
  testing::run(c, solver, env, {}, s, 1.0 / 60.0, 120);
  Real meanX = 0.0;
  for (std::size_t i = c.size() - 10; i < c.size(); ++i) meanX += c.position[i].x / 10.0;
  EXPECT_GT(meanX, 0.3);  // the bottom row was blown well downwind of the rail at x = 0
}

}  // namespace
}  // namespace pba::cloth
