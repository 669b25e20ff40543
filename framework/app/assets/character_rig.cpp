#include "app/assets/character_rig.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <unordered_map>

#include <glm/gtc/matrix_transform.hpp>

#include "app/runner/resource_dir.h"
#include "graphics/model.h"

namespace pba::app {

using namespace pba::ik;

namespace {

constexpr size_t kMaxJoints = 1000;                  // the chain scene's largest chain: solves stay interactive
constexpr size_t kMaxEffectors = 64;                 // rows of the Jacobian: 3 per effector
constexpr int kListedJoints = 40;                    // joint names listed in an error message before "..."
constexpr Real kTrunkWeight = 0.1;                   // [1] DOF weight of joints above several effectors
constexpr Real kTrunkLimit = 15.0 * kPi / 180.0;     // [rad] per Euler angle of those trunk joints
constexpr Real kClavicleLimit = 30.0 * kPi / 180.0;  // [rad] per Euler angle of a clavicle

/// Narrows every DOF of a ball joint to [−limit, limit] (never widens it).
void clampRange(Joint& joint, Real limit) {
  for (int k = 0; k < 3; ++k) joint.lo[k] = std::max(joint.lo[k], -limit), joint.hi[k] = std::min(joint.hi[k], limit);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

struct RestFrame {
  Vec3 position{0.0};
  Quat rotation{1, 0, 0, 0};
};

/// Global rest frames of the nodes: positions from the full transforms, rotations with scale removed.
std::vector<RestFrame> restFrames(const graphics::Model& m) {
  std::vector<glm::dmat4> global(m.nodes.size());
  std::vector<RestFrame> frames(m.nodes.size());
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    const glm::dmat4 local(m.nodes[i].local);
    global[i] = m.nodes[i].parent >= 0 ? global[static_cast<size_t>(m.nodes[i].parent)] * local : local;
    frames[i].position = Vec3(global[i][3]);
    Mat3 r(global[i]);
    for (int c = 0; c < 3; ++c) {
      const Real len = glm::length(r[c]);
      r[c] = len > 1e-12 ? r[c] / len : Vec3(c == 0, c == 1, c == 2);
    }
    frames[i].rotation = glm::normalize(glm::quat_cast(r));
  }
  return frames;
}

std::string jointList(const Skeleton& s) {
  std::string list;
  for (int j = 0; j < s.jointCount() && j < kListedJoints; ++j) list += (j ? ", " : "") + s.joint(j).name;
  if (s.jointCount() > kListedJoints) list += ", ...";
  return list;
}

/// Hands and feet by name (topmost match on each branch), else the leaves.
std::vector<int> automaticEffectors(const Skeleton& s) {
  std::vector<int> picked;
  std::vector<char> matched(static_cast<size_t>(s.jointCount()), 0);
  for (int j = 0; j < s.jointCount(); ++j) {
    const std::string n = lower(s.joint(j).name);
    const int p = s.joint(j).parent;
    const bool ancestorMatched = p >= 0 && matched[static_cast<size_t>(p)];
    matched[static_cast<size_t>(j)] =
        ancestorMatched || n.find("hand") != std::string::npos || n.find("foot") != std::string::npos;
    if (matched[static_cast<size_t>(j)] && !ancestorMatched) picked.push_back(j);
  }
  if (picked.empty())
    for (int j = 1; j < s.jointCount(); ++j)
      if (s.children(j).empty()) picked.push_back(j);
  return picked;
}

/// The name without a namespace prefix ("mixamorig:LeftLeg" → "leftleg"), lower-case.
std::string bareName(const std::string& name) {
  const size_t colon = name.find_last_of(":|");
  return lower(colon == std::string::npos ? name : name.substr(colon + 1));
}

bool contains(const std::string& s, const char* part) { return s.find(part) != std::string::npos; }

/// Model-space vector [file units] from node i to its first child at a distinct position.
std::optional<Vec3> firstBone(const graphics::Model& m, const std::vector<RestFrame>& rest, size_t i, Real scale) {
  for (size_t c = i + 1; c < m.nodes.size(); ++c)
    if (m.nodes[c].parent == static_cast<int>(i) && glm::length(rest[c].position - rest[i].position) * scale > 1e-6)
      return rest[c].position - rest[i].position;
  return std::nullopt;
}

/// Knees and elbows by name; when no name matches, the parents of the topmost "hand" (elbow) and
/// "foot" (knee) nodes: in BVH, Mixamo and CMU files the joint above the wrist is the elbow.
std::vector<LimbJoint> limbJoints(const graphics::Model& m) {
  std::vector<LimbJoint> limbs(m.nodes.size(), LimbJoint::None);
  bool any = false;
  for (size_t i = 0; i < m.nodes.size(); ++i)
    any = (limbs[i] = limbJointFromName(m.nodes[i].name)) != LimbJoint::None || any;
  if (any) return limbs;
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    const int p = m.nodes[i].parent;
    if (p < 0) continue;
    const std::string n = bareName(m.nodes[i].name), pn = bareName(m.nodes[static_cast<size_t>(p)].name);
    if (contains(n, "hand") && !contains(pn, "hand")) limbs[static_cast<size_t>(p)] = LimbJoint::Elbow;
    if (contains(n, "foot") && !contains(pn, "foot")) limbs[static_cast<size_t>(p)] = LimbJoint::Knee;
  }
  return limbs;
}

/// The direction the character faces (model space, horizontal, unit): lateral × up, where lateral
/// sums "left…" minus "right…" joint positions of the pairs with matching names; +z without pairs.
Vec3 facingDirection(const graphics::Model& m, const std::vector<RestFrame>& rest) {
  Vec3 lateral(0.0);
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    const std::string n = bareName(m.nodes[i].name);
    const size_t at = n.find("left");
    if (at == std::string::npos) continue;
    const std::string mirrored = n.substr(0, at) + "right" + n.substr(at + 4);
    for (size_t k = 0; k < m.nodes.size(); ++k)
      if (bareName(m.nodes[k].name) == mirrored) lateral += rest[i].position - rest[k].position;
  }
  lateral.y = 0.0;
  if (glm::length(lateral) < 1e-9) return Vec3(0, 0, 1);
  return glm::normalize(glm::cross(lateral, Vec3(0, 1, 0)));
}

}  // namespace

