// ShadowMap: depth FBO and light camera fitting.
#include "graphics/shadow_map.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace pba::graphics {

ShadowMap::ShadowMap(int size) : size_(size) {
  glGenTextures(1, &depth_);
  glBindTexture(GL_TEXTURE_2D, depth_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
  const GLenum noColor = GL_NONE;  // depth only (glDrawBuffers: GL 3.3 and WebGL2 alike)
  glDrawBuffers(1, &noColor);
  glReadBuffer(GL_NONE);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

ShadowMap::~ShadowMap() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteTextures(1, &depth_);
}

void ShadowMap::fit(const glm::vec3& sceneMin, const glm::vec3& sceneMax, const glm::vec3& lightDir) {
  // Extend the box by the shadow of its top corners on y = 0 (x' = x - y * L.xz / L.y).
  glm::vec3 lo = sceneMin, hi = sceneMax;
  if (lightDir.y > 0.05f) {
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 c((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
      if (c.y <= 0.0f) continue;
      const glm::vec3 ground = c - lightDir * (c.y / lightDir.y);
      lo = glm::min(lo, ground);
      hi = glm::max(hi, ground);
    }
  }
  const glm::vec3 center = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 0.1f);
  const glm::vec3 up = std::abs(lightDir.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  const glm::mat4 view = glm::lookAt(center + lightDir * (2.0f * radius), center, up);
  const glm::mat4 proj = glm::ortho(-radius, radius, -radius, radius, 0.01f * radius, 4.0f * radius);
  worldTexel_ = 2.0f * radius / static_cast<float>(size_);
  lightViewProj_ = proj * view;
}

void ShadowMap::beginPass() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, size_, size_);
  glClear(GL_DEPTH_BUFFER_BIT);
}

void ShadowMap::endPass() const { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

void ShadowMap::bindTexture(int unit) const {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, depth_);
}

}  // namespace pba::graphics
