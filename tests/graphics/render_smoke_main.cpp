// pba_render_smoke: opens a window (use xvfb-run without a display), renders a lit demo scene with
// every primitive the renderer offers (grid, shadows, instanced solids, lines, dots, arrows, frames,
// a skinned glTF mesh posed at t = 0.5 s, a BVH skeleton), writes a PNG and checks it is not blank.
// Usage: pba_render_smoke OUT.png [SHADER_DIR] [--lecture] [--hidden] [--frames N]
// Exit codes: 0 ok, 1 rendering or image check failed, 2 bad arguments.
#include "graphics/camera.h"
#include "graphics/debug_renderer.h"
#include "graphics/model.h"
#include "graphics/renderer.h"
#include "graphics/screenshot.h"
#include "graphics/skinned_mesh.h"
#include "graphics/skinning.h"
#include "graphics/window.h"

#include <GL/glew.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace gfx = pba::graphics;
namespace colors = pba::graphics::colors;

namespace {

const char* kSkinPath = PBA_TEST_RESOURCE_DIR "/models/simple_skin/simple_skin.gltf";
const char* kBvhPath = PBA_TEST_RESOURCE_DIR "/models/mocap/01_01.bvh";

void drawScene(gfx::DebugRenderer& debug) {
  // A row of primitives on the ground, casting shadows.
  debug.sphere({-2.2f, 0.5f, 0.0f}, 0.5f, colors::kBlue);
  debug.box({-0.8f, 0.4f, 0.3f}, {0.4f, 0.4f, 0.4f}, glm::angleAxis(0.5f, glm::vec3(0, 1, 0)), colors::kOrange);
  debug.capsule({0.4f, 0.35f, -0.6f}, {1.4f, 0.35f, 0.2f}, 0.35f, colors::kGreen);
  debug.cylinder({2.4f, 0.0f, -0.4f}, {2.4f, 1.1f, -0.4f}, 0.35f, colors::kPurple);
  debug.sphere({0.3f, 1.6f, 0.9f}, 0.25f, colors::kRed);  // floating: its shadow shows the light
  // A pendulum-like chain of particles with springs as lines and a force arrow.
  glm::vec3 prev(-3.2f, 2.8f, -1.6f);
  debug.point(prev, 12.0f, colors::kDark);
  for (int i = 1; i <= 6; ++i) {
    const glm::vec3 p =
        glm::vec3(-3.2f + 0.35f * static_cast<float>(i), 2.8f - 0.12f * static_cast<float>(i * i) * 0.5f,
                  -1.6f + 0.1f * static_cast<float>(i));
    debug.line(prev, p, colors::kDark);
    debug.point(p, 10.0f, colors::categorical(i));
    prev = p;
  }
  debug.arrow(prev, prev + glm::vec3(0.0f, -0.8f, 0.0f), colors::kRed);
  debug.frame({1.2f, 1.9f, 1.4f}, glm::angleAxis(0.6f, glm::normalize(glm::vec3(1, 1, 0))), 0.6f);
  debug.frame({0.0f, 0.0f, 0.0f}, glm::quat(1, 0, 0, 0), 0.8f);
  debug.label({-2.2f, 1.2f, 0.0f}, "sphere");
}

void drawBvhSkeleton(gfx::DebugRenderer& debug, const gfx::Model& bvh, float t) {
  if (bvh.animations.empty()) return;
  const auto global = gfx::globalTransforms(bvh, gfx::sampleAnimation(bvh, bvh.animations[0], t));
  // CMU BVH files are in inches-ish units (~ 0.056 m); place the figure behind the primitives.
  const glm::mat4 place =
      glm::translate(glm::mat4(1.0f), glm::vec3(-3.8f, 0.0f, -2.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.056f));
  for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
    const int parent = bvh.nodes[i].parent;
    if (parent < 0) continue;
    const glm::vec3 a = glm::vec3(place * global[static_cast<std::size_t>(parent)][3]);
    const glm::vec3 b = glm::vec3(place * global[i][3]);
    if (glm::distance(a, b) > 1e-4f) debug.capsule(a, b, 0.045f, colors::kTeal);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string out, shaderDir = PBA_SHADER_DIR;
  bool lecture = false, hidden = false;
  int frames = 3;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--lecture") == 0) {
      lecture = true;
    } else if (std::strcmp(argv[i], "--hidden") == 0) {
      hidden = true;
    } else if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
      frames = std::max(1, std::atoi(argv[++i]));
    } else if (out.empty()) {
      out = argv[i];
    } else {
      shaderDir = argv[i];
    }
  }
  if (out.empty()) {
    std::fprintf(stderr, "usage: pba_render_smoke OUT.png [SHADER_DIR] [--lecture] [--hidden] [--frames N]\n");
    return 2;
  }
  std::string error;
  gfx::WindowDesc desc;
  desc.title = "pba_render_smoke";
  desc.vsync = false;
  desc.visible = !hidden;
  auto window = gfx::Window::create(desc, &error);
  if (!window) {
    std::fprintf(stderr, "pba_render_smoke: %s\n", error.c_str());
    return 1;
  }
  std::printf("GL renderer: %s, %s, MSAA %d\n", window->glRenderer().c_str(), window->glVersion().c_str(),
              window->samples());
  auto renderer = gfx::Renderer::create(shaderDir, &error);
  if (!renderer) {
    std::fprintf(stderr, "pba_render_smoke: %s\n", error.c_str());
    return 1;
  }
  renderer->lectureMode(lecture);

  auto skin = gfx::loadModel(kSkinPath, &error);
  if (!skin) {
    std::fprintf(stderr, "pba_render_smoke: %s (resources/models)\n", error.c_str());
    return 1;
  }
  std::vector<std::unique_ptr<gfx::SkinnedMesh>> skinMeshes;
  for (const gfx::ModelMesh& mesh : skin->meshes) skinMeshes.push_back(std::make_unique<gfx::SkinnedMesh>(mesh));
  auto bvh = gfx::loadModel(kBvhPath, &error);
  if (!bvh) std::fprintf(stderr, "pba_render_smoke: warning: %s\n", error.c_str());

  gfx::OrbitCamera camera;
  gfx::DebugRenderer debug;
  const glm::ivec2 size = window->framebufferSize();
  for (int frame = 0; frame < frames; ++frame) {
    gfx::Window::pollEvents();
    debug.clear();
    drawScene(debug);
    if (bvh) drawBvhSkeleton(debug, *bvh, 0.5f);
    if (frame == 0) {
      glm::vec3 lo, hi;
      debug.bounds(&lo, &hi);
      camera.frame(lo, hi, static_cast<float>(size.x) / static_cast<float>(size.y));
      camera.distance *= 0.62f;  // frame() fits the bounding sphere; this scene is flat and wide
      camera.target.y = 0.7f;
    }
    renderer->beginFrame(camera, size.x, size.y);
    debug.flush(*renderer);
    const auto pose =
        gfx::sampleAnimation(*skin, skin->animations.empty() ? gfx::Animation{} : skin->animations[0], 0.5f);
    const auto skinning = gfx::skinningMatrices(*skin, gfx::globalTransforms(*skin, pose));
    const glm::mat4 place =
        glm::translate(glm::mat4(1.0f), glm::vec3(3.6f, 0.0f, -1.6f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.9f));
    for (const auto& mesh : skinMeshes) renderer->drawSkinned(*mesh, skinning, place, colors::kPink);
    renderer->endFrame();
    if (frame + 1 == frames) {
      if (!gfx::saveScreenshot(out, size.x, size.y, &error)) {
        std::fprintf(stderr, "pba_render_smoke: %s\n", error.c_str());
        return 1;
      }
    }
    window->swapBuffers();
  }
  const GLenum glError = glGetError();
  if (glError != GL_NO_ERROR) {
    std::fprintf(stderr, "pba_render_smoke: OpenGL error 0x%x\n", glError);
    return 1;
  }
  gfx::ImageStats stats;
  if (!gfx::imageStats(out, &stats, &error)) {
    std::fprintf(stderr, "pba_render_smoke: %s\n", error.c_str());
    return 1;
  }
  const auto& fs = renderer->stats();
  std::printf("wrote %s: %dx%d, %d colours, luminance sd %.1f; %d draw calls, %d instances, %d lines, %d points\n",
              out.c_str(), stats.width, stats.height, stats.distinctColors, stats.luminanceStdDev, fs.drawCalls,
              fs.instances, fs.lines, fs.points);
  if (stats.distinctColors < 200 || stats.luminanceStdDev < 5.0) {
    std::fprintf(stderr, "pba_render_smoke: %s looks blank\n", out.c_str());
    return 1;
  }
  return 0;
}