LimbJoint limbJointFromName(const std::string& name) {
  const std::string n = bareName(name);
  // Elbows: "elbow", Mixamo/CMU/BVH "ForeArm", "LowerArm" (Unity/VRM humanoids).
  if (contains(n, "elbow") || contains(n, "forearm") || contains(n, "lowerarm") || contains(n, "lower_arm"))
    return LimbJoint::Elbow;
  // Knees: "knee", "shin", "calf", "LowerLeg", and the Mixamo/CMU convention "LeftLeg" (the shin;
  // "LeftUpLeg" is the thigh). "leg" alone is a knee unless it says up/upper/thigh.
  if (contains(n, "knee") || contains(n, "shin") || contains(n, "calf") || contains(n, "lowerleg") ||
      contains(n, "lower_leg"))
    return LimbJoint::Knee;
  if (n.size() >= 3 && n.compare(n.size() - 3, 3, "leg") == 0 && !contains(n, "up") && !contains(n, "thigh"))
    return LimbJoint::Knee;
  return LimbJoint::None;
}

std::string resolveModelPath(const std::string& path) { return app::resolveRepositoryPath(path); }

std::vector<std::string> splitNames(const std::string& list) {
  std::vector<std::string> names;
  size_t start = 0;
  while (start <= list.size()) {
    size_t end = list.find(',', start);
    if (end == std::string::npos) end = list.size();
    std::string name = list.substr(start, end - start);
    const auto blank = [](unsigned char c) { return std::isspace(c) != 0; };
    name.erase(name.begin(), std::find_if_not(name.begin(), name.end(), blank));
    name.erase(std::find_if_not(name.rbegin(), name.rend(), blank).base(), name.end());
    if (!name.empty()) names.push_back(name);
    start = end + 1;
  }
  return names;
}

