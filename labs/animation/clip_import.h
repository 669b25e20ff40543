#pragma once
// The animation lab's bridge from an imported model (graphics/model.h: BVH, FBX, COLLADA, glTF
// through Assimp) to the physics library's Skeleton and Clip (the library never sees Assimp).
//
// Every node becomes a joint, parents first, with its rest local transform split into translation
// and rotation (scale dropped). The file's first animation becomes the clip: position keys → the
// joint's translation channel (linear), rotation keys → its rotation channel (slerp), times in
// seconds. The whole character is scaled by `height` / (the rest pose's largest extent), so files in
// centimetres, inches or metres all play at human size; no other offset is applied. A file with meshes
// (skinned or rigid, e.g. Debian assimp-testmodels' X/BCN_Epileptic.X) keeps them as the clip's skin.
#include <string>

#include "app/assets/character_skin.h"
#include "physics/animation/clip.h"
#include "physics/core/result.h"

namespace pba::lab {

struct ImportedClip {
  pba::animation::Skeleton skeleton;
  pba::animation::Clip clip;
  Real scale = 1.0;  ///< [m per file unit]
  std::string path;  ///< the file as opened
  /// The file's meshes for the skeleton's joint frames (app/assets/character_skin.h; joint j is node j), or an
  /// empty skin (null model) when the file has none, as BVH files never do.
  app::CharacterSkin skin;
};

/// The path as given when it exists, else relative to the repository root (app::repositoryRoot()).
std::string resolveResourcePath(const std::string& path);

/// Errors name the field and the file: "skeleton: x.bvh: <Assimp's message>", "skeleton: x.obj: has
/// no animation (a clip needs keyframes)", "height: must be > 0".
Result<ImportedClip> importClip(const std::string& path, Real height, const std::string& field = "skeleton");

}  // namespace pba::lab
