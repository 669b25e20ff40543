#pragma once
// The scene alone, for the UI tests' lecture-layout check (tests/ui): with the UI status on (PBA_UI_STATUS),
// a screenshot also renders the same frame's scene once more with no UI, no background gradient and an
// invisible ground (graphics::RendererSettings::sceneOnly: a flat kSceneOnlyBackground; what lies below the
// ground stays hidden) and writes it as a binary PPM
// next to the PNG, so the check finds the scene's own pixels and whether a window lies over any of them.
#include <string>

#include <glm/vec2.hpp>

#include "app/runner/scene.h"
#include "graphics/camera.h"
#include "graphics/debug_renderer.h"
#include "graphics/renderer.h"
#include "physics/core/result.h"

namespace pba::app {

/// "shots/x.png" -> "shots/x-scene.ppm": where the scene alone of the screenshot `png` goes.
std::string sceneImagePath(const std::string& png);

/// Renders `scene` alone into the back buffer (the whole `framebuffer`, in pixels) and writes it to `path` as
/// a binary PPM (P6, rows top-down). Call before the frame's own rendering, which clears the buffer again.
Status writeSceneImage(graphics::Renderer& renderer, graphics::DebugRenderer& debug,
                       const graphics::OrbitCamera& camera, const Scene& scene, glm::ivec2 framebuffer,
                       const std::string& path);

}  // namespace pba::app
