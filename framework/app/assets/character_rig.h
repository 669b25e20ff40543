#pragma once
// The bridge from an imported model (graphics/model.h: any skeleton Assimp reads: BVH, FBX,
// COLLADA, glTF) to the physics Skeleton, shared by the IK lab's character scenes and the ragdoll lab's
// imported figures (app layer: the physics library never sees Assimp).
//
// Conversion. Every node of the model becomes a joint, parents first. Rest frames come from the
// nodes' global bind transforms (scale and shear removed), so a joint's offset is its rest position
// in the parent's rotated frame, i.e. the bone length comes from the node offsets. The root is pinned
// (Fixed: the character stands where the file puts it), nodes with a child at a distinct position are
// ball joints with ±limit on each Euler angle, except knees and elbows (limbJointFromName(); when no
// name matches, the parents of the hand and foot joints), which are hinges: flexion about the axis
// bone × forward (elbow: the forearm swings to the front, in [−5°, 150°]) or forward × bone (knee:
// the shin swings to the back, same range), where forward is the character's facing direction
// estimated from its Left*/Right* joints (lateral × up; +z when it has none). The rest (end sites,
// helper nodes) are Fixed. Clavicles ("Shoulder", "Collar", "Clavicle") turn at most ±30°. The
// trunk joints above several effectors get DOF weight 0.1 and at most ±15° per Euler angle (the limbs
// reach, the body stays upright). The
// whole skeleton is scaled so that its rest pose is `height` tall (files come in m, cm or inches)
// and placed with its lowest joint on the ground and its root above the origin.
//
// Effectors are joints named in a comma-separated list; an empty list picks them from the names:
// the topmost joints whose name contains "hand" or "foot" (case-insensitive), else every leaf.
#include <string>
#include <vector>

#include "app/assets/character_skin.h"
#include "graphics/model.h"

#include "physics/core/result.h"
#include "physics/ik/builders.h"

namespace pba::app {

struct CharacterDesc {
  std::string skeleton =
      "resources/models/humanoid.bvh";  ///< file path; relative paths also tried from the repository root
  std::string effectors;                ///< "LeftHand,RightFoot"; empty = hands and feet by name
  double height = 1.7;                  ///< [m] height of the rest pose after scaling
  double limit = 100.0 * kPi / 180.0;   ///< [rad] every ball DOF in [−limit, limit]
};

inline constexpr double kHingeFlexMin = -5.0 * kPi / 180.0;   ///< [rad] a knee or elbow straightens slightly past rest
inline constexpr double kHingeFlexMax = 150.0 * kPi / 180.0;  ///< [rad] and flexes this far

enum class LimbJoint { None, Elbow, Knee };
/// Knee or elbow by the naming conventions of BVH, Mixamo and CMU files: "LeftForeArm",
/// "mixamorig:RightLeg" (the shin; "UpLeg" is the thigh), "l_knee", "LowerArm", "Calf", … .
LimbJoint limbJointFromName(const std::string& name);

/// The path as given when it exists, else relative to the repository root (app::repositoryRoot()).
std::string resolveModelPath(const std::string& path);

/// Splits "a, b,c" into {"a", "b", "c"} (blanks trimmed, empty names dropped).
std::vector<std::string> splitNames(const std::string& list);

/// Loads and converts; fills *skin when given (app/assets/character_skin.h: the file's meshes, skinned by
/// linear blend skinning with the solved joint frames; rigid meshes follow their node; joint j of the rig
/// is node j). Errors: "skeleton: <path>: <Assimp's message>",
/// "skeleton: <path>: has no joints", "effectors: no joint named 'x' in <path> (joints: a, b, c, ...)";
/// also refuses duplicate joint names, a file where no joint can move, more than 1,000 joints and more
/// than 64 effectors (the Jacobian would not fit in memory or time).
Result<pba::ik::Rig> loadCharacterRig(const CharacterDesc& desc, CharacterSkin* skin = nullptr);

}  // namespace pba::app
