#include "app/window/target_nudge.h"

#include <algorithm>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace pba::app {

std::optional<NudgeDirection> nudgeDirectionForKey(int key, int mods) {
  const bool shift = (mods & GLFW_MOD_SHIFT) != 0;
  switch (key) {
    case GLFW_KEY_LEFT:
      return NudgeDirection::Left;
    case GLFW_KEY_RIGHT:
      return NudgeDirection::Right;
    case GLFW_KEY_UP:
      return shift ? NudgeDirection::Away : NudgeDirection::Up;
    case GLFW_KEY_DOWN:
      return shift ? NudgeDirection::Toward : NudgeDirection::Down;
    case GLFW_KEY_PAGE_UP:
      return NudgeDirection::Away;
    case GLFW_KEY_PAGE_DOWN:
      return NudgeDirection::Toward;
    default:
      return std::nullopt;
  }
}

bool nudgeIsFine(int mods) { return (mods & GLFW_MOD_CONTROL) != 0; }

Vec3 nudgeDisplacement(NudgeDirection direction, const Vec3& right, const Vec3& up, const Vec3& forward, Real step) {
  switch (direction) {
    case NudgeDirection::Left:
      return -step * right;
    case NudgeDirection::Right:
      return step * right;
    case NudgeDirection::Up:
      return step * up;
    case NudgeDirection::Down:
      return -step * up;
    case NudgeDirection::Toward:
      return -step * forward;
    case NudgeDirection::Away:
      return step * forward;
  }
  return Vec3(0.0);
}

Real nudgeStepForSize(Real sceneSize) { return std::max(kNudgeFraction * sceneSize, kNudgeMinStep); }

bool nudgeScene(Scene& scene, NudgeDirection direction, const Vec3& right, const Vec3& up, const Vec3& forward,
                Real sceneSize, bool fine) {
  const Real own = scene.nudgeStep();
  const Real step = (own > 0.0 ? own : nudgeStepForSize(sceneSize)) * (fine ? kNudgeFineFactor : 1.0);
  return scene.nudge(nudgeDisplacement(direction, right, up, forward, step));
}

}  // namespace pba::app
