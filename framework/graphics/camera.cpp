// OrbitCamera math: spherical eye placement, pan/zoom/frame, picking rays and projection.
#include "graphics/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace pba::graphics {
namespace {

float safeAspect(float aspect) { return std::isfinite(aspect) && aspect > 1e-6f ? aspect : 1.0f; }
float safeExtent(float pixels) { return std::isfinite(pixels) && pixels >= 1.0f ? pixels : 1.0f; }

}  // namespace

glm::vec3 OrbitCamera::forward() const {
  // Eye offset from target is (cos p sin y, sin p, cos p cos y) * distance; forward is its opposite.
  return -glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
}

glm::vec3 OrbitCamera::right() const { return glm::vec3(std::cos(yaw), 0.0f, -std::sin(yaw)); }

glm::vec3 OrbitCamera::up() const { return glm::cross(right(), forward()); }

glm::vec3 OrbitCamera::eye() const { return target - distance * forward(); }

void OrbitCamera::clampState() {
  if (!std::isfinite(pitch)) pitch = 0.0f;
  if (!std::isfinite(yaw)) yaw = 0.0f;
  if (!std::isfinite(distance)) distance = 6.0f;
  pitch = std::clamp(pitch, -kMaxPitch, kMaxPitch);
  yaw = std::remainder(yaw, 6.2831853f);
  distance = std::clamp(distance, kMinDistance, kMaxDistance);
  if (keepAboveGround && std::isfinite(groundHeight)) {
    // eye.y = target.y + distance sin(pitch) >= ground + minEyeHeight gives the lowest pitch.
    if (!std::isfinite(target.y) || target.y < groundHeight) target.y = groundHeight;
    const float s = (groundHeight + minEyeHeight() - target.y) / distance;
    if (s > -1.0f) pitch = std::clamp(pitch, std::asin(std::min(s, std::sin(kMaxPitch))), kMaxPitch);
  }
  fovY = std::clamp(fovY, 0.01f, 3.0f);
  nearPlane = std::max(nearPlane, 1e-5f);
  farPlane = std::max(farPlane, nearPlane * 2.0f);
}

float OrbitCamera::minEyeHeight() const { return std::max(0.01f, 0.01f * distance); }

void OrbitCamera::rotate(float dxPixels, float dyPixels) {
  yaw -= dxPixels * rotateSpeed;
  pitch += dyPixels * rotateSpeed;
  clampState();
}

void OrbitCamera::pan(float dxPixels, float dyPixels, const glm::vec2& viewport) {
  // World size of one pixel at the target depth: the view height there is 2 d tan(fov/2).
  const float metresPerPixel = 2.0f * distance * std::tan(0.5f * fovY) / safeExtent(viewport.y);
  target += (-dxPixels * right() + dyPixels * up()) * metresPerPixel;
  clampState();
}

void OrbitCamera::zoom(float wheelSteps) {
  // Clamp the exponent: a huge step count would overflow pow() (and the clamp below makes it moot).
  distance *= std::pow(zoomFactor, std::clamp(wheelSteps, -100.0f, 100.0f));
  clampState();
}

void OrbitCamera::frame(const glm::vec3& aabbMin, const glm::vec3& aabbMax, float aspect) {
  glm::vec3 lo = glm::min(aabbMin, aabbMax);
  glm::vec3 hi = glm::max(aabbMin, aabbMax);
  if (!std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z)) lo = hi = glm::vec3(0.0f);
  target = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 0.05f);  // bounding sphere, m
  // The sphere fits when distance >= r / sin(half angle) for the narrower of the two half angles.
  const float halfY = 0.5f * fovY;
  const float halfX = std::atan(std::tan(halfY) * safeAspect(aspect));
  const float half = std::min(halfX, halfY);
  distance = std::clamp(1.08f * radius / std::sin(half), kMinDistance, kMaxDistance);
  nearPlane = std::clamp(0.25f * (distance - radius), 1e-4f, 0.05f);
  farPlane = std::max(500.0f, 4.0f * (distance + radius));
  clampState();
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(eye(), target, glm::vec3(0.0f, 1.0f, 0.0f)); }

glm::mat4 OrbitCamera::projection(float aspect) const {
  return glm::perspective(fovY, safeAspect(aspect), nearPlane, farPlane);
}

Ray OrbitCamera::ray(float cursorX, float cursorY, float viewportW, float viewportH) const {
  const float w = safeExtent(viewportW), h = safeExtent(viewportH);
  const float ndcX = 2.0f * cursorX / w - 1.0f;
  const float ndcY = 1.0f - 2.0f * cursorY / h;
  const float tanHalf = std::tan(0.5f * fovY);
  const glm::vec3 d = forward() + right() * (ndcX * tanHalf * (w / h)) + up() * (ndcY * tanHalf);
  return Ray{eye(), glm::normalize(d)};
}

ScreenPoint OrbitCamera::project(const glm::vec3& world, float viewportW, float viewportH) const {
  const float w = safeExtent(viewportW), h = safeExtent(viewportH);
  const glm::vec4 clip = projection(w / h) * view() * glm::vec4(world, 1.0f);
  ScreenPoint out;
  if (!(clip.w > 1e-12f)) return out;  // behind (or at) the eye: no meaningful pixel
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  out.pixel = glm::vec2((ndc.x * 0.5f + 0.5f) * w, (0.5f - ndc.y * 0.5f) * h);
  out.depth = ndc.z;
  out.visible = std::abs(ndc.x) <= 1.0f && std::abs(ndc.y) <= 1.0f && std::abs(ndc.z) <= 1.0f;
  return out;
}

}  // namespace pba::graphics
