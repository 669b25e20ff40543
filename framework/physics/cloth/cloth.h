#pragma once
// A cloth: a triangle mesh of particles (docs/architecture.md §2: a description with documented defaults, separate
// from the runtime object it builds). Two models live on the same particles and can be switched live:
//   mass-spring   Provot 1995: structural, shear and bend springs (links), forces and their Jacobians;
//   constraints   Müller et al. 2007 (PBD), Macklin et al. 2016 (XPBD): a distance constraint on every mesh
//                 edge plus isometric bending (Bergou et al. 2006) on every pair of triangles sharing an edge.
// Pinned particles have inverse mass 0 (docs/architecture.md §2); a pin may move (a curtain rail) through its target.
//
// Glossary
//   x, v      particle positions [m] and velocities [m/s], world frame, y up
//   x̄         rest positions [m] (the flat cloth as cut: lengths, areas and bending are measured on them)
//   w = 1/m   inverse mass [1/kg]; 0 = pinned
//   L         rest length of a link [m] (|x̄_i − x̄_j|)
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "physics/core/enum_names.h"
#include "physics/core/result.h"
#include "physics/core/types.h"

namespace pba::cloth {

using Triangle = std::array<std::uint32_t, 3>;

/// What a link (spring or distance constraint) resists: stretch along the weave, shear across it, bending.
enum class LinkKind : std::uint8_t { Stretch, Shear, Bend };
inline constexpr int kLinkKinds = 3;

/// A spring or distance constraint between two particles.
struct Link {
  std::uint32_t i = 0, j = 0;
  Real restLength = 0.0;  ///< L [m] > 0
  LinkKind kind = LinkKind::Stretch;
};

/// An edge of the triangle mesh with the triangles on either side (the second is absent on the border).
struct Edge {
  std::uint32_t a = 0, b = 0;              ///< a < b
  std::uint32_t oppositeA = 0;             ///< vertex of the first triangle not on the edge
  std::optional<std::uint32_t> oppositeB;  ///< vertex of the second triangle, if any
};

/// Isometric bending (Bergou et al. 2006, "A quadratic bending model for inextensible surfaces", §4) on two
/// triangles (e0, e1, o0) and (e1, e0, o1) sharing the edge e0–e1. With c_ab the cotangent of the angle
/// between edges a and b at the shared edge, K = (c03 + c04, c01 + c02, −c01 − c03, −c02 − c04) and the
/// energy is E = ½ k_b (3 / (A0 + A1)) |Σ K_i x_i|², which is 0 for any rigid motion of the flat pair and
/// quadratic in x: its Hessian is constant. XPBD treats C = √(3/(A0+A1)) Σ K_i x_i ∈ ℝ³ as a linear vector
/// constraint with compliance 1/k_b, so that E = ½ |C|² / α (Macklin et al. 2016 eq. 4).
struct BendingStencil {
  std::array<std::uint32_t, 4> vertex{};  ///< e0, e1, o0, o1
  std::array<Real, 4> weight{};           ///< √(3/(A0+A1)) K_i [1/m]
};

/// A pinned particle and where it is held [m]. Scenes move the target (curtain rail, mouse drag).
struct Pin {
  std::uint32_t particle = 0;
  Vec3 target{0.0};
};

/// Material of the cloth: stiffness for the spring model, compliance for XPBD, damping, thickness.
struct ClothMaterial {
  Real massPerArea = 0.2;          ///< [kg/m²] cotton ≈ 0.1–0.3
  Real stretchStiffness = 1000.0;  ///< [N/m] per spring, mass-spring model; typical 10²–10⁵
  Real shearStiffness = 1000.0;    ///< [N/m]
  Real bendStiffness = 100.0;      ///< [N/m] bend springs (skip one particle)
  Real springDamping = 0.02;       ///< [N·s/m] along every spring (resists the rate of change of length)
  Real stretchCompliance = 0.0;    ///< α [m/N] XPBD distance constraints (0 = inextensible); 1/k of a spring
  Real shearCompliance = 0.0;      ///< α [m/N] for edges that are quad diagonals of a grid
  Real bendCompliance = 1000.0;  ///< α [1/(N·m)] isometric bending: 1/k_b, k_b [N·m] ≈ 10⁻⁵ (silk) – 10⁻³ (denim)
  Real bendLinkCompliance = 1.0;  ///< α [m/N] distance bending (TMP #14–15: across every inner edge)
  Real thickness = 0.01;          ///< [m] particles keep this distance from each other and half of it from colliders
};
Status validate(const ClothMaterial& material);

/// How the springs of the mass-spring model are laid out.
enum class SpringLayout {
  Grid,  ///< Provot 1995 on a rectangular grid: axis neighbours, both diagonals, skip-one (CLOTH-1)
  Mesh,  ///< any triangle mesh: every edge, and across every inner edge the two opposite vertices
};
inline constexpr auto kSpringLayoutNames =
    enumNames<SpringLayout>({{SpringLayout::Grid, "grid"}, {SpringLayout::Mesh, "mesh"}});

/// Which way each quad of a grid is split into two triangles.
enum class GridDiagonals { Regular, Alternating };

/// Which particles a grid pins.
enum class GridPins { None, TopCorners, TopRow, TopCornersAndMiddle };

/// A rectangular cloth of resolutionX × resolutionY particles. Particle (i, j) sits at
/// center + (i/(nx−1) − ½) width û + (j/(ny−1) − ½) height v̂; row j = 0 is the "top" that GridPins names.
struct GridDesc {
  int resolutionX = 32;        ///< particles along û, ≥ 2
  int resolutionY = 32;        ///< particles along v̂, ≥ 2
  Real width = 1.0;            ///< [m] along û
  Real height = 1.0;           ///< [m] along v̂
  Vec3 center{0.0, 1.5, 0.0};  ///< [m]
  Vec3 axisU{1.0, 0.0, 0.0};   ///< unit, the row direction
  Vec3 axisV{0.0, 0.0, 1.0};   ///< unit, ⟂ axisU; (0, −1, 0) hangs the cloth with row 0 on top
  GridDiagonals diagonals = GridDiagonals::Alternating;
  GridPins pins = GridPins::TopCorners;
  SpringLayout layout = SpringLayout::Grid;
};
Status validate(const GridDesc& desc);

/// Vertices and triangles from anywhere (a grid, a model file the lab loads): what buildCloth() takes.
struct TriangleMesh {
  std::vector<Vec3> vertices;       ///< [m] rest positions (also the initial positions)
  std::vector<Triangle> triangles;  ///< indices into vertices, counter-clockwise seen from the front
};
/// The grid's mesh (rest positions and triangles) without building a cloth.
TriangleMesh gridMesh(const GridDesc& desc);

/// The runtime cloth: plain structs of arrays (docs/architecture.md §2), so saving and restoring state is a copy.
struct Cloth {
  std::vector<Vec3> position;      ///< x [m]
  std::vector<Vec3> velocity;      ///< v [m/s]
  std::vector<Vec3> restPosition;  ///< x̄ [m]
  std::vector<Real> mass;          ///< [kg] lumped: a third of each adjacent triangle's rest area × massPerArea
  std::vector<Real> inverseMass;   ///< [1/kg]; 0 while pinned
  std::vector<Triangle> triangles;
  std::vector<Edge> edges;              ///< unique mesh edges
  std::vector<Link> constraints;        ///< XPBD/PBD: one distance constraint per edge
  std::vector<Link> springs;            ///< mass-spring model
  std::vector<BendingStencil> bending;  ///< XPBD/PBD isometric bending, one per inner edge
  std::vector<Link> bendLinks;          ///< XPBD/PBD distance bending: the opposite vertices of each inner edge
  std::vector<Pin> pins;
  ClothMaterial material;
  SpringLayout layout = SpringLayout::Mesh;
  int gridX = 0, gridY = 0;  ///< grid resolution while the topology is still the grid's (0 after tearing)
  std::size_t torn = 0;      ///< vertex splits so far (tearing.h)

