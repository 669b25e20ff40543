#include "app/runner/scene_runner.h"

#include <chrono>
#include <cmath>

#include "app/runner/scene_registry.h"
#include "physics/core/format.h"
#include "physics/core/validate.h"

namespace pba::app {
namespace {
std::string formatTime(Real t) { return formatFixed(t, 3); }
}  // namespace

Status SceneRunner::load(const std::string& name, std::uint64_t seed) {
  const SceneEntry* entry = findScene(name);
  if (!entry) return Error{"unknown scene '" + name + "' (see --list-scenes)"};
  std::unique_ptr<Scene> scene = entry->create();
  scene->setSeed(seed);
  adopt(std::move(scene), name);
  return Status::success();
}

void SceneRunner::adopt(std::unique_ptr<Scene> scene, std::string name) {
  scene_ = std::move(scene);
  sceneName_ = std::move(name);
  if (!dtFromUser_) dt_ = scene_->defaultDt();
  reset();
}

void SceneRunner::reset() {
  scene_->reset();
  accumulator_ = 0.0;
  simTime_ = 0.0;
  steps_ = 0;
  finite_ = true;
  guardMessage_.reset();
  frameStats_.clear();
  const std::optional<Real> e = scene_->energy();
  energyScale_ = e ? std::max(std::abs(*e), kMinEnergyScale) : 0.0;
  rebaseEnergy();
}

void SceneRunner::noteInput() {
  if (scene_) rebaseEnergy();
}

void SceneRunner::rebaseEnergy() {
  energyReference_ = scene_->energy();
  paramValues_ = paramValues();
}

std::vector<double> SceneRunner::paramValues() const {
  std::vector<double> values;
  for (const Param& p : scene_->params().all())
    if (p.get) values.push_back(p.get());
  return values;
}

std::size_t RunnerSnapshot::bytes() const {
  return sizeof(RunnerSnapshot) + (scene ? scene->bytes() : 0) + (guardMessage ? guardMessage->capacity() : 0);
}

RunnerSnapshot SceneRunner::snapshot() const {
  RunnerSnapshot s;
  if (scene_) s.scene = scene_->saveState();
  s.simTime = simTime_;
  s.accumulator = accumulator_;
  s.energyScale = energyScale_;
  s.energyReference = energyReference_;
  s.paramValues = paramValues_;
  s.steps = steps_;
  s.finite = finite_;
  s.guardMessage = guardMessage_;
  return s;
}

bool SceneRunner::restore(const RunnerSnapshot& s) {
  if (!scene_ || !s.scene || !scene_->restoreState(*s.scene)) return false;
  simTime_ = s.simTime;
  accumulator_ = s.accumulator;
  energyScale_ = s.energyScale;
  energyReference_ = s.energyReference;
  paramValues_ = s.paramValues;
  steps_ = s.steps;
  finite_ = s.finite;
  guardMessage_ = s.guardMessage;
  return true;
}

Status SceneRunner::setDt(Real dt, bool keepAcrossScenes) {
  if (Status s = checkRange("dt", dt, kMinDt, kMaxDt); !s) return s;
  dt_ = dt;
  dtFromUser_ = dtFromUser_ || keepAcrossScenes;
  return Status::success();
}

Status SceneRunner::setSubsteps(int n) {
  if (n < 1 || n > kMaxSubsteps)
    return Error{"substeps: must be in [1, " + std::to_string(kMaxSubsteps) + "], got " + std::to_string(n)};
  substeps_ = n;
  return Status::success();
}

Status SceneRunner::setTimeScale(Real scale) {
  if (Status s = checkRange("time scale", scale, kMinTimeScale, kMaxTimeScale); !s) return s;
  timeScale_ = scale;
  return Status::success();
}

bool SceneRunner::stepOnce() {
  const Real h = dt_ / substeps_;
  for (int i = 0; i < substeps_; ++i) scene_->step(h);
  simTime_ += dt_;
  ++steps_;
  checkGuard();
  return !guardMessage_;
}

void SceneRunner::checkGuard() {
  if (std::optional<std::string> bad = scene_->nonFiniteState()) {
    finite_ = false;
    paused_ = true;
    guardMessage_ = "Paused: " + *bad + " at t = " + formatTime(simTime_) +
                    " s. The simulation blew up: try a smaller time step (dt), more substeps, a more stable "
                    "integrator or more solver iterations, then press R to reset.";
    return;
  }
  if (std::optional<std::string> diverged = scene_->divergedState()) {
    paused_ = true;
    guardMessage_ = "Paused: " + *diverged + " at t = " + formatTime(simTime_) +
                    " s (runaway). Try a smaller time step (dt), more substeps, more damping or a more stable "
                    "integrator, then press R to reset.";
    return;
  }
  if (energyScale_ <= 0.0) return;
  const std::optional<Real> e = scene_->energy();
  if (!e) return;
  // A parameter edited between steps (panel, file, soak) changes the energy by itself: count from here.
  if (energyReference_ && paramValues() != paramValues_) rebaseEnergy();
  Real from = energyScale_;
  bool runaway = std::abs(*e) > kRunawayEnergyFactor * energyScale_;
  if (!runaway && energyReference_) {
    const std::optional<Real> bound = scene_->energyGainBound(*energyReference_);
    runaway = bound && *e > *energyReference_ + *bound;
    from = *energyReference_;
  }
  if (!runaway) return;
  paused_ = true;
  guardMessage_ = "Paused: energy grew from " + formatTime(from) + " J to " + formatTime(*e) +
                  " J by t = " + formatTime(simTime_) +
                  " s (runaway). Try a smaller time step (dt), more substeps, more damping or a more stable "
                  "integrator, then press R to reset.";
}

void SceneRunner::advanceFrame(Real frameSeconds, int maxSteps) {
  if (paused_ || !scene_) return;
  accumulator_ += frameSeconds * timeScale_;
  const auto start = std::chrono::steady_clock::now();
  int taken = 0;
  // A small tolerance so that a frame of exactly k·dt takes k steps despite rounding.
  const Real tolerance = 1e-9 * dt_;
  while (accumulator_ + tolerance >= dt_) {
    if (maxSteps >= 0 && taken >= maxSteps) {
      accumulator_ = 0.0;  // fall behind real time rather than freeze the window
      break;
    }
    accumulator_ -= dt_;
    ++taken;
    if (!stepOnce()) break;
  }
  if (taken > 0) {
    const auto end = std::chrono::steady_clock::now();
    frameStats_.add(std::chrono::duration<double, std::milli>(end - start).count());
  }
}

void SceneRunner::singleStep() {
  if (!scene_ || guardMessage_) return;
  const auto start = std::chrono::steady_clock::now();
  stepOnce();
  frameStats_.add(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace pba::app
