#pragma once
// A character's meshes drawn over a skeleton that a lab poses on the CPU (the IK lab's character, the
// animation lab's mocap): linear blend skinning (graphics/skinning.h) by the joints' world frames.
//
// The skeleton has one joint per node of the imported model (joint j is node j) and places it at
//   world = scale · (model space + shift)
// with the node's rotation stripped of the file's scale and shear. `shape` puts them back: per node,
// R_rest⁻¹ · linear(G_rest), where R_rest is the joint's world rotation at rest in the skeleton and G_rest
// the node's global rest transform in the file. A posed node is then G = [R · shape | p / scale − shift],
// its skinning matrix G · offset, and a vertex v' = Σ wᵢ (G_bᵢ · offset_bᵢ) v.
#include <cstdint>
#include <memory>
#include <vector>

#include "graphics/model.h"
#include "physics/core/types.h"

namespace pba::app {

struct CharacterSkin {
  std::shared_ptr<const graphics::Model> model;  ///< null when the file has no mesh
  Real scale = 1.0;                              ///< [m per file unit] world = scale · (model space + shift)
  Vec3 shift{0.0};                               ///< [file units]
  std::vector<Mat3> shape;                       ///< per node: R_rest⁻¹ · linear(G_rest)
};

/// One mesh of the character in world space for the current pose.
struct SkinSurface {
  size_t mesh = 0;  ///< index in Model::meshes
  std::vector<Vec3> positions, normals;
  std::vector<std::uint32_t> indices;
};

/// The skin of `model` for a skeleton whose joint j, node j of the model, has world rotation
/// restRotations[j] at rest. An empty skin (null model) when the file has no mesh or the sizes differ.
CharacterSkin makeCharacterSkin(const graphics::Model& model, Real scale, const Vec3& shift,
                                const std::vector<Quat>& restRotations);

/// Meshes of the skin that are drawn (placeholders of mesh-less files left out).
int meshCount(const CharacterSkin& skin);

/// The meshes posed by the joints' world positions [m] and rotations, one per node.
std::vector<SkinSurface> poseSkin(const CharacterSkin& skin, const std::vector<Vec3>& positions,
                                  const std::vector<Quat>& rotations);

/// The same for any frame type with `position` and `rotation` (ik::Frame, animation::JointWorld).
template <typename Frame>
std::vector<SkinSurface> poseSkin(const CharacterSkin& skin, const std::vector<Frame>& frames) {
  std::vector<Vec3> p;
  std::vector<Quat> r;
  p.reserve(frames.size());
  r.reserve(frames.size());
  for (const Frame& f : frames) p.push_back(f.position), r.push_back(f.rotation);
  return poseSkin(skin, p, r);
}

}  // namespace pba::app
