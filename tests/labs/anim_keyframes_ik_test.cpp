// The animation lab's keyframes scene poses a limb by any IK solver of the library (parameter "ik") and
// keys the result: after a drag of the left hand to a goal, the clip itself, sampled at the drag's time,
// must put the hand on the goal. The reference is the goal; the hand's reach is measured from the
// character's rest pose (goals at 55–85 % of it, so each is reachable with the elbow bent).
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/runner/scene_registry.h"
#include "physics/exercises/not_implemented.h"
#include "physics/ik/solver.h"

namespace pba {
namespace {

Vec3 jointAt(const app::Scene& scene, const std::string& name) {
  for (const app::NamedPoint& p : scene.jointPositions())
    if (p.name == name) return p.position;
  ADD_FAILURE() << "no joint " << name;
  return Vec3(0.0);
}

// The drag handle of joint `name`: the scene's handles are joint indices, in jointPositions()' order.
int handleOf(const app::Scene& scene, const std::string& name) {
  const std::vector<app::NamedPoint> joints = scene.jointPositions();
  for (const app::DragHandle& h : scene.dragHandles())
    if (h.handle >= 0 && h.handle < static_cast<int>(joints.size()) &&
        joints[static_cast<size_t>(h.handle)].name == name)
      return h.handle;
  return -1;
}

// An integration test of the lab's wiring over every solver: the goal test needs the solutions of the
// exercises it runs through (IK-2 to IK-6 in the solvers, ANIM-1 to ANIM-3 in the clip's sampling and
// forward kinematics), each graded on its own by its tagged tests. The checks that do not depend on any
// solution run for every drag (a new key, the method in the metrics); the positions are checked for each
// drag during which no exercise stub ran: every drag in this repository, and in the hand-out each method
// whose exercises the student has solved.
TEST(KeyframesIk, AKeySetByEveryIkMethodPutsTheHandOnItsGoal) {
  const app::SceneEntry* entry = app::findScene("keyframes");
  ASSERT_NE(entry, nullptr);
  // [m] the keyed hand on its goal: the solvers stop within 0.1 mm; squad through a key returns it exactly.
  constexpr Real kTolerance = 1e-3;
  const Vec3 directions[] = {Vec3(0.3, -0.5, 0.8), Vec3(0.6, 0.4, 0.5), Vec3(0.2, -0.9, -0.3)};
  const Real fractions[] = {0.85, 0.7, 0.55};
  int positionsChecked = 0, positionsNotChecked = 0;
  for (const ik::SolverInfo& method : ik::solverTable()) {
    for (int g = 0; g < 3; ++g) {
      exercises::clearNotImplemented();
      std::unique_ptr<app::Scene> scene = entry->create();
      ASSERT_TRUE(scene->params().setFromText("ik", std::string(method.name)).ok()) << method.name;
      scene->reset();
      scene->step(0.1);  // between the clip's keys: the drag inserts a new one
      const Vec3 shoulder = jointAt(*scene, "LeftArm"), elbow = jointAt(*scene, "LeftForeArm");
      const Vec3 hand = jointAt(*scene, "LeftHand");
      const Real reach = glm::length(elbow - shoulder) + glm::length(hand - elbow);
      const Vec3 goal = shoulder + fractions[g] * reach * glm::normalize(directions[g]);
      const int handle = handleOf(*scene, "LeftHand");
      const std::string where = std::string(method.name) + " goal " + std::to_string(g) + ": ";
      ASSERT_GE(handle, 0) << where << "the left hand is not a drag handle";
      const size_t keysBefore = scene->metrics()["keys"].get<size_t>();
      scene->drag(handle, goal);
      scene->release(handle);
      const nlohmann::json m = scene->metrics();
      EXPECT_EQ(m["ik_method"], method.name) << where << "the metrics name another method";
      EXPECT_EQ(m["keys"].get<size_t>(), keysBefore + 1) << where << "no new key at the drag's time";
      if (const std::vector<std::string> stubs = exercises::notImplementedTags(); !stubs.empty()) {
        ++positionsNotChecked;
        std::cout << where << "the stub of " << stubs.front() << " ran: positions not checked\n";
        continue;
      }
      ++positionsChecked;
      // The pose on screen now is the clip sampled at the drag's time: the key, not the solver's pose.
      EXPECT_LT(glm::length(jointAt(*scene, "LeftHand") - goal), kTolerance) << where << "the keyed hand is off";
      // The limb stays rigid (both bones keep their lengths), whatever the method.
      const Vec3 e = jointAt(*scene, "LeftForeArm"), s = jointAt(*scene, "LeftArm"), h = jointAt(*scene, "LeftHand");
      EXPECT_NEAR(glm::length(e - s) + glm::length(h - e), reach, 1e-9) << where << "a bone changed length";
    }
  }
  std::cout << "positions checked after " << positionsChecked << " drags, not checked after " << positionsNotChecked
            << " (an exercise stub ran)\n";
}

}  // namespace
}  // namespace pba
