#include "clip_import.h"

#include <algorithm>
#include <filesystem>
#include <unordered_map>

#include "app/runner/resource_dir.h"
#include "bvh_import.h"
#include "graphics/model.h"
#include "graphics/skinning.h"

namespace pba::lab {

namespace an = pba::animation;

std::string resolveResourcePath(const std::string& path) { return app::resolveRepositoryPath(path); }

namespace {

Quat rotationOf(const glm::mat4& m) {
  glm::dmat3 r(m);
  for (int c = 0; c < 3; ++c) r[c] = glm::normalize(r[c]);  // drop the scale
  return glm::normalize(glm::quat_cast(r));
}

/// Largest extent of the rest pose's joint positions [file units].
Real restExtent(const graphics::Model& model) {
  const std::vector<glm::mat4> g = graphics::globalTransforms(model, graphics::restPose(model));
  Vec3 lo(1e300), hi(-1e300);
  for (const glm::mat4& m : g) {
    const Vec3 p(m[3]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
}

/// Replaces the skeleton's offsets and the clip's keys of a .bvh file, which the graphics import has
/// read and checked (its messages name every malformed file), by the double-precision reader's
/// (bvh_import.h): Assimp keeps the keys in float. The two must agree on the joints (tested).
Status useDoubleKeys(const std::string& path, Real height, const std::string& field, ImportedClip& out) {
  Result<BvhClip> read = readBvh(path);
  if (!read) return Error{field + ": " + read.error()};
  BvhClip& b = read.value();
  if (b.skeleton.names != out.skeleton.names || b.skeleton.parents != out.skeleton.parents)
    return Error{field + ": " + path + ": the BVH reader and the model import disagree on the joints"};
  if (b.clip.frames < 2 || !(b.clip.duration > 0.0))
    return Error{field + ": " + path + ": has no animation (a clip needs keyframes)"};
  // Rest rotations are the identity: a joint's rest position is the sum of the offsets above it.
  std::vector<Vec3> rest(b.skeleton.restTranslations.size());
  Vec3 lo(1e300), hi(-1e300);
  for (size_t j = 0; j < rest.size(); ++j) {
    const int p = b.skeleton.parents[j];
    rest[j] = (p < 0 ? Vec3(0.0) : rest[static_cast<size_t>(p)]) + b.skeleton.restTranslations[j];
    lo = glm::min(lo, rest[j]);
    hi = glm::max(hi, rest[j]);
  }
  const Real extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  out.scale = extent > 1e-9 ? height / extent : 1.0;
  out.skeleton = std::move(b.skeleton);
  for (Vec3& t : out.skeleton.restTranslations) t *= out.scale;
  const std::string name = out.clip.name;
  out.clip = std::move(b.clip);
  out.clip.name = name;
  for (an::JointTrack& t : out.clip.tracks)
    for (int k = 0; k < t.translation.size(); ++k) t.translation.setValue(k, out.scale * t.translation.value(k));
  return Status::success();
}

}  // namespace

Result<ImportedClip> importClip(const std::string& file, Real height, const std::string& field) {
  if (!(height > 0.0)) return Error{"height: must be > 0"};
  const std::string path = resolveResourcePath(file);
  if (path.empty()) return Error{field + ": no file given"};
  std::string error;
  const std::optional<graphics::Model> model = graphics::loadModel(path, &error);
  if (!model) return Error{field + ": " + error};
  if (model->nodes.empty()) return Error{field + ": " + path + ": has no joints"};
  // Assimp matches a channel to its joint by name: two joints of one name would share one channel.
  std::unordered_map<std::string, size_t> seen;
  for (size_t i = 0; i < model->nodes.size(); ++i) {
    const std::string& name = model->nodes[i].name;
    if (const auto [it, fresh] = seen.emplace(name, i); !fresh && !name.empty())
      return Error{field + ": " + path + ": joint name '" + name + "' is used by joints " + std::to_string(it->second) +
                   " and " + std::to_string(i) + " (names must be unique)"};
  }
  if (model->animations.empty() || model->animations[0].channels.empty() || !(model->animations[0].duration > 0.0f))
    return Error{field + ": " + path + ": has no animation (a clip needs keyframes)"};
  ImportedClip out;
  out.path = path;
  const Real extent = restExtent(*model);
  out.scale = extent > 1e-9 ? height / extent : 1.0;
  std::vector<Quat> restWorld;  // R_i = R_parent · q_i of the rest pose, for the skin
  for (const graphics::ModelNode& n : model->nodes) {
    out.skeleton.add(n.name, n.parent, out.scale * Vec3(n.local[3]), rotationOf(n.local));
    const Quat q = out.skeleton.restRotations.back();
    restWorld.push_back(n.parent < 0 ? q : glm::normalize(restWorld[static_cast<size_t>(n.parent)] * q));
  }
  out.skin = app::makeCharacterSkin(*model, out.scale, Vec3(0.0), restWorld);
  const graphics::Animation& a = model->animations[0];
  an::Clip& clip = out.clip;
  clip.name = a.name.empty() ? "clip" : a.name;
  clip.duration = a.duration;
  clip.tracks.resize(model->nodes.size());
  for (const graphics::NodeChannel& c : a.channels) {
    if (c.node < 0 || c.node >= static_cast<int>(clip.tracks.size())) continue;
    an::JointTrack& t = clip.tracks[static_cast<size_t>(c.node)];
    const std::string where = field + ": " + path + ": channel of " + model->nodes[static_cast<size_t>(c.node)].name;
    for (const auto& k : c.positions)
      if (const Result<int> r = t.translation.insert(k.time, out.scale * Vec3(k.value)); !r.ok())
        return Error{where + ": " + r.error()};
    for (const auto& k : c.rotations)
      if (const Result<int> r = t.rotation.insert(k.time, glm::normalize(Quat(k.value))); !r.ok())
        return Error{where + ": " + r.error()};
    clip.frames = std::max({clip.frames, static_cast<int>(c.positions.size()), static_cast<int>(c.rotations.size())});
  }
  if (isBvhPath(path)) {
    if (Status s = useDoubleKeys(path, height, field, out); !s.ok()) return Error{s.error()};
  }
  if (Status s = an::validate(out.clip, out.skeleton, path); !s.ok()) return Error{field + ": " + s.error()};
  return out;
}

}  // namespace pba::lab
