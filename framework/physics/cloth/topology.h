#pragma once
// The connectivity of a cloth: mesh edges with their adjacent triangles, the springs of the two layouts
// (Provot's grid and any triangle mesh) and the bending stencils. Pure functions of the triangles and the
// rest positions, so tearing can rebuild all of it after it splits a vertex.
#include <cstdint>
#include <span>
#include <vector>

#include "physics/cloth/cloth.h"
#include "physics/core/result.h"

namespace pba::cloth {

/// Checks a mesh at the library's boundary: at least one triangle, indices in range, no triangle with a
/// repeated vertex or zero area, no edge shared by more than two triangles, finite vertices.
Status validateMesh(const TriangleMesh& mesh);

/// The unique edges of `triangles` (a < b), each with the opposite vertex of one or two adjacent triangles,
/// sorted by (a, b). Assumes a manifold mesh (validateMesh); a third triangle on an edge is ignored.
std::vector<Edge> buildEdges(std::span<const Triangle> triangles);

/// A link of a grid between particles p and q (indices j·nx + i) and what it resists.
struct GridLink {
  std::uint32_t p = 0, q = 0;
  LinkKind kind = LinkKind::Stretch;
  bool operator==(const GridLink&) const = default;
};

// ***** CLOTH-1: the spring topology of a grid (Provot 1995, §2 "structural, shear and flexion springs") *****
// Particle (i, j) of an nx × ny grid, i = 0…nx−1 along a row, j = 0…ny−1, has index j·nx + i.
// Return every spring of the grid exactly once, as a GridLink (p, q, kind):
// (1) Stretch (structural) springs join grid neighbours, shear springs the two diagonals of every quad,
//     bend (flexion) springs particles one particle apart along a row or a column (Provot §2).
// (2) To list each spring once, let each particle start only the springs that go to its right and
//     downwards; work out which of them exist at the grid's last columns and rows.
// Rest lengths are not your concern: the caller measures them on the rest positions.
// Check: a 3 × 3 grid has 12 stretch, 8 shear and 6 bend springs; no spring appears twice or joins a
// particle to itself; every index is below nx·ny.
// *****
std::vector<GridLink> gridSpringTopology(int nx, int ny);

/// The springs of the Mesh layout: every edge (Stretch; Shear when `gridX` > 0 and the edge is a quad
/// diagonal) and, across every inner edge, the two opposite vertices (Bend; Shear when it joins the other
/// diagonal of a grid quad). Rest lengths from `rest`.
std::vector<Link> meshSprings(std::span<const Edge> edges, std::span<const Vec3> rest, int gridX);
/// Across every inner edge, a link between its two opposite vertices (Bend; Shear when it is the other
/// diagonal of a grid quad). Rest lengths from `rest`.
std::vector<Link> acrossEdgeLinks(std::span<const Edge> edges, std::span<const Vec3> rest, int gridX);
/// One distance constraint per edge (kinds as in meshSprings), rest lengths from `rest`.
std::vector<Link> edgeConstraints(std::span<const Edge> edges, std::span<const Vec3> rest, int gridX);
/// Turns grid links into springs with rest lengths measured on `rest`.
std::vector<Link> gridSprings(std::span<const GridLink> links, std::span<const Vec3> rest);
/// Isometric bending stencils (cloth.h, BendingStencil) for every inner edge, measured on the rest shape.
/// Pairs of triangles with a degenerate rest angle are skipped.
std::vector<BendingStencil> bendingStencils(std::span<const Edge> edges, std::span<const Vec3> rest);

/// Reorders links, then bending stencils, so that Gauss–Seidel visits them colour by colour: a greedy
/// colouring in which no two members of a colour share a particle (Fratarcangeli et al. 2016 colour
/// constraints to run them in parallel). Here it is for robustness: sweeping in index order (row by row)
/// let rounding perturbations grow without bound in a falling 30 × 200 ribbon with one sweep per
/// substep, a linear instability of that particular order; the colour order damps them. Deterministic.
void orderByColour(std::vector<Link>& links, std::size_t particles);
void orderByColour(std::vector<BendingStencil>& stencils, std::size_t particles);

/// Lumped masses: each triangle gives a third of massPerArea × its rest area to each of its vertices.
std::vector<Real> lumpedMasses(std::span<const Triangle> triangles, std::span<const Vec3> rest, Real massPerArea,
                               std::size_t particles);

}  // namespace pba::cloth
