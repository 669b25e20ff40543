#pragma once
// One-line scene registration (docs/architecture.md §3; Box2D's RegisterSample is the model):
//   PBA_REGISTER_SCENE("Basics", "drop", DropScene);
// registers a factory in the executable's scene list in the order of the lab's source files.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/runner/scene.h"

namespace pba::app {

struct SceneEntry {
  std::string category;
  std::string name;  ///< command line name: lower-case, dash-separated
  std::function<std::unique_ptr<Scene>()> create;
};

/// All scenes of this executable, sorted by category then registration order.
const std::vector<SceneEntry>& scenes();
/// The entry named `name`, or nullptr.
const SceneEntry* findScene(const std::string& name);
/// Index of `name` in scenes(), or -1.
int sceneIndex(const std::string& name);

/// Returns true so that it can initialise a static in the registering file.
bool registerScene(std::string category, std::string name, std::function<std::unique_ptr<Scene>()> create);

/// A lab flag that sets a scene parameter, e.g. --integrator rk4 sets parameter "integrator".
struct LabFlag {
  std::string flag;   ///< without dashes
  std::string param;  ///< parameter name it sets
  std::string help;
  /// When set and no --scene is given, using the flag selects this scene (e.g. --targets K selects
  /// the IK lab's "batch" scene).
  std::string impliesScene;
  /// Of several scene-selecting flags on one command line, the highest priority picks the scene
  /// (the order of the flags does not matter; equal priorities: the last one).
  int priority = 0;
};
const std::vector<LabFlag>& labFlags();
bool registerLabFlag(std::string flag, std::string param, std::string help, std::string impliesScene = {},
                     int priority = 0);

/// A key of one scene's own (a letter the common keys leave free, e.g. G in the ragdoll lab's
/// ik-to-ragdoll): the window passes it to Scene::keyPressed, and the F1 help and --help list it.
struct LabKey {
  char key = 0;       ///< upper-case letter
  std::string scene;  ///< the scene that answers it
  std::string action;
};
const std::vector<LabKey>& labKeys();
bool registerLabKey(char key, std::string scene, std::string action);

}  // namespace pba::app

#define PBA_CONCAT_INNER(a, b) a##b
#define PBA_CONCAT(a, b) PBA_CONCAT_INNER(a, b)
// Every registered scene can save and restore its state by copying itself (app/runner/scene_state.h).
#define PBA_REGISTER_SCENE(category, name, Type)                                                                  \
  static const bool PBA_CONCAT(pbaSceneRegistered_, __COUNTER__) = ::pba::app::registerScene(category, name, [] { \
    auto scene = std::unique_ptr<::pba::app::Scene>(new Type());                                                  \
    static const auto ops = std::make_shared<const ::pba::app::CopySceneStateOps<Type>>();                        \
    scene->setStateOps(ops);                                                                                      \
    return scene;                                                                                                 \
  })
#define PBA_REGISTER_LAB_KEY(...) \
  static const bool PBA_CONCAT(pbaKeyRegistered_, __COUNTER__) = ::pba::app::registerLabKey(__VA_ARGS__)
#define PBA_REGISTER_LAB_FLAG(...) \
  static const bool PBA_CONCAT(pbaFlagRegistered_, __COUNTER__) = ::pba::app::registerLabFlag(__VA_ARGS__)
