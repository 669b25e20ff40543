// The OpenGL API the renderer is written against: OpenGL 3.3 core through GLEW on the desktop, OpenGL
// ES 3.0 (WebGL2) in the browser. The renderer uses only what both have (no geometry shaders, no
// glDrawBuffer, no GL_MULTISAMPLE switch), so no other file needs to know which it is.
#pragma once

#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>
#else
#include <GL/glew.h>
#endif

#include <string>

namespace pba::graphics {

/// The #version line for Dear ImGui's OpenGL3 backend (its shaders come in one variant per version).
#ifdef __EMSCRIPTEN__
inline constexpr const char* kImGuiGlslVersion = "#version 300 es";
#else
inline constexpr const char* kImGuiGlslVersion = "#version 330 core";
#endif

/// Loads the GL entry points for the current context (GLEW on the desktop; nothing to load in the
/// browser) and turns multisampling on where the context has samples. false + *error on failure.
bool loadGlFunctions(int samples, std::string* error);

}  // namespace pba::graphics
