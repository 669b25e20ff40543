// Window: GLFW initialisation (reference counted), OpenGL 3.3 core forward-compatible context, GLEW.
#include "graphics/window.h"

#include "graphics/gl.h"

#include <GLFW/glfw3.h>

#include <cstdlib>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

namespace pba::graphics {
namespace {

int g_glfwUsers = 0;
std::string g_lastGlfwError;

void onGlfwError(int code, const char* description) {
  g_lastGlfwError = std::string(description ? description : "unknown") + " (GLFW error " + std::to_string(code) + ")";
}

// Only an X11 or Wayland desktop announces itself in the environment: there, no DISPLAY means no
// window can open, and saying so is clearer than GLFW's error. Windows and macOS always have a desktop
// session when a program can run at all, and a browser page has its canvas, so GLFW alone decides there.
bool hasDisplay() {
#if defined(_WIN32) || defined(__APPLE__) || defined(__EMSCRIPTEN__)
  return true;
#else
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 && *x11) || (wayland && *wayland);
#endif
}

bool acquireGlfw(std::string* error) {
  if (g_glfwUsers == 0) {
    glfwSetErrorCallback(onGlfwError);
    if (!hasDisplay()) {
      if (error) *error = "no display (DISPLAY is not set): run under xvfb-run -a or use --headless";
      return false;
    }
    if (glfwInit() != GLFW_TRUE) {
      if (error) *error = "cannot initialise GLFW: " + g_lastGlfwError + "; run under xvfb-run -a or use --headless";
      return false;
    }
  }
  ++g_glfwUsers;
  return true;
}

void releaseGlfw() {
  if (g_glfwUsers > 0 && --g_glfwUsers == 0) glfwTerminate();
}

GLFWwindow* openWindow(const WindowDesc& desc, int samples) {
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, desc.visible ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_SAMPLES, samples);
#if GLFW_VERSION_MAJOR > 3 || GLFW_VERSION_MINOR >= 3  // Emscripten's GLFW is 3.2 (the page scales itself)
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
#endif
  return glfwCreateWindow(desc.width, desc.height, desc.title.c_str(), nullptr, nullptr);
}

}  // namespace

std::unique_ptr<Window> Window::create(const WindowDesc& desc, std::string* error) {
  if (!acquireGlfw(error)) return nullptr;
  std::unique_ptr<Window> window(new Window());
  window->window_ = openWindow(desc, desc.samples);
  if (!window->window_ && desc.samples > 0) window->window_ = openWindow(desc, 0);  // no MSAA visual
  if (!window->window_) {
    if (error) {
      *error = "cannot create an OpenGL 3.3 core window: " + g_lastGlfwError +
               "; update the GL driver (Mesa >= 10), try LIBGL_ALWAYS_SOFTWARE=1, or use --headless";
    }
    releaseGlfw();
    window.reset();  // window_ is null: the destructor must not release GLFW a second time
    return nullptr;
  }
  glfwMakeContextCurrent(window->window_);
  glfwSwapInterval(desc.vsync ? 1 : 0);
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  window->samples_ = samples;
  if (!loadGlFunctions(samples, error)) return nullptr;
  return window;
}

Window::~Window() {
  if (window_) {
    glfwDestroyWindow(window_);
    releaseGlfw();
  }
}

glm::ivec2 Window::framebufferSize() const {
  glm::ivec2 size(0);
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

glm::ivec2 Window::windowSize() const {
  glm::ivec2 size(0);
  glfwGetWindowSize(window_, &size.x, &size.y);
  return size;
}

glm::vec2 Window::contentScale() const {
  glm::vec2 scale(1.0f);
#if GLFW_VERSION_MAJOR > 3 || GLFW_VERSION_MINOR >= 3
  glfwGetWindowContentScale(window_, &scale.x, &scale.y);
#endif
  return scale;
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void Window::setShouldClose(bool close) { glfwSetWindowShouldClose(window_, close ? GLFW_TRUE : GLFW_FALSE); }
#ifdef __EMSCRIPTEN__
// In the browser a frame is shown when the program gives control back to the page: the lab's loop
// waits here for the next animation frame (ASYNCIFY unwinds and rewinds the stack around the wait; the
// function is listed in ASYNCIFY_IMPORTS, cmake/PbaLab.cmake).
// ES5 JavaScript inside EM_JS: clang-format would split an arrow function's `=>`.
EM_JS(void, waitForAnimationFrame, (),
      { Asyncify.handleSleep(function(wakeUp) { requestAnimationFrame(function() { wakeUp(); }); }); });
#endif

void Window::swapBuffers() {
  glfwSwapBuffers(window_);
#ifdef __EMSCRIPTEN__
  waitForAnimationFrame();
#endif
}
void Window::pollEvents() { glfwPollEvents(); }
void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }
void Window::makeCurrent() { glfwMakeContextCurrent(window_); }

std::string Window::glRenderer() const {
  const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return text ? text : "";
}

std::string Window::glVersion() const {
  const auto* text = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return text ? text : "";
}

}  // namespace pba::graphics
