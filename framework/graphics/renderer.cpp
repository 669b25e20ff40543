// Renderer: batching, bounds, shadow pass and colour pass (see renderer.h).
#include "graphics/renderer.h"

#include "graphics/line_renderer.h"
#include "graphics/model.h"
#include "graphics/shader.h"
#include "graphics/shadow_map.h"
#include "graphics/skinned_mesh.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pba::graphics {
namespace {

constexpr int kShadowTextureUnit = 3;
constexpr int kSoftwareShadowTaps = 4;  // RendererSettings::shadowTaps on a software rasteriser

constexpr GLuint kBoneBlockBinding = 0;
constexpr float kMinLength = 1e-6f;  // m; keeps degenerate segments invertible

// OpenGL runs on the CPU: Mesa's llvmpipe or softpipe, or SwiftShader.
bool softwareRasteriser() {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!name) return false;
  const std::string text(name);
  return text.find("llvmpipe") != std::string::npos || text.find("softpipe") != std::string::npos ||
         text.find("SwiftShader") != std::string::npos;
}

glm::vec3 srgbToLinear(const glm::vec3& c) { return glm::pow(c, glm::vec3(2.2f)); }

/// Lecture mode's stronger line and dot colours: mid-tones darken (a pale yellow or grey line holds on
/// a washed-out projector), black and white stay, hues and alpha are kept.
glm::vec4 lectureContrast(const glm::vec4& c) { return glm::vec4(glm::pow(glm::vec3(c), glm::vec3(1.6f)), c.a); }

/// Colours of the ground and its grid (sRGB): normal, and lecture mode's darker lines on a lighter ground.
struct GridColors {
  glm::vec3 ground, minor, major, axisX, axisZ;
};
constexpr GridColors kGridColors{
    {0.90f, 0.905f, 0.91f}, {0.78f, 0.79f, 0.81f}, {0.60f, 0.62f, 0.66f}, {0.85f, 0.45f, 0.42f}, {0.42f, 0.56f, 0.86f}};
// The grid and its axes stay quieter than the physics: light greys, and axes only tinted (the saturated
// red and blue axes were the strongest lines on a projected screen, and red is for danger).
constexpr GridColors kLectureGridColors{
    {0.95f, 0.955f, 0.96f}, {0.80f, 0.81f, 0.83f}, {0.66f, 0.68f, 0.71f}, {0.85f, 0.66f, 0.64f}, {0.64f, 0.71f, 0.85f}};
// Lecture mode's background: nearly white, barely graded, so the scene's colours carry the picture.
constexpr glm::vec3 kLectureBackgroundTop{0.90f, 0.93f, 0.96f};
constexpr glm::vec3 kLectureBackgroundBottom{1.0f, 1.0f, 1.0f};

/// Model matrix mapping the unit +y segment [0,1] (radius 1) onto a -> b with the given radius.
glm::mat4 segmentTransform(const glm::vec3& a, const glm::vec3& b, float radius) {
  const glm::vec3 axis = b - a;
  const float length = glm::length(axis);
  const glm::quat q = length > kMinLength ? glm::rotation(glm::vec3(0, 1, 0), axis / length) : glm::quat(1, 0, 0, 0);
  const float r = std::max(std::abs(radius), kMinLength);
  return glm::translate(glm::mat4(1.0f), a) * glm::mat4_cast(q) *
         glm::scale(glm::mat4(1.0f), glm::vec3(r, std::max(length, kMinLength), r));
}

void bindBoneBlock(const ShaderProgram& program) {
  const GLuint index = glGetUniformBlockIndex(program.id(), "Bones");
  if (index != GL_INVALID_INDEX) glUniformBlockBinding(program.id(), index, kBoneBlockBinding);
}

}  // namespace

