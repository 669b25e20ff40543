#pragma once
// Keyboard nudging of a scene's current target (IK goal, …): the arrow keys move it in the camera
// plane, PageUp/PageDown (or Shift+Up/Down) toward or away from the camera; Ctrl makes the step
// five times finer. The keys do not overlap the standard keys of docs/architecture.md §3. No GL and no ImGui
// here, so the mapping is tested headless (tests/app/target_nudge_test.cpp).
#include <optional>

#include "app/runner/scene.h"

namespace pba::app {

enum class NudgeDirection { Left, Right, Up, Down, Toward, Away };

inline constexpr Real kNudgeFraction = 0.02;   ///< fallback step: 2 % of the scene's drawn size
inline constexpr Real kNudgeMinStep = 1e-4;    ///< [m] never smaller (a point-sized scene)
inline constexpr Real kNudgeFineFactor = 0.2;  ///< Ctrl: one fifth of the step

/// The nudge direction of a GLFW key code with its modifier bits (GLFW_MOD_SHIFT = 1), or none.
/// Left/Right/Up/Down arrows; Shift+Up/Down and PageUp/PageDown: Away/Toward the camera.
std::optional<NudgeDirection> nudgeDirectionForKey(int glfwKey, int glfwMods);
/// True when the modifiers ask for the fine step (Ctrl).
bool nudgeIsFine(int glfwMods);

/// World displacement [m] of one nudge of length `step`, given the camera's unit right, up and
/// forward (eye toward target) vectors. Toward the camera is −forward.
Vec3 nudgeDisplacement(NudgeDirection direction, const Vec3& right, const Vec3& up, const Vec3& forward, Real step);

/// The step [m] for a scene `sceneSize` metres across (the diagonal of its drawn bounds).
Real nudgeStepForSize(Real sceneSize);

/// Nudges the scene's target one step: the scene's own nudgeStep() when positive, else
/// nudgeStepForSize(sceneSize); times kNudgeFineFactor when `fine`. False when the scene has no
/// target to nudge.
bool nudgeScene(Scene& scene, NudgeDirection direction, const Vec3& right, const Vec3& up, const Vec3& forward,
                Real sceneSize, bool fine);

}  // namespace pba::app
