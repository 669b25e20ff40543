// loadGlFunctions: GLEW on the desktop; WebGL2 needs no loader and multisamples whenever it has samples.
#include "graphics/gl.h"

namespace pba::graphics {

bool loadGlFunctions(int samples, std::string* error) {
#ifdef __EMSCRIPTEN__
  static_cast<void>(samples);
  static_cast<void>(error);
  return true;
#else
  glewExperimental = GL_TRUE;
  const GLenum glewStatus = glewInit();
  // GLEW 2.x may return GLEW_ERROR_NO_GLX_DISPLAY on EGL/Wayland contexts although GL works.
  if (glewStatus != GLEW_OK && glGenVertexArrays == nullptr) {
    if (error)
      *error = std::string("cannot load OpenGL functions (GLEW): ") +
               reinterpret_cast<const char*>(glewGetErrorString(glewStatus));
    return false;
  }
  while (glGetError() != GL_NO_ERROR) {}  // glewInit leaves a GL_INVALID_ENUM behind in core profiles
  if (samples > 0) glEnable(GL_MULTISAMPLE);
  return true;
#endif
}

}  // namespace pba::graphics