std::unique_ptr<Renderer> Renderer::create(const std::string& shaderDir, std::string* error) {
  std::unique_ptr<Renderer> r(new Renderer());
  const std::string dir = shaderDir + "/";
  struct Program {
    std::unique_ptr<ShaderProgram>* target;
    std::string vert, frag;
  };
  const Program programs[] = {{&r->litShader_, "lit.vert", "lit.frag"},
                              {&r->skinnedShader_, "skinned.vert", "lit.frag"},
                              {&r->shadowShader_, "shadow.vert", "shadow.frag"},
                              {&r->shadowSkinnedShader_, "shadow_skinned.vert", "shadow.frag"},
                              {&r->gridShader_, "grid.vert", "grid.frag"},
                              {&r->backgroundShader_, "background.vert", "background.frag"}};
  for (const Program& p : programs) {
    *p.target = ShaderProgram::loadFiles(dir + p.vert, dir + p.frag, error);
    if (!*p.target) return nullptr;
  }
  r->lines_ = LineRenderer::create(shaderDir, error);
  if (!r->lines_) return nullptr;
  bindBoneBlock(*r->skinnedShader_);
  bindBoneBlock(*r->shadowSkinnedShader_);
  r->sphere_ = std::make_unique<Mesh>(makeSphere(40, 20));
  r->box_ = std::make_unique<Mesh>(makeBox());
  r->cylinder_ = std::make_unique<Mesh>(makeCylinder(40, true));
  r->tube_ = std::make_unique<Mesh>(makeCylinder(40, false));
  r->cone_ = std::make_unique<Mesh>(makeCone(32));
  r->plane_ = std::make_unique<Mesh>(makePlane());
  r->shadowMap_ = std::make_unique<ShadowMap>(r->settings_.shadowMapSize);
  if (softwareRasteriser()) r->settings_.shadowTaps = kSoftwareShadowTaps;
  glGenVertexArrays(1, &r->emptyVao_);
  glGenBuffers(1, &r->boneUbo_);
  glBindBuffer(GL_UNIFORM_BUFFER, r->boneUbo_);
  glBufferData(GL_UNIFORM_BUFFER, kMaxSkinningBones * static_cast<GLsizeiptr>(sizeof(glm::mat4)), nullptr,
               GL_DYNAMIC_DRAW);
  glBindBuffer(GL_UNIFORM_BUFFER, 0);
  const GLenum glError = glGetError();
  if (glError != GL_NO_ERROR) {
    if (error) *error = "OpenGL error " + std::to_string(glError) + " while creating the renderer";
    return nullptr;
  }
  return r;
}

Renderer::~Renderer() {
  glDeleteBuffers(1, &boneUbo_);
  glDeleteVertexArrays(1, &emptyVao_);
}

float Renderer::lineWidth() const { return settings_.lineWidthPx * (settings_.lectureMode ? 2.0f : 1.0f); }

void Renderer::beginFrame(const OrbitCamera& camera, int viewportW, int viewportH, int originX, int originY) {
  camera_ = camera;
  viewport_ = glm::ivec2(std::max(viewportW, 1), std::max(viewportH, 1));
  origin_ = glm::ivec2(originX, originY);
  viewProj_ = camera.projection(static_cast<float>(viewport_.x) / static_cast<float>(viewport_.y)) * camera.view();
  for (MeshBatch& batch : batches_) batch.instances.clear();
  skinned_.clear();
  streamedUsed_ = 0;
  lines_->clear();
  building_ = FrameStats{};
  boundsMin_ = glm::vec3(std::numeric_limits<float>::max());
  boundsMax_ = glm::vec3(-std::numeric_limits<float>::max());
  inFrame_ = true;
}

void Renderer::grow(const glm::vec3& p) {
  if (!std::isfinite(p.x + p.y + p.z)) return;
  boundsMin_ = glm::min(boundsMin_, p);
  boundsMax_ = glm::max(boundsMax_, p);
}

void Renderer::addInstance(const Mesh& mesh, const glm::mat4& model, const glm::vec4& color) {
  auto batch = std::find_if(batches_.begin(), batches_.end(), [&](const MeshBatch& b) { return b.mesh == &mesh; });
  if (batch == batches_.end()) batch = batches_.insert(batches_.end(), MeshBatch{&mesh, {}});
  batch->instances.push_back(Instance{model, color});
  ++building_.instances;
  // World AABB of the transformed object box: centre +- |M| * half extents.
  const glm::vec3 c = glm::vec3(model * glm::vec4(0.5f * (mesh.boundsMin() + mesh.boundsMax()), 1.0f));
  const glm::vec3 h = 0.5f * (mesh.boundsMax() - mesh.boundsMin());
  const glm::mat3 m(model);
  const glm::vec3 e = glm::abs(m[0]) * h.x + glm::abs(m[1]) * h.y + glm::abs(m[2]) * h.z;
  grow(c - e);
  grow(c + e);
}

void Renderer::drawSphere(const glm::vec3& center, float radius, const glm::vec4& color) {
  const float r = std::max(std::abs(radius), kMinLength);
  addInstance(*sphere_, glm::scale(glm::translate(glm::mat4(1.0f), center), glm::vec3(r)), color);
}

void Renderer::drawBox(const glm::vec3& center, const glm::vec3& halfExtents, const glm::quat& rotation,
                       const glm::vec4& color) {
  const glm::vec3 h = glm::max(glm::abs(halfExtents), glm::vec3(kMinLength));
  addInstance(*box_,
              glm::translate(glm::mat4(1.0f), center) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), h),
              color);
}

