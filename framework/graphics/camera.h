// OrbitCamera: a camera orbiting a target point (yaw about +y, pitch above the horizon), the usual
// viewer of physics samples. Pure math (no GL), unit-tested in tests/graphics/camera_test.cpp.
// Screen conventions: pixels with the origin at the top-left corner, x right, y down; a cursor at
// (x, y) addresses the continuous position, so the viewport centre is (w/2, h/2).
#pragma once

#include <glm/glm.hpp>

namespace pba::graphics {

struct Ray {
  glm::vec3 origin{0.0f};                  ///< camera eye, m
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  ///< unit
};

struct ScreenPoint {
  glm::vec2 pixel{0.0f};  ///< top-left origin, pixels
  float depth = 0.0f;     ///< normalised device depth in [-1, 1] when visible
  bool visible = false;   ///< in front of the camera and inside the viewport and depth range
};

class OrbitCamera {
 public:
  static constexpr float kMaxPitch = 1.5533430f;  ///< 89 degrees: never look straight down the pole
  static constexpr float kMinDistance = 1e-3f;    ///< m
  static constexpr float kMaxDistance = 1e5f;     ///< m

  glm::vec3 target{0.0f, 0.5f, 0.0f};  ///< orbit centre, m
  float yaw = 0.6f;                    ///< rad about +y; 0 looks from +z towards -z
  float pitch = 0.45f;                 ///< rad above the horizon (eye higher than target when > 0)
  float distance = 6.0f;               ///< eye-to-target distance, m
  float fovY = 0.7853982f;             ///< vertical field of view, rad (45 degrees)
  float nearPlane = 0.05f;             ///< m
  float farPlane = 500.0f;             ///< m
  /// The ground plane y = groundHeight [m] (the renderer's grid) stays below the eye: clampState keeps
  /// the target on or above it and the eye at least minEyeHeight() above it, so no orbit, pan or zoom
  /// looks at the ground from below (which shows nothing but the grid's underside). keepAboveGround
  /// false lifts the rule (a scene without ground).
  bool keepAboveGround = true;
  float groundHeight = 0.0f;   ///< m
  float rotateSpeed = 0.006f;  ///< rad per pixel of drag
  float zoomFactor = 0.88f;    ///< distance multiplier per wheel step (wheel up = closer)

  glm::vec3 eye() const;
  glm::vec3 forward() const;  ///< unit, eye towards target
  glm::vec3 right() const;    ///< unit, screen right
  glm::vec3 up() const;       ///< unit, screen up

  /// Orbits: dx pixels to the right turns the view as if dragging the scene right; dy down tilts.
  void rotate(float dxPixels, float dyPixels);
  /// Moves target (and eye) so that the point at the target depth follows the cursor.
  void pan(float dxPixels, float dyPixels, const glm::vec2& viewport);
  /// Positive steps zoom in (mouse wheel up).
  void zoom(float wheelSteps);
  /// Fits the box [aabbMin, aabbMax] in view for the given aspect ratio; keeps yaw and pitch.
  /// A degenerate (point or inverted) box is handled: it frames a small sphere around it.
  void frame(const glm::vec3& aabbMin, const glm::vec3& aabbMax, float aspect = 16.0f / 9.0f);

  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;  ///< aspect = width / height (guarded against 0)

  /// Ray from the eye through the cursor pixel (top-left origin).
  Ray ray(float cursorX, float cursorY, float viewportW, float viewportH) const;
  /// Projects a world point to pixels (top-left origin).
  ScreenPoint project(const glm::vec3& world, float viewportW, float viewportH) const;

  /// Restores the invariants after fields were edited directly (pitch, distance, planes, ground).
  void clampState();
  /// The smallest height [m] of the eye above the ground: 1 % of the distance, at least 1 cm.
  float minEyeHeight() const;
};

}  // namespace pba::graphics
