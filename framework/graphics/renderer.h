// Renderer: the scene renderer of every lab. Submit primitives between beginFrame and endFrame; equal
// primitives are instanced (one draw call per primitive type per pass). endFrame renders a shadow
// depth pass from an orthographic light fitted to the scene, then the colour pass: gradient
// background, Blinn-Phong lit instances with PCF shadows, skinned meshes, the procedural ground grid
// (y = 0, receives shadows), thick anti-aliased lines and screen-sized dots.
// Colours are sRGB vec4 (alpha < 1 blends but is not depth sorted). Units: m; sizes on screen: pixels.
#pragma once

#include "graphics/camera.h"
#include "graphics/mesh.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <memory>
#include <string>
#include <vector>

namespace pba::graphics {

class LineRenderer;
class ShaderProgram;
class ShadowMap;
class SkinnedMesh;

/// The flat background of a RendererSettings::sceneOnly frame (sRGB magenta: exact through sRGB encoding and
/// not a colour the labs draw), so every other pixel of such a frame is the scene's.
inline constexpr glm::vec3 kSceneOnlyBackground{1.0f, 0.0f, 1.0f};

struct RendererSettings {
  bool shadows = true;
  bool grid = true;          ///< ground plane with the 1 m / 5 m grid at y = 0
  int shadowMapSize = 2048;  ///< texels per side
  /// Poisson taps of the soft shadow (1 to 12). Renderer::create lowers it to 4 when OpenGL is a software
  /// rasteriser (Mesa llvmpipe under Xvfb, a VM without a GPU): a third of the shading cost per pixel of
  /// ground, for a slightly grainier penumbra, and the window stays interactive.
  int shadowTaps = 12;
  float lineWidthPx = 2.0f;
  bool lectureMode = false;  ///< thicker lines, bigger dots (projectors)
  /// The scene's own pixels alone: a flat kSceneOnlyBackground instead of the gradient, the ground grid in the
  /// depth buffer only (it still hides what lies below it) (the UI tests' lecture-layout check finds the
  /// scene's pixels in this picture).
  bool sceneOnly = false;
  glm::vec3 lightDirection = glm::normalize(glm::vec3(-0.45f, 0.85f, 0.35f));  ///< towards the light
  glm::vec3 backgroundTop{0.74f, 0.81f, 0.89f};                                ///< sRGB
  glm::vec3 backgroundBottom{0.95f, 0.96f, 0.97f};                             ///< sRGB
};

struct FrameStats {
  int drawCalls = 0;
  int instances = 0;
  int lines = 0;
  int points = 0;
};

class Renderer {
 public:
  /// Loads the shaders from shaderDir (e.g. the resources/shaders folder); needs a current GL 3.3 context.
  static std::unique_ptr<Renderer> create(const std::string& shaderDir, std::string* error);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Starts a frame in the viewport of viewportW × viewportH pixels whose lower-left corner is at
  /// (originX, originY) of the framebuffer (GL's convention); only that rectangle is cleared, so two
  /// views side by side (A/B runs) are two frames into one framebuffer.
  void beginFrame(const OrbitCamera& camera, int viewportW, int viewportH, int originX = 0, int originY = 0);
  void drawSphere(const glm::vec3& center, float radius, const glm::vec4& color);
  void drawBox(const glm::vec3& center, const glm::vec3& halfExtents, const glm::quat& rotation,
               const glm::vec4& color);
  void drawCylinder(const glm::vec3& a, const glm::vec3& b, float radius, const glm::vec4& color);
  void drawCapsule(const glm::vec3& a, const glm::vec3& b, float radius, const glm::vec4& color);
  void drawCone(const glm::vec3& base, const glm::vec3& apex, float radius, const glm::vec4& color);
  void drawLine(const glm::vec3& a, const glm::vec3& b, const glm::vec4& color);
  void drawLine(const glm::vec3& a, const glm::vec3& b, const glm::vec4& colorA, const glm::vec4& colorB);
  void drawPoint(const glm::vec3& p, float sizePx, const glm::vec4& color);
  /// An uploaded mesh (e.g. from mesh_data generators) placed by `model`; instanced per Mesh.
  void drawMesh(const Mesh& mesh, const glm::mat4& model, const glm::vec4& color);
  /// A world-space triangle mesh that changes every frame (uploaded to a pooled stream buffer).
  void drawTriangles(const MeshData& mesh, const glm::vec4& color);
  /// A skinned mesh posed by `skinning` (skinningMatrices(), at most kMaxSkinningBones) and placed by `model`.
  void drawSkinned(const SkinnedMesh& mesh, const std::vector<glm::mat4>& skinning, const glm::mat4& model,
                   const glm::vec4& color);
  /// Renders the frame into the default framebuffer (viewport given to beginFrame).
  void endFrame();

  RendererSettings& settings() { return settings_; }
  void setLineWidth(float px) { settings_.lineWidthPx = px; }
  float lineWidth() const;  ///< effective width (lecture mode included)
  void lectureMode(bool on) { settings_.lectureMode = on; }
  bool lectureMode() const { return settings_.lectureMode; }
  const FrameStats& stats() const { return stats_; }  ///< of the last endFrame
  /// Bounds of everything submitted this frame (lines, points, primitives); empty -> min > max.
  glm::vec3 boundsMin() const { return boundsMin_; }
  glm::vec3 boundsMax() const { return boundsMax_; }

 private:
  struct SkinnedDraw {
    const SkinnedMesh* mesh;
    std::vector<glm::mat4> skinning;
    glm::mat4 model;
    glm::vec4 color;
  };
  struct MeshBatch {
    const Mesh* mesh;
    std::vector<Instance> instances;
  };
  Renderer() = default;
  void addInstance(const Mesh& mesh, const glm::mat4& model, const glm::vec4& color);
  void grow(const glm::vec3& p);
  void setLightingUniforms(const ShaderProgram& program) const;
  void shadowPass();
  void colorPass();
  void drawGrid();
  void uploadBones(const std::vector<glm::mat4>& skinning) const;

  RendererSettings settings_;
  FrameStats stats_, building_;
  std::unique_ptr<ShaderProgram> litShader_, skinnedShader_, shadowShader_, shadowSkinnedShader_, gridShader_,
      backgroundShader_;
  std::unique_ptr<Mesh> sphere_, box_, cylinder_, tube_, cone_, plane_;
  std::unique_ptr<ShadowMap> shadowMap_;
  std::unique_ptr<LineRenderer> lines_;
  GLuint emptyVao_ = 0, boneUbo_ = 0;
  std::vector<MeshBatch> batches_;
  std::vector<SkinnedDraw> skinned_;
  std::vector<std::unique_ptr<Mesh>> streamed_;  ///< pool for drawTriangles, reused frame to frame
  std::size_t streamedUsed_ = 0;
  OrbitCamera camera_;
  glm::ivec2 viewport_{1, 1};
  glm::ivec2 origin_{0, 0};
  glm::mat4 viewProj_{1.0f};
  glm::vec3 boundsMin_{0.0f}, boundsMax_{0.0f};
  bool inFrame_ = false;
};

}  // namespace pba::graphics