void Renderer::drawCylinder(const glm::vec3& a, const glm::vec3& b, float radius, const glm::vec4& color) {
  addInstance(*cylinder_, segmentTransform(a, b, radius), color);
}

void Renderer::drawCapsule(const glm::vec3& a, const glm::vec3& b, float radius, const glm::vec4& color) {
  // An open tube between two spheres is exactly a capsule's surface (the spheres' inner halves hide).
  addInstance(*tube_, segmentTransform(a, b, radius), color);
  drawSphere(a, radius, color);
  drawSphere(b, radius, color);
}

void Renderer::drawCone(const glm::vec3& base, const glm::vec3& apex, float radius, const glm::vec4& color) {
  addInstance(*cone_, segmentTransform(base, apex, radius), color);
}

void Renderer::drawLine(const glm::vec3& a, const glm::vec3& b, const glm::vec4& color) {
  drawLine(a, b, color, color);
}

void Renderer::drawLine(const glm::vec3& a, const glm::vec3& b, const glm::vec4& colorA, const glm::vec4& colorB) {
  if (settings_.lectureMode)
    lines_->addLine(a, b, lectureContrast(colorA), lectureContrast(colorB));
  else
    lines_->addLine(a, b, colorA, colorB);
  grow(a);
  grow(b);
}

void Renderer::drawPoint(const glm::vec3& p, float sizePx, const glm::vec4& color) {
  lines_->addPoint(p, sizePx, settings_.lectureMode ? lectureContrast(color) : color);
  grow(p);
}

void Renderer::drawMesh(const Mesh& mesh, const glm::mat4& model, const glm::vec4& color) {
  addInstance(mesh, model, color);
}

void Renderer::drawTriangles(const MeshData& mesh, const glm::vec4& color) {
  if (mesh.indices.empty()) return;
  if (streamedUsed_ == streamed_.size())
    streamed_.push_back(std::make_unique<Mesh>(mesh));
  else
    streamed_[streamedUsed_]->update(mesh);
  addInstance(*streamed_[streamedUsed_++], glm::mat4(1.0f), color);
}

void Renderer::drawSkinned(const SkinnedMesh& mesh, const std::vector<glm::mat4>& skinning, const glm::mat4& model,
                           const glm::vec4& color) {
  skinned_.push_back(SkinnedDraw{&mesh, skinning, model, color});
  if (skinned_.back().skinning.size() > static_cast<std::size_t>(kMaxSkinningBones)) {
    skinned_.back().skinning.resize(static_cast<std::size_t>(kMaxSkinningBones));
  }
  if (skinned_.back().skinning.empty()) skinned_.back().skinning.push_back(glm::mat4(1.0f));
  // Bounds: bind-pose box moved by each bone's skinning matrix (conservative enough for framing).
  for (const glm::mat4& s : skinned_.back().skinning) {
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 c((i & 1) ? mesh.boundsMax().x : mesh.boundsMin().x,
                        (i & 2) ? mesh.boundsMax().y : mesh.boundsMin().y,
                        (i & 4) ? mesh.boundsMax().z : mesh.boundsMin().z);
      grow(glm::vec3(model * s * glm::vec4(c, 1.0f)));
    }
  }
}

void Renderer::uploadBones(const std::vector<glm::mat4>& skinning) const {
  glBindBuffer(GL_UNIFORM_BUFFER, boneUbo_);
  glBufferSubData(GL_UNIFORM_BUFFER, 0, static_cast<GLsizeiptr>(skinning.size() * sizeof(glm::mat4)), skinning.data());
  glBindBufferBase(GL_UNIFORM_BUFFER, kBoneBlockBinding, boneUbo_);
}

