#pragma once
// --pose-json FILE (docs/decisions/2026-12-01-animation-splines-skeletons-and-skins.md): the world position of every
// joint of the scene's skeleton, by name, when the run ends, so that a pose can be checked from outside the lab (a
// script compares a hand with its goal). One writer for every lab with a skeleton (IK, animation): a scene lists its
// joints through Scene::jointPositions(), the runner writes them.
//
//   {"lab": "ik", "scene": "character", "sim_time_s": 0.5, "unit": "m",
//    "joints": {"Hips": [0.0, 0.95, 0.0], "LeftHand": [...], ...},
//    "goals": {"LeftHand": [...], ...}}   (IK: each effector's goal, by the name of the point reaching for it)
#include <string>

#include <nlohmann/json.hpp>

#include "app/runner/scene_runner.h"
#include "physics/core/result.h"

namespace pba::app {

/// The document above for the runner's current scene; "joints" is empty when the scene has no skeleton.
nlohmann::json poseReport(const std::string& lab, const SceneRunner& runner);

/// Checks that the scene has a skeleton: "--pose-json: scene 'splines' has no skeleton".
Status checkPoseJson(const SceneRunner& runner);

/// Writes poseReport to `path`. Errors: "--pose-json: scene 'x' has no skeleton", "--pose-json: FILE: cannot write".
Status writePoseJson(const std::string& lab, const SceneRunner& runner, const std::string& path);

}  // namespace pba::app
