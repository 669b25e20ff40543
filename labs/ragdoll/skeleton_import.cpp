#include "skeleton_import.h"

#include <algorithm>

#include "app/assets/character_rig.h"  // resolveModelPath, shared with the IK lab
#include "graphics/model.h"
#include "graphics/skinning.h"

namespace pba::lab {

namespace {

/// The channel with the most keys sets the frames (BVH: every joint has one key a frame).
const graphics::NodeChannel* longestChannel(const graphics::Model& m) {
  if (m.animations.empty()) return nullptr;
  const graphics::NodeChannel* best = nullptr;
  for (const graphics::NodeChannel& c : m.animations[0].channels)
    if (!best || c.rotations.size() > best->rotations.size()) best = &c;
  return best && !best->rotations.empty() ? best : nullptr;
}

std::vector<Vec3> positionsOf(const std::vector<glm::mat4>& global) {
  std::vector<Vec3> p;
  p.reserve(global.size());
  for (const glm::mat4& g : global) p.emplace_back(Vec3(g[3]));
  return p;
}

}  // namespace

Result<LoadedSkeleton> loadSkeleton(const SkeletonFile& file) {
  const std::string path = app::resolveModelPath(file.path);
  if (path.empty()) return Error{"skeleton: no file given"};
  std::string error;
  const std::optional<graphics::Model> model = graphics::loadModel(path, &error);
  if (!model) return Error{"skeleton: " + error};
  if (model->nodes.empty()) return Error{"skeleton: " + path + ": has no joints"};
  LoadedSkeleton out;
  const graphics::NodeChannel* channel = longestChannel(*model);
  out.frames = channel ? static_cast<int>(channel->rotations.size()) : 0;
  const int frame = file.clampFrame ? std::min(file.frame, out.frames - 1) : file.frame;
  if (frame >= out.frames && frame >= 0)
    return Error{"frame: " + path + " has " + std::to_string(out.frames) + " frames (0 ... " +
                 std::to_string(std::max(out.frames - 1, 0)) + "); -1 is the rest pose"};

  const std::vector<Vec3> rest = positionsOf(graphics::globalTransforms(*model, graphics::restPose(*model)));
  const std::vector<Vec3> posed =
      frame < 0 ? rest
                : positionsOf(graphics::globalTransforms(
                      *model, graphics::sampleAnimation(*model, model->animations[0],
                                                        channel->rotations[static_cast<size_t>(frame)].time, false)));
  // The rest pose sets the scale (every frame of a file gets the same size).
  Vec3 lo(1e300), hi(-1e300);
  for (const Vec3& p : rest) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const Real extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const Real scale = extent > 1e-9 ? file.height / extent : 1.0;
  Real lowest = 1e300;
  for (const Vec3& p : posed) lowest = std::min(lowest, p.y);
  const Vec3 shift(-posed[0].x, -lowest, -posed[0].z);
  for (size_t i = 0; i < model->nodes.size(); ++i) {
    const graphics::ModelNode& n = model->nodes[i];
    out.joints.push_back({n.name.empty() ? "node" + std::to_string(i) : n.name, n.parent, scale * (posed[i] + shift)});
    if (!isFinite(out.joints.back().position))
      return Error{"skeleton: " + path + ": joint '" + out.joints.back().name + "' position is not finite"};
  }
  return out;
}

}  // namespace pba::lab
