#include "app/lab_session.h"

#include "app/scene_file.h"
#include "app/scene_registry.h"

namespace pba::app {

LabSession::LabSession(std::string lab, SceneRunner& runner, std::uint64_t seed)
    : lab_(std::move(lab)), runner_(runner), seed_(seed) {}

void LabSession::togglePause() {
  if (runner_.guardMessage()) {
    message_ = "The instability guard paused the scene: press R to reset.";
    return;
  }
  runner_.setPaused(!runner_.paused());
  message_ = runner_.paused() ? "Paused" : "Running";
}

void LabSession::singleStep() {
  runner_.setPaused(true);
  runner_.singleStep();
  message_ = "Single step";
}

void LabSession::reset() {
  runner_.reset();
  plots_.clear();
  message_ = "Reset";
}

int LabSession::sceneIndex() const { return app::sceneIndex(runner_.sceneName()); }

void LabSession::switchScene(int index) {
  const int count = static_cast<int>(scenes().size());
  if (count == 0) return;
  index = ((index % count) + count) % count;
  const bool wasPaused = runner_.paused();
  if (Status s = runner_.load(scenes()[static_cast<size_t>(index)].name, seed_); !s) {
    message_ = s.error();
    return;
  }
  runner_.setPaused(wasPaused);
  sceneChanged();
}

void LabSession::nextScene(int delta) { switchScene(sceneIndex() + delta); }

void LabSession::applyPreset(int index) {
  const std::vector<Preset> presets = runner_.scene().presets();
  if (index < 0 || index >= static_cast<int>(presets.size())) {
    message_ = "This scene has no preset " + std::to_string(index + 1);
    return;
  }
  const Preset& preset = presets[static_cast<size_t>(index)];
  const Result<nlohmann::json> values = presetParams(runner_.sceneName(), preset);
  if (!values) {
    message_ = values.error();
    return;
  }
  if (Status s = applyParams(runner_.scene(), values.value(), "preset " + preset.name); !s) {
    message_ = s.error();
    return;
  }
  runner_.reset();
  plots_.clear();
  message_ = "Preset " + std::to_string(index + 1) + ": " + preset.name;
}

void LabSession::drag(int handle, const Vec3& target) {
  runner_.scene().drag(handle, target);
  if (runner_.paused()) runner_.scene().refresh();
}

void LabSession::release(int handle) {
  runner_.scene().release(handle);
  if (runner_.paused()) runner_.scene().refresh();
}

bool LabSession::nudge(NudgeDirection direction, const Vec3& right, const Vec3& up, const Vec3& forward, Real sceneSize,
                       bool fine) {
  if (!nudgeScene(runner_.scene(), direction, right, up, forward, sceneSize, fine)) return false;
  if (runner_.paused()) runner_.scene().refresh();
  return true;
}

bool LabSession::loadSceneFile(const std::string& path) {
  Result<LoadedScene> loaded = app::loadSceneFile(path, lab_);
  if (!loaded) {
    fileError_ = loaded.error();
    message_ = "Could not load the scene file; the current scene keeps running.";
    return false;
  }
  LoadedScene& scene = loaded.value();
  if (Status s = scene.scene->validate(); !s) {
    fileError_ = path + ": " + s.error();
    message_ = "Could not load the scene file; the current scene keeps running.";
    return false;
  }
  if (scene.dt) runner_.setDt(*scene.dt);
  scene.scene->setSeed(seed_);
  runner_.adopt(std::move(scene.scene), scene.name);
  fileError_.clear();
  message_ = "Loaded " + path;
  sceneChanged();
  return true;
}

bool LabSession::saveSceneFile(const std::string& path) {
  if (Status s = app::saveSceneFile(path, lab_, runner_.sceneName(), runner_.scene(), runner_.dt()); !s) {
    fileError_ = s.error();
    return false;
  }
  fileError_.clear();
  message_ = "Saved " + path;
  return true;
}

void LabSession::recordPlots() { plots_.record(runner_.simTime(), runner_.scene().metrics()); }

bool LabSession::takeFrameRequest() {
  const bool requested = frameRequested_;
  frameRequested_ = false;
  return requested;
}

void LabSession::sceneChanged() {
  plots_.clear();
  settings_.lastScene = runner_.sceneName();
  frameRequested_ = true;
}

}  // namespace pba::app
