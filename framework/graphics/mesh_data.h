// MeshData: CPU triangle meshes (positions, normals, indices) and the unit primitive generators the
// renderer instances. Conventions (object space, y up, counter-clockwise front faces):
//   box      centre 0, half extent 1 along each axis (the cube [-1,1]^3): scale by half extents
//   sphere   centre 0, radius 1
//   cylinder axis +y from y=0 to y=1, radius 1, with caps: scale x,z by r and y by length
//   cone     base disc at y=0 radius 1, apex at y=1 (arrow heads)
//   plane    y=0, x,z in [-1,1], normal +y
//   capsule  axis +y, segment from y=-halfLength to +halfLength, radius r (real geometry, not scaled)
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace pba::graphics {

struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      ///< unit, one per position
  std::vector<std::uint32_t> indices;  ///< triangles, counter-clockwise seen from outside

  std::size_t triangleCount() const { return indices.size() / 3; }
  /// Appends `other` (indices shifted).
  void append(const MeshData& other);
};

MeshData makeBox();
MeshData makeSphere(int slices = 32, int stacks = 16);
MeshData makeCylinder(int slices = 32, bool caps = true);
MeshData makeCone(int slices = 32);
MeshData makePlane();
MeshData makeCapsule(float radius, float halfLength, int slices = 32, int stacks = 16);

/// Smooth per-vertex normals from triangles (area weighted); used when an import has none.
std::vector<glm::vec3> computeVertexNormals(const std::vector<glm::vec3>& positions,
                                            const std::vector<std::uint32_t>& indices);

}  // namespace pba::graphics