Result<Rig> loadCharacterRig(const CharacterDesc& d, CharacterSkin* skin) {
  const std::string path = resolveModelPath(d.skeleton);
  if (path.empty()) return Error{"skeleton: no file given"};
  std::string error;
  const std::optional<graphics::Model> model = graphics::loadModel(path, &error);
  if (!model) return Error{"skeleton: " + error};
  if (model->nodes.empty()) return Error{"skeleton: " + path + ": has no joints"};
  if (model->nodes.size() > kMaxJoints)
    return Error{"skeleton: " + path + ": has " + std::to_string(model->nodes.size()) +
                 " joints; the character scene takes at most " + std::to_string(kMaxJoints)};
  // Effectors, the panel and scene files name joints: two joints of one name would be one of them.
  std::unordered_map<std::string, size_t> seen;
  for (size_t i = 0; i < model->nodes.size(); ++i) {
    const std::string& name = model->nodes[i].name;
    if (const auto [it, fresh] = seen.emplace(name, i); !fresh && !name.empty())
      return Error{"skeleton: " + path + ": joint name '" + name + "' is used by joints " + std::to_string(it->second) +
                   " and " + std::to_string(i) + " (names must be unique)"};
  }
  const std::vector<RestFrame> rest = restFrames(*model);

  // Scale to the requested height; lowest joint on the ground, root above the origin.
  Vec3 lo(1e300), hi(-1e300);
  for (const RestFrame& f : rest) lo = glm::min(lo, f.position), hi = glm::max(hi, f.position);
  const Real extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const Real scale = extent > 1e-9 ? d.height / extent : 1.0;
  const Vec3 shift(-rest[0].position.x, -lo.y, -rest[0].position.z);

  const std::vector<LimbJoint> limbs = limbJoints(*model);
  const Vec3 forward = facingDirection(*model, rest);
  Rig rig;
  for (size_t i = 0; i < model->nodes.size(); ++i) {
    const graphics::ModelNode& node = model->nodes[i];
    Joint j;
    j.name = node.name.empty() ? "node" + std::to_string(i) : node.name;
    j.parent = node.parent;
    if (node.parent < 0) {
      j.offset = scale * (rest[i].position + shift);
      j.restRotation = rest[i].rotation;
    } else {
      const RestFrame& p = rest[static_cast<size_t>(node.parent)];
      j.offset = scale * (glm::inverse(p.rotation) * (rest[i].position - p.position));
      j.restRotation = glm::normalize(glm::inverse(p.rotation) * rest[i].rotation);
    }
    const std::optional<Vec3> bone = firstBone(*model, rest, i, scale);
    j.type = node.parent >= 0 && bone ? JointType::Ball : JointType::Fixed;
    for (int k = 0; k < 3; ++k) j.lo[k] = -d.limit, j.hi[k] = d.limit;
    // Clavicles ("LeftShoulder" in BVH, Mixamo and CMU files; "Collar", "Clavicle") barely move.
    if (const std::string n = bareName(j.name);
        j.type == JointType::Ball && (contains(n, "shoulder") || contains(n, "clavicle") || contains(n, "collar")))
      clampRange(j, kClavicleLimit);
    if (j.type == JointType::Ball && limbs[i] != LimbJoint::None) {
      // Flexion axis (world, at rest): elbow bone × forward, knee forward × bone; then in the
      // joint's pre-rotation frame, which at rest is the node's global rotation.
      const Vec3 b = glm::normalize(*bone);
      const Vec3 axis = limbs[i] == LimbJoint::Elbow ? glm::cross(b, forward) : glm::cross(forward, b);
      if (glm::length(axis) > 0.1) {  // a limb along the facing direction keeps its ball joint
        j.type = JointType::Hinge;
        j.axis = glm::normalize(glm::inverse(rest[i].rotation) * glm::normalize(axis));
        j.lo[0] = kHingeFlexMin;
        j.hi[0] = kHingeFlexMax;
      }
    }
    if (Result<int> added = rig.skeleton.add(j); !added)
      return Error{"skeleton: " + path + ": joint '" + j.name + "': " + added.error()};
  }

  if (std::none_of(rig.skeleton.joints().begin(), rig.skeleton.joints().end(),
                   [](const Joint& j) { return j.type != JointType::Fixed; }))
    return Error{"skeleton: " + path + ": no joint can move (" + std::to_string(rig.skeleton.jointCount()) +
                 " nodes and no bone between two of them: is it a skeleton?)"};

  std::vector<int> chosen;
  const std::vector<std::string> names = splitNames(d.effectors);
  for (const std::string& name : names) {
    const int j = rig.skeleton.find(name);
    if (j < 0)
      return Error{"effectors: no joint named '" + name + "' in " + path + " (joints: " + jointList(rig.skeleton) +
                   ")"};
    chosen.push_back(j);
  }
  if (names.empty()) chosen = automaticEffectors(rig.skeleton);
  if (chosen.size() > kMaxEffectors)
    return Error{"effectors: " + std::to_string(chosen.size()) + " effectors in " + path + "; at most " +
                 std::to_string(kMaxEffectors) + " (name them with --effectors)"};
  const Pose restPose = rig.skeleton.restPose();
  const std::vector<Frame> frames = forwardKinematics(rig.skeleton, restPose);
  for (int j : chosen) {
    Effector e;
    e.joint = j;
    e.targetPosition = frames[static_cast<size_t>(j)].position;
    rig.effectors.push_back(e);
  }
  // Trunk joints shared by several effectors (spine, chest) get a small weight, so the limbs do the
  // reaching and the body stays upright (IK slides, "Units": weights scale the Jacobian columns).
  const std::vector<std::vector<int>> below = effectorsBelowJoints(rig.skeleton, rig.effectors);
  // They also bend at most kTrunkLimit per Euler angle: without it, the small steps of a low weight
  // still add up over the frames of a moving goal, and the spine ends up folded.
  for (int j = 0; j < rig.skeleton.jointCount(); ++j) {
    Joint& joint = rig.skeleton.joint(j);
    if (below[static_cast<size_t>(j)].size() > 1) {
      for (Real& w : joint.weight) w = kTrunkWeight;
      if (joint.type == JointType::Ball) clampRange(joint, kTrunkLimit);
    }
  }
  if (skin) {
    std::vector<Quat> restRotations;
    for (const RestFrame& f : rest) restRotations.push_back(f.rotation);
    *skin = app::makeCharacterSkin(*model, scale, shift, restRotations);
  }
  return rig;
}

}  // namespace pba::app
