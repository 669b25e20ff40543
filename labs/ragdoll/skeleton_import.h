#pragma once
// The ragdoll lab's bridge from a skeleton file (graphics/model.h: anything Assimp reads — BVH, FBX,
// COLLADA, glTF) to the library's SkeletonJoint list (physics/ragdoll/skeleton_ragdoll.h): names,
// parents and world positions, in the file's rest pose or in one frame of its first animation. The file
// path resolves as in the IK lab (app/assets/character_rig.h, resolveModelPath: also tried from the
// repository root). The skeleton is scaled so that its rest pose is `height` tall (files come in m, cm or
// inches) and moved so that its lowest joint is at y = 0 with the root above the origin.
#include <string>
#include <vector>

#include "physics/core/result.h"
#include "physics/ragdoll/skeleton_ragdoll.h"

namespace pba::lab {

struct SkeletonFile {
  std::string path = "resources/models/humanoid.bvh";  ///< as given; relative paths also from the repository root
  int frame = -1;                                      ///< frame of the first animation; −1: the rest pose
  bool clampFrame = false;                             ///< a frame past the last is the last (else an error)
  Real height = 1.7;                                   ///< [m] height of the rest pose after scaling
};

struct LoadedSkeleton {
  std::vector<pba::ragdoll::SkeletonJoint> joints;  ///< [m] world positions, lowest joint at y = 0
  int frames = 0;                                   ///< keyframes of the first animation (0: none)
};

/// Errors name the file: "skeleton: PATH: <Assimp's message>", "skeleton: PATH: has no joints",
/// "frame: PATH has N frames (0 … N−1)" (unless clampFrame).
Result<LoadedSkeleton> loadSkeleton(const SkeletonFile& file);

}  // namespace pba::lab
