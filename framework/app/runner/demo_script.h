#pragma once
// Lecture demo scripts (docs/instructor-guide.md, "Demo scripts"; resources/demos/*.json): a list of
// steps, each a lab, a scene with parameters, a camera, an optional recording and speaker notes,
// played with `./pba demo FILE` like slides (PageDown / PageUp). The file:
//   {"title": "...", "chapter": "docs/workbook/02-....md",
//    "steps": [{"title": "...", "lab": "particles", "scene": "oscillator", "params": {"h": 0.1},
//               "dt": 0.01, "camera": {...}, "paused": false, "record": "oscillator.mp4", "notes": "..."}]}
// Only "lab", "scene" and "notes" are required in a step.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/runner/scene.h"
#include "physics/core/result.h"

namespace pba::app {

struct DemoStep {
  std::string title;
  std::string lab;
  std::string scene;
  nlohmann::json params = nlohmann::json::object();
  std::optional<Real> dt;
  std::optional<CameraView> camera;
  bool paused = false;  ///< start the step paused (a setup to talk over before it runs)
  std::string record;   ///< when set, the step is recorded to this path (FILE.mp4, FILE.gif or DIR/)
  std::string notes;    ///< the speaker's notes
};

struct DemoScript {
  std::string path;
  std::string title;
  std::string chapter;
  std::vector<DemoStep> steps;
};

/// Reads and checks the structure; errors read "<path>: steps[2].scene: ..." (a line for JSON syntax).
Result<DemoScript> loadDemoScript(const std::string& path);

/// Checks step `index` against this lab's registry: the scene exists and its parameters and dt apply
/// and validate (on a fresh instance). Errors name the file and the step's field.
Status checkDemoStep(const DemoScript& script, std::size_t index);

/// Builds the scene of a step (created, parameters applied, validated; not yet reset).
Result<std::unique_ptr<Scene>> demoStepScene(const DemoScript& script, std::size_t index, std::uint64_t seed);

}  // namespace pba::app
