#include "mesh_import.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "graphics/model.h"

namespace pba::lab {

using namespace pba::cloth;

Result<pba::cloth::TriangleMesh> loadClothMesh(const std::string& path, Real size, const Vec3& center) {
  std::string error;
  const std::optional<graphics::Model> model = graphics::loadModel(path, &error);
  if (!model) return Error{"mesh: " + error};
  pba::cloth::TriangleMesh mesh;
  std::map<std::tuple<long long, long long, long long>, std::uint32_t> welded;
  constexpr Real kWeld = 1e-6;  // relative to the model's units: positions closer than this are one vertex
  for (const graphics::ModelMesh& m : model->meshes) {
    if (m.placeholder) continue;
    std::vector<std::uint32_t> remap(m.positions.size());
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
      const glm::vec3 p = m.positions[v];
      const auto key = std::make_tuple(std::llround(p.x / kWeld), std::llround(p.y / kWeld), std::llround(p.z / kWeld));
      const auto [it, inserted] = welded.emplace(key, static_cast<std::uint32_t>(mesh.vertices.size()));
      if (inserted) mesh.vertices.emplace_back(p.x, p.y, p.z);
      remap[v] = it->second;
    }
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      const pba::cloth::Triangle tri{remap[m.indices[t]], remap[m.indices[t + 1]], remap[m.indices[t + 2]]};
      if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2]) mesh.triangles.push_back(tri);
    }
  }
  if (mesh.triangles.empty()) return Error{"mesh: " + path + ": has no triangles"};
  Vec3 lo(1e300), hi(-1e300);
  for (const Vec3& x : mesh.vertices) {
    lo = glm::min(lo, x);
    hi = glm::max(hi, x);
  }
  const Real extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(extent > 0.0)) return Error{"mesh: " + path + ": all vertices coincide"};
  const Vec3 middle = 0.5 * (lo + hi);
  for (Vec3& x : mesh.vertices) x = center + (x - middle) * (size / extent);
  return mesh;
}

}  // namespace pba::lab
