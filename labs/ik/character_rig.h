#pragma once
// The IK lab's bridge from an imported model (graphics/model.h: any skeleton Assimp reads: BVH, FBX,
// COLLADA, glTF) to the physics Skeleton (app layer: the physics library never sees Assimp).
//
// Conversion. Every node of the model becomes a joint, parents first. Rest frames come from the
// nodes' global bind transforms (scale and shear removed), so a joint's offset is its rest position
// in the parent's rotated frame, i.e. the bone length comes from the node offsets. The root is pinned
// (Fixed: the character stands where the file puts it), nodes with a child at a distinct position are
// ball joints with ±limit on each Euler angle, the rest (end sites, helper nodes) are Fixed. The
// trunk joints above several effectors get DOF weight 0.1 (the limbs reach, the body stays upright). The
// whole skeleton is scaled so that its rest pose is `height` tall (files come in m, cm or inches)
// and placed with its lowest joint on the ground and its root above the origin.
//
// Effectors are joints named in a comma-separated list; an empty list picks them from the names:
// the topmost joints whose name contains "hand" or "foot" (case-insensitive), else every leaf.
#include <string>
#include <vector>

#include "physics/core/result.h"
#include "physics/ik/builders.h"

namespace pba::labs::ik {

struct CharacterDesc {
  std::string skeleton = "resources/models/humanoid.bvh";  ///< file path; relative paths also tried from the repository root
  std::string effectors;                                   ///< "LeftHand,RightFoot"; empty = hands and feet by name
  double height = 1.7;                                     ///< [m] height of the rest pose after scaling
  double limit = 100.0 * kPi / 180.0;                                    ///< [rad] every ball DOF in [−limit, limit]
};

/// The path as given when it exists, else relative to the repository root (PBA_RESOURCE_DIR/..).
std::string resolveModelPath(const std::string& path);

/// Splits "a, b,c" into {"a", "b", "c"} (blanks trimmed, empty names dropped).
std::vector<std::string> splitNames(const std::string& list);

/// Loads and converts. Errors: "skeleton: <path>: <Assimp's message>", "skeleton: <path>: has no
/// joints", "effectors: no joint named 'x' in <path> (joints: a, b, c, ...)".
Result<pba::ik::Rig> loadCharacterRig(const CharacterDesc& desc);

}  // namespace pba::labs::ik