  std::size_t size() const { return position.size(); }
  /// Total mass of the cloth [kg] (pinned particles included).
  Real totalMass() const;
};

/// Builds a cloth from any triangle mesh (Mesh layout). Errors name the field: "mesh.triangles[3]: ...".
/// Rejects an empty mesh, indices out of range, degenerate triangles and non-manifold edges (shared by
/// more than two triangles). `pinned` lists particles to pin where they are.
Result<Cloth> buildCloth(const TriangleMesh& mesh, const ClothMaterial& material,
                         std::span<const std::uint32_t> pinned = {});
/// Builds the grid of `desc` (docs/architecture.md §1: the lab, the tests and the benchmarks share this builder).
Result<Cloth> buildClothGrid(const GridDesc& desc, const ClothMaterial& material);

/// Recomputes edges, constraints, springs, bending stencils and lumped masses from the triangles and the
/// rest positions (after tearing or a layout change). Pinned particles stay pinned.
void rebuildTopology(Cloth& cloth);
/// Pins particle i at `target` (inverse mass 0); a particle already pinned gets the new target.
void pin(Cloth& cloth, std::uint32_t particle, const Vec3& target);
/// Releases the pin of particle i (its inverse mass is 1/mass again). No effect if it is not pinned.
void unpin(Cloth& cloth, std::uint32_t particle);
/// The pin of particle i, if any.
Pin* findPin(Cloth& cloth, std::uint32_t particle);

/// "particle 17 position is NaN" for the first particle whose state is not finite.
std::optional<std::string> describeNonFinite(const Cloth& cloth);

}  // namespace pba::cloth
