#include "app/assets/character_skin.h"

#include <algorithm>

#include "graphics/skinning.h"

namespace pba::app {

CharacterSkin makeCharacterSkin(const graphics::Model& model, Real scale, const Vec3& shift,
                                const std::vector<Quat>& restRotations) {
  CharacterSkin skin;
  const bool hasMesh = std::any_of(model.meshes.begin(), model.meshes.end(),
                                   [](const graphics::ModelMesh& m) { return !m.placeholder; });
  if (!hasMesh || restRotations.size() != model.nodes.size()) return skin;
  skin.model = std::make_shared<const graphics::Model>(model);
  skin.scale = scale;
  skin.shift = shift;
  const std::vector<glm::mat4> global = graphics::globalTransforms(model, graphics::restPose(model));
  for (size_t i = 0; i < model.nodes.size(); ++i)
    skin.shape.push_back(glm::mat3_cast(glm::inverse(restRotations[i])) * Mat3(glm::dmat4(global[i])));
  return skin;
}

int meshCount(const CharacterSkin& skin) {
  if (!skin.model) return 0;
  return static_cast<int>(std::count_if(skin.model->meshes.begin(), skin.model->meshes.end(),
                                        [](const graphics::ModelMesh& m) { return !m.placeholder; }));
}

std::vector<SkinSurface> poseSkin(const CharacterSkin& skin, const std::vector<Vec3>& positions,
                                  const std::vector<Quat>& rotations) {
  std::vector<SkinSurface> out;
  if (!skin.model || positions.size() != skin.model->nodes.size() || rotations.size() != positions.size()) return out;
  const graphics::Model& model = *skin.model;
  // Node globals in model space: the joint frames with the file's scale and shear put back.
  std::vector<glm::mat4> global(positions.size());
  for (size_t n = 0; n < positions.size(); ++n) {
    const Mat3 linear = glm::mat3_cast(rotations[n]) * skin.shape[n];
    glm::dmat4 g(linear);
    g[3] = glm::dvec4(positions[n] / skin.scale - skin.shift, 1.0);
    global[n] = glm::mat4(g);
  }
  const std::vector<glm::mat4> skinning = graphics::skinningMatrices(model, global);
  for (size_t m = 0; m < model.meshes.size(); ++m) {
    const graphics::ModelMesh& mesh = model.meshes[m];
    if (mesh.placeholder) continue;
    SkinSurface s;
    s.mesh = m;
    std::vector<glm::vec3> p, nrm;
    if (mesh.skinned()) {
      p = graphics::skinPositions(mesh, skinning);
      nrm = graphics::skinNormals(mesh, skinning);
    } else {  // rigid: follows the node that instances it
      const glm::mat4 g = mesh.node >= 0 ? global[static_cast<size_t>(mesh.node)] : glm::mat4(1.0f);
      for (const glm::vec3& v : mesh.positions) p.push_back(glm::vec3(g * glm::vec4(v, 1.0f)));
      for (const glm::vec3& v : mesh.normals) nrm.push_back(glm::normalize(glm::mat3(g) * v));
    }
    for (const glm::vec3& v : p) s.positions.push_back(skin.scale * (Vec3(v) + skin.shift));
    for (const glm::vec3& v : nrm) s.normals.push_back(Vec3(v));
    s.indices = mesh.indices;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace pba::app
