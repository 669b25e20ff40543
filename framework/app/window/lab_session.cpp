#include "app/window/lab_session.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "app/runner/compare_run.h"
#include "app/runner/scene_file.h"
#include "app/runner/scene_registry.h"
#include "physics/core/format.h"

namespace pba::app {

LabSession::LabSession(std::string lab, SceneRunner& runner, std::uint64_t seed)
    : lab_(std::move(lab)), runner_(runner), seed_(seed) {
  restartHistory();
}

void LabSession::togglePause() {
  if (runner_.guardMessage()) {
    message_ = "The instability guard paused the scene: press R to reset.";
    return;
  }
  runner_.setPaused(!runner_.paused());
  if (partner_) partner_->setPaused(runner_.paused());
  if (!runner_.paused() && !history_.atNewest())
    message_ = "Running from t = " + formatFixed(runner_.simTime(), 3) + " s: the later frames are discarded";
  else
    message_ = runner_.paused() ? "Paused" : "Running";
}

void LabSession::singleStep() {
  runner_.setPaused(true);
  runner_.singleStep();
  if (partner_) {
    partner_->setPaused(true);
    partner_->singleStep();
  }
  afterFrame();
  message_ = "Single step";
}

void LabSession::reset() {
  // The guard's pause ends with the reset it asks for (R, as its banner says): the scene runs again. A
  // pause of the user's own stays.
  const bool guardPaused = runner_.guardMessage() || (partner_ && partner_->guardMessage());
  runner_.reset();
  if (partner_) partner_->reset();
  if (guardPaused) {
    runner_.setPaused(false);
    if (partner_) partner_->setPaused(false);
  }
  restartHistory();
  message_ = guardPaused ? "Reset: running again" : "Reset";
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
  rebuildPartner();
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
  rebuildPartner();
  restartHistory();
  message_ = "Preset " + std::to_string(index + 1) + ": " + preset.name;
}

void LabSession::drag(int handle, const Vec3& target) {
  for (SceneRunner* r : {&runner_, partner_.get()}) {
    if (!r) continue;
    r->scene().drag(handle, target);
    r->noteInput();
    if (r->paused()) r->scene().refresh();
  }
}

void LabSession::release(int handle) {
  for (SceneRunner* r : {&runner_, partner_.get()}) {
    if (!r) continue;
    r->scene().release(handle);
    r->noteInput();
    if (r->paused()) r->scene().refresh();
  }
}

bool LabSession::nudge(NudgeDirection direction, const Vec3& right, const Vec3& up, const Vec3& forward, Real sceneSize,
                       bool fine) {
  if (!nudgeScene(runner_.scene(), direction, right, up, forward, sceneSize, fine)) return false;
  runner_.noteInput();
  if (runner_.paused()) runner_.scene().refresh();
  if (partner_ && nudgeScene(partner_->scene(), direction, right, up, forward, sceneSize, fine)) {
    partner_->noteInput();
    if (partner_->paused()) partner_->scene().refresh();
  }
  return true;
}

void LabSession::adoptScene(std::unique_ptr<Scene> scene, std::string name) {
  runner_.adopt(std::move(scene), std::move(name));
  rebuildPartner();
  sceneChanged();
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
  if (scene.camera) cameraRequest_ = scene.camera;
  rebuildPartner();
  sceneChanged();
  return true;
}

bool LabSession::saveSceneFile(const std::string& path) {
  if (Status s = app::saveSceneFile(path, lab_, runner_.sceneName(), runner_.scene(), runner_.dt(), currentCamera_);
      !s) {
    fileError_ = s.error();
    return false;
  }
  fileError_.clear();
  message_ = "Saved " + path;
  return true;
}

void LabSession::afterFrame(bool dragging) {
  const bool stepped = runner_.steps() != historySteps_;
  if (!stepped && (runner_.paused() && !dragging)) return;
  nlohmann::json metrics = runner_.scene().metrics();
  nlohmann::json partnerMetrics = partner_ ? partner_->scene().metrics() : nlohmann::json();
  if (!runner_.paused() || dragging || stepped) {
    plots_.record(runner_.simTime(), metrics);
    if (partner_) partnerPlots_.record(partner_->simTime(), partnerMetrics);
  }
  if (stepped) {
    RewindHistory::Frame frame{runner_.snapshot(), std::move(metrics)};
    if (partner_) {
      frame.partner = partner_->snapshot();
      frame.partnerMetrics = std::move(partnerMetrics);
    }
    history_.push(std::move(frame));
    historySteps_ = runner_.steps();
  }
}

void LabSession::scrubTo(std::size_t i) {
  if (history_.empty()) return;
  i = std::min(i, history_.size() - 1);
  if (!runner_.restore(history_.at(i).state)) {
    message_ = "This scene cannot rewind (its state cannot be copied)";
    return;
  }
  runner_.setPaused(true);
  const RewindHistory::Frame& shown = history_.at(i);
  if (partner_ && shown.partner) {
    partner_->restore(*shown.partner);
    partner_->setPaused(true);
  }
  history_.setCursor(i);
  historySteps_ = runner_.steps();
  plots_.clear();
  partnerPlots_.clear();
  const std::size_t first = i + 1 > plots_.capacity() ? i + 1 - plots_.capacity() : 0;
  for (std::size_t k = first; k <= i; ++k) {
    const RewindHistory::Frame& f = history_.at(k);
    plots_.record(f.state.simTime, f.metrics);
    if (partner_ && f.partner) partnerPlots_.record(f.partner->simTime, f.partnerMetrics);
  }
  message_ = "Rewound to t = " + formatFixed(runner_.simTime(), 3) + " s (frame " + std::to_string(i + 1) + " of " +
             std::to_string(history_.size()) + "): Space runs on from here";
}

void LabSession::stepBack() {
  if (history_.empty()) return;
  const std::size_t i = history_.cursor();
  if (i == 0) {
    runner_.setPaused(true);
    message_ = "The history starts here";
    return;
  }
  scrubTo(i - 1);
}

void LabSession::stepForward() {
  if (!history_.atNewest()) {
    scrubTo(history_.cursor() + 1);
    return;
  }
  singleStep();
}

std::int64_t LabSession::stepsPerSecond() const { return std::max<std::int64_t>(1, std::llround(1.0 / runner_.dt())); }

void LabSession::stepBy(std::int64_t delta) {
  if (delta == 0 || history_.empty()) return;
  if (partner_) {
    for (std::int64_t k = 0; k < std::abs(delta); ++k) delta < 0 ? stepBack() : stepForward();
    return;
  }
  const std::int64_t newest = history_.at(history_.size() - 1).state.steps;
  const std::int64_t target = std::max<std::int64_t>(history_.at(0).state.steps, runner_.steps() + delta);
  if (target >= newest) {  // at or past the newest frame: restore it, then new steps
    if (runner_.steps() != newest || !history_.atNewest()) scrubTo(history_.size() - 1);
    runner_.setPaused(true);
    for (std::int64_t k = runner_.steps(); k < target; ++k) runner_.singleStep();
    afterFrame();
  } else {
    std::size_t i = history_.size() - 1;
    while (i > 0 && history_.at(i).state.steps > target) --i;
    scrubTo(i);
    for (std::int64_t k = runner_.steps(); k < target; ++k) runner_.singleStep();
    historySteps_ = runner_.steps();  // between two kept frames: not a frame of its own
    if (runner_.steps() != history_.at(i).state.steps) plots_.record(runner_.simTime(), runner_.scene().metrics());
  }
  message_ = "Step " + std::to_string(runner_.steps()) + ", t = " + formatFixed(runner_.simTime(), 3) +
             " s: , and . step by one step, Shift by a second; Space runs on from here";
}

bool LabSession::takeFrameRequest() {
  const bool requested = frameRequested_;
  frameRequested_ = false;
  return requested;
}

void LabSession::restartHistory() {
  plots_.clear();
  partnerPlots_.clear();
  history_.clear();
  historySteps_ = -1;
  if (!runner_.hasScene()) return;
  // The first frame of the history is the state at reset, so scrubbing can go back to t = 0.
  RewindHistory::Frame frame{runner_.snapshot(), runner_.scene().metrics()};
  if (partner_ && partner_->hasScene()) {
    frame.partner = partner_->snapshot();
    frame.partnerMetrics = partner_->scene().metrics();
  }
  history_.push(std::move(frame));
  historySteps_ = runner_.steps();
}

void LabSession::startCompare(std::unique_ptr<SceneRunner> b, std::string sideA, std::string sideB) {
  partner_ = std::move(b);
  sideA_ = std::move(sideA);
  sideB_ = std::move(sideB);
  partner_->setPaused(runner_.paused());
  restartHistory();
}

void LabSession::duplicateAsB() {
  partner_ = std::make_unique<SceneRunner>();
  sideA_.clear();
  sideB_.clear();
  rebuildPartner();
  runner_.reset();
  editingB_ = true;
  restartHistory();
  message_ = "B is a copy of A, both from the start: the panel now edits B";
}

void LabSession::endCompare() {
  partner_.reset();
  editingB_ = false;
  restartHistory();
  message_ = "A/B comparison ended";
}

void LabSession::rebuildPartner() {
  if (!partner_) return;
  // A keeps its own side's settings over a preset or another scene; B starts from A's parameters.
  std::string problem;
  auto apply = [&problem](SceneRunner& r, const std::string& text, const std::string& side) {
    Result<std::vector<CompareSetting>> settings = parseCompareSide(text, side);
    if (!settings) {
      problem = settings.error();
      return;
    }
    std::vector<CompareSetting> known;
    for (const CompareSetting& c : settings.value())
      if (c.name == "dt" || c.name == "substeps" || c.name == "time_scale" || r.scene().params().find(c.name))
        known.push_back(c);
    if (Status s = applyCompareSide(r, known, side); !s) problem = s.error();
  };
  apply(runner_, sideA_, "A");
  auto b = std::make_unique<SceneRunner>();
  if (Status s = b->load(runner_.sceneName(), seed_); !s) {
    message_ = "B: " + s.error();
    partner_.reset();
    return;
  }
  b->setDt(runner_.dt());
  b->setSubsteps(runner_.substeps());
  b->setTimeScale(runner_.timeScale());
  if (Status s = applyParams(b->scene(), runner_.scene().params().toJson(), "B"); !s) problem = s.error();
  apply(*b, sideB_, "B");
  b->reset();
  b->setPaused(runner_.paused());
  partner_ = std::move(b);
  if (!problem.empty()) message_ = problem;
}

void LabSession::sceneChanged() {
  restartHistory();
  settings_.lastScene = runner_.sceneName();
  frameRequested_ = true;
}

}  // namespace pba::app
