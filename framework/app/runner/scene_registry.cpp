#include "app/runner/scene_registry.h"

#include <algorithm>

namespace pba::app {
namespace {
std::vector<SceneEntry>& mutableScenes() {
  static std::vector<SceneEntry> list;
  return list;
}
std::vector<LabFlag>& mutableFlags() {
  static std::vector<LabFlag> list;
  return list;
}
}  // namespace

const std::vector<SceneEntry>& scenes() { return mutableScenes(); }

bool registerScene(std::string category, std::string name, std::function<std::unique_ptr<Scene>()> create) {
  auto& list = mutableScenes();
  SceneEntry entry{std::move(category), std::move(name), std::move(create)};
  // Keep categories together while preserving registration order inside each one.
  auto last =
      std::find_if(list.rbegin(), list.rend(), [&](const SceneEntry& e) { return e.category == entry.category; });
  list.insert(last == list.rend() ? list.end() : last.base(), std::move(entry));
  return true;
}

const SceneEntry* findScene(const std::string& name) {
  for (const SceneEntry& e : scenes())
    if (e.name == name) return &e;
  return nullptr;
}

int sceneIndex(const std::string& name) {
  const auto& list = scenes();
  for (size_t i = 0; i < list.size(); ++i)
    if (list[i].name == name) return static_cast<int>(i);
  return -1;
}

const std::vector<LabFlag>& labFlags() { return mutableFlags(); }

bool registerLabFlag(std::string flag, std::string param, std::string help, std::string impliesScene, int priority) {
  mutableFlags().push_back({std::move(flag), std::move(param), std::move(help), std::move(impliesScene), priority});
  return true;
}

static std::vector<LabKey>& mutableKeys() {
  static std::vector<LabKey> keys;
  return keys;
}
const std::vector<LabKey>& labKeys() { return mutableKeys(); }
bool registerLabKey(char key, std::string scene, std::string action) {
  mutableKeys().push_back({key, std::move(scene), std::move(action)});
  return true;
}

}  // namespace pba::app
