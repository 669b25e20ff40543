#include "app/runner/pose_json.h"

#include <fstream>

#include "app/runner/message_text.h"

namespace pba::app {

nlohmann::json poseReport(const std::string& lab, const SceneRunner& runner) {
  nlohmann::json joints = nlohmann::json::object();
  for (const NamedPoint& j : runner.scene().jointPositions())
    joints[j.name] = {j.position.x, j.position.y, j.position.z};
  nlohmann::json report = {{"lab", lab},
                           {"scene", runner.sceneName()},
                           {"sim_time_s", runner.simTime()},
                           {"unit", "m"},
                           {"joints", std::move(joints)}};
  const std::vector<NamedPoint> goals = runner.scene().goalPositions();
  for (const NamedPoint& g : goals) report["goals"][g.name] = {g.position.x, g.position.y, g.position.z};
  return report;
}

Status checkPoseJson(const SceneRunner& runner) {
  if (runner.scene().jointPositions().empty())
    return Error{"--pose-json: scene '" + runner.sceneName() + "' has no skeleton"};
  return Status::success();
}

Status writePoseJson(const std::string& lab, const SceneRunner& runner, const std::string& path) {
  if (Status s = checkPoseJson(runner); !s) return s;
  std::ofstream out(path);
  out << poseReport(lab, runner).dump(2) << '\n';
  if (!out) return Error{"--pose-json: " + oneLine(path) + ": cannot write"};
  return Status::success();
}

}  // namespace pba::app
