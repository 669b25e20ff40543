#pragma once
// A cloth from any triangle mesh Assimp loads (issue 14: "built from any triangle mesh that Assimp loads;
// the lab loads it, the library takes vertices and triangles"). Vertices that Assimp split at seams are
// welded by position, the mesh is scaled to `size` and centred at `center`.
#include <string>

#include "physics/cloth/cloth.h"

namespace pba::lab {

/// "mesh: FILE: reason" on failure (the field is the scene parameter's name).
Result<pba::cloth::TriangleMesh> loadClothMesh(const std::string& path, Real size, const Vec3& center);

}  // namespace pba::lab