void Renderer::shadowPass() {
  glm::vec3 lo = boundsMin_, hi = boundsMax_;
  if (lo.x > hi.x) lo = hi = glm::vec3(0.0f);
  shadowMap_->fit(lo, hi, glm::normalize(settings_.lightDirection));
  shadowMap_->beginPass();
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  shadowShader_->use();
  shadowShader_->set("uLightViewProj", shadowMap_->lightViewProj());
  for (const MeshBatch& batch : batches_) {
    if (batch.instances.empty()) continue;
    batch.mesh->drawInstanced(batch.instances);
    ++building_.drawCalls;
  }
  shadowSkinnedShader_->use();
  shadowSkinnedShader_->set("uLightViewProj", shadowMap_->lightViewProj());
  for (const SkinnedDraw& draw : skinned_) {
    uploadBones(draw.skinning);
    shadowSkinnedShader_->set("uModel", draw.model);
    draw.mesh->draw();
    ++building_.drawCalls;
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  shadowMap_->endPass();
}

void Renderer::setLightingUniforms(const ShaderProgram& program) const {
  program.use();
  program.set("uViewProj", viewProj_);
  program.set("uLightDir", glm::normalize(settings_.lightDirection));
  program.set("uLightColor", glm::vec3(0.95f, 0.93f, 0.88f));
  program.set("uSkyAmbient", srgbToLinear(glm::vec3(0.62f, 0.66f, 0.72f)));
  program.set("uGroundAmbient", srgbToLinear(glm::vec3(0.45f, 0.43f, 0.41f)));
  program.set("uCameraPos", camera_.eye());
  program.set("uLightViewProj", shadowMap_->lightViewProj());
  program.set("uShadowMap", kShadowTextureUnit);
  program.set("uShadowTexel", 1.0f / static_cast<float>(shadowMap_->size()));
  program.set("uShadowNormalOffset", 1.5f * shadowMap_->worldTexel());
  program.set("uShadowsOn", settings_.shadows ? 1 : 0);
  program.set("uShadowTaps", settings_.shadowTaps);
}

void Renderer::drawGrid() {
  setLightingUniforms(*gridShader_);
  const float extent = std::max(60.0f, 25.0f * camera_.distance);
  const float fadeEnd = std::clamp(7.0f * camera_.distance, 25.0f, extent);
  gridShader_->set("uCenter", glm::floor(glm::vec2(camera_.target.x, camera_.target.z)));
  gridShader_->set("uExtent", extent);
  gridShader_->set("uFadeStart", 0.3f * fadeEnd);
  gridShader_->set("uFadeEnd", fadeEnd);
  const GridColors& c = settings_.lectureMode ? kLectureGridColors : kGridColors;
  gridShader_->set("uGroundColor", c.ground);
  gridShader_->set("uMinorColor", c.minor);
  gridShader_->set("uMajorColor", c.major);
  gridShader_->set("uAxisXColor", c.axisX);
  gridShader_->set("uAxisZColor", c.axisZ);
  plane_->drawInstanced({Instance{}});
  ++building_.drawCalls;
}

void Renderer::colorPass() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(origin_.x, origin_.y, viewport_.x, viewport_.y);
  glEnable(GL_SCISSOR_TEST);  // the clear below stays inside this view
  glScissor(origin_.x, origin_.y, viewport_.x, viewport_.y);
  glDepthMask(GL_TRUE);
  const glm::vec3 top = settings_.lectureMode ? kLectureBackgroundTop : settings_.backgroundTop;
  const glm::vec3 bottom = settings_.lectureMode ? kLectureBackgroundBottom : settings_.backgroundBottom;
  const glm::vec3 clear = settings_.sceneOnly ? kSceneOnlyBackground : bottom;
  glClearColor(clear.r, clear.g, clear.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  if (!settings_.sceneOnly) {  // background gradient (no depth)
    backgroundShader_->use();
    backgroundShader_->set("uTop", top);
    backgroundShader_->set("uBottom", bottom);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    ++building_.drawCalls;
  }

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  shadowMap_->bindTexture(kShadowTextureUnit);
  if (settings_.grid && settings_.sceneOnly) {  // the ground draws nothing but still hides what lies below it
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    drawGrid();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  setLightingUniforms(*litShader_);
  for (const MeshBatch& batch : batches_) {
    if (batch.instances.empty()) continue;
    batch.mesh->drawInstanced(batch.instances);
    ++building_.drawCalls;
  }
  if (!skinned_.empty()) {
    setLightingUniforms(*skinnedShader_);
    for (const SkinnedDraw& draw : skinned_) {
      uploadBones(draw.skinning);
      skinnedShader_->set("uModel", draw.model);
      skinnedShader_->set("uColor", draw.color);
      draw.mesh->draw();
      ++building_.drawCalls;
    }
  }
  if (settings_.grid && !settings_.sceneOnly) drawGrid();
  // Lines and dots: depth tested but not written, so overlapping translucent strokes blend.
  glDepthMask(GL_FALSE);
  const float pointScale = settings_.lectureMode ? 1.6f : 1.0f;
  lines_->draw(viewProj_, glm::vec2(viewport_), lineWidth(), pointScale);
  building_.drawCalls += (lines_->lineCount() > 0 ? 1 : 0) + (lines_->pointCount() > 0 ? 1 : 0);
  glDepthMask(GL_TRUE);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_SCISSOR_TEST);
}

void Renderer::endFrame() {
  if (!inFrame_) return;
  building_.lines = static_cast<int>(lines_->lineCount());
  building_.points = static_cast<int>(lines_->pointCount());
  if (settings_.shadows) shadowPass();
  colorPass();
  stats_ = building_;
  inFrame_ = false;
}

}  // namespace pba::graphics
