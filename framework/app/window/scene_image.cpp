#include "app/window/scene_image.h"

#include <fstream>
#include <vector>

#include "app/window/scene_draw.h"
#include "graphics/screenshot.h"

namespace pba::app {

std::string sceneImagePath(const std::string& png) {
  const std::string stem =
      png.size() > 4 && png.compare(png.size() - 4, 4, ".png") == 0 ? png.substr(0, png.size() - 4) : png;
  return stem + "-scene.ppm";
}

Status writeSceneImage(graphics::Renderer& renderer, graphics::DebugRenderer& debug,
                       const graphics::OrbitCamera& camera, const Scene& scene, glm::ivec2 framebuffer,
                       const std::string& path) {
  renderer.settings().sceneOnly = true;
  renderer.beginFrame(camera, framebuffer.x, framebuffer.y);
  SceneDraw draw(debug);
  scene.draw(draw);
  debug.flush(renderer);
  debug.clear();
  renderer.endFrame();
  renderer.settings().sceneOnly = false;
  std::vector<unsigned char> rgb;
  std::string why;
  if (!graphics::readFramebuffer(framebuffer.x, framebuffer.y, rgb, &why)) return Error{path + ": " + why};
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << "P6\n" << framebuffer.x << ' ' << framebuffer.y << "\n255\n";
  out.write(reinterpret_cast<const char*>(rgb.data()), static_cast<std::streamsize>(rgb.size()));
  if (!out) return Error{path + ": cannot write the scene image"};
  return Status::success();
}

}  // namespace pba::app
