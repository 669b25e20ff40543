// ShadowMap: a depth texture + framebuffer rendered from an orthographic light camera fitted to the
// scene bounds (and to their shadows on the ground plane y = 0), sampled with hardware comparison.
#pragma once

#include <glm/glm.hpp>
#include "graphics/gl.h"

namespace pba::graphics {

class ShadowMap {
 public:
  explicit ShadowMap(int size = 2048);  ///< texels per side; needs a current GL context
  ~ShadowMap();
  ShadowMap(const ShadowMap&) = delete;
  ShadowMap& operator=(const ShadowMap&) = delete;

  /// Fits the light camera. lightDir: unit, from the scene towards the light.
  void fit(const glm::vec3& sceneMin, const glm::vec3& sceneMax, const glm::vec3& lightDir);
  /// Binds the framebuffer, sets the viewport and clears depth; restore the viewport afterwards.
  void beginPass() const;
  void endPass() const;
  void bindTexture(int unit) const;

  const glm::mat4& lightViewProj() const { return lightViewProj_; }
  int size() const { return size_; }
  float worldTexel() const { return worldTexel_; }  ///< m covered by one texel

 private:
  GLuint fbo_ = 0, depth_ = 0;
  int size_ = 0;
  glm::mat4 lightViewProj_{1.0f};
  float worldTexel_ = 0.01f;
};

}  // namespace pba::graphics
